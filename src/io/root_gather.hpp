#pragma once
// The values every rank owns of one array, collected on rank 0 into the whole array, for a file
// that rank 0 alone writes (the snapshot: no HDF5 call of the write involves another rank). Each
// rank says once where its values go (the point of the array each belongs to); every `gather`
// then sends its values in that order to rank 0 (MPI_Gatherv), which places them and puts a fill
// value at the points no rank owns. Rank 0 holds one whole array at a time, and the values
// received for it.

#include <cstdint>
#include <span>
#include <vector>

#include "src/parallel/communicator.hpp"

namespace bagnold::io {

class RootGather {
 public:
  // Collective. `points`: the point (of an array of `size` points) each of this rank's values
  // belongs to; no point belongs to two ranks.
  RootGather(const parallel::Communicator& comm, const std::vector<std::uint64_t>& points,
             std::uint64_t size);

  // Collective. `values`: `width` consecutive values for each point given to the constructor, in
  // its order. Rank 0 gets the whole array (size × width values, a point's values consecutive),
  // `fill` at the points no rank owns; the other ranks an empty vector. Throws Hdf5Error on every
  // rank when the ranks' values are too many for one MPI message (2^31).
  std::vector<double> gather(std::span<const double> values, int width, double fill) const;

 private:
  const parallel::Communicator& m_comm;
  std::uint64_t m_size;
  std::int64_t m_total;                 // points of all ranks
  int m_local;                          // this rank's points
  std::vector<std::uint64_t> m_points;  // rank 0: every rank's, in rank order
  std::vector<int> m_counts;            // rank 0: each rank's number of points
};

}  // namespace bagnold::io
