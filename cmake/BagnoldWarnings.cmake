# Warnings and sanitizers applied to Bagnold's own targets (not to third-party headers).
function(bagnold_target_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  # GCC 12 at -O3 reports -Wrestrict inside libstdc++'s own std::string copy (char_traits.h), a
  # false positive of that compiler; the check stays on for other compilers and versions.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(BAGNOLD_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(BAGNOLD_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=${BAGNOLD_SANITIZE} -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=${BAGNOLD_SANITIZE})
  endif()
endfunction()
