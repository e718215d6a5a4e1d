#pragma once
// The integrity of a snapshot: a checksum of every field dataset, written with it, and the check
// a restart makes before it reads one.
//
// The checksum of a dataset of doubles is Σ_e h(e, bits(v_e)) mod 2⁶⁴ over all its elements e
// (row-major index), h a 64-bit mix of the index and the value's bits (SplitMix64's finalizer,
// Steele, Lea & Flood, OOPSLA 2014). A sum does not depend on which rank wrote which element, so
// each rank adds its own points and one Allreduce gives the whole; elements nobody writes hold the
// fill value (NaN) and enter as h(e, bits(NaN)). It is stored as the dataset's uint64 attribute
// `checksum`. Any changed byte of a stored value changes it (with probability 1 − 2⁻⁶⁴).
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace bagnold::io {

std::uint64_t element_hash(std::uint64_t index, double value);
// Σ_{e < count} h(e, value): a dataset of `count` elements that all hold `value`.
std::uint64_t uniform_checksum(std::uint64_t count, double value);

// What a restart accepts in a field's fluid cells.
struct FieldRange {
  std::string name;
  double low = -INFINITY, high = INFINITY;
  bool nan_allowed = false;  // NaN means "not evaluated" (Θ without a granular temperature)
};

// Serial (one rank): opens the snapshot, checks every field dataset and its boundary dataset
// against its checksum (where the snapshot has one: written before they existed, it has none),
// and the fluid cells of each field in `ranges` (from /grid/cell_flags) against its range.
// Nothing when all hold; otherwise the first problem, naming the dataset.
std::optional<std::string> verify_snapshot(const std::string& path,
                                           const std::vector<FieldRange>& ranges);

}  // namespace bagnold::io
