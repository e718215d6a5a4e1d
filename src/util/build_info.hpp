#pragma once
// What this build is: the version (CMake's project version) and the git hash of the tree it was
// built from (`git describe --always --dirty` at build time, "unknown" outside a git checkout;
// cmake/BagnoldBuildInfo.cmake).

#include <string>

namespace bagnold {

std::string version();   // "0.1.0"
std::string git_hash();  // "c8034df", "v0.1-12-gc8034df-dirty", or "unknown"

}  // namespace bagnold
