#include "src/util/build_info.hpp"

#include "generated/build_info.hpp"  // the build tree's, rewritten at every build

namespace bagnold {

std::string version() { return BAGNOLD_VERSION; }
std::string git_hash() { return BAGNOLD_GIT_HASH; }

}  // namespace bagnold
