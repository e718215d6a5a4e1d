#pragma once
// The integrity of a snapshot: a checksum of every field dataset, written with it, and the check
// a restart makes before it reads one.
//
// The checksum of a dataset of doubles is Σ_e h(e, bits(v_e)) mod 2⁶⁴ over all its elements e
// (row-major index), h a 64-bit mix of the index and the value's bits (SplitMix64's finalizer,
// Steele, Lea & Flood, OOPSLA 2014). The writer sums it over the whole array it writes (gathered
// on rank 0), the elements no rank owns holding the fill value (NaN) and entering as
// h(e, bits(NaN)). It is stored as the dataset's uint64 attribute `checksum`. Any changed byte of
// a stored value changes it (with probability 1 − 2⁻⁶⁴).
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace bagnold::io {

std::uint64_t element_hash(std::uint64_t index, double value);
// Σ_e h(e, values[e]): the checksum of a dataset holding `values`.
std::uint64_t checksum(std::span<const double> values);

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
