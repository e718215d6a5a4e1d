#include "src/io/root_gather.hpp"

#include <climits>
#include <string>

#include "src/io/io_error.hpp"

namespace bagnold::io {

namespace {

// Where each rank's block starts in the gathered buffer, for `width` values per point.
std::vector<int> scaled(const std::vector<int>& counts, int width) {
  std::vector<int> out(counts.size());
  for (std::size_t r = 0; r < counts.size(); ++r) out[r] = counts[r] * width;
  return out;
}

std::vector<int> offsets(const std::vector<int>& counts) {
  std::vector<int> out(counts.size(), 0);
  for (std::size_t r = 1; r < counts.size(); ++r) out[r] = out[r - 1] + counts[r - 1];
  return out;
}

void check_message_size(std::int64_t values) {
  if (values > INT_MAX)
    throw Hdf5Error("cannot gather " + std::to_string(values) +
                    " values on rank 0 in one MPI message (at most 2^31)");
}

}  // namespace

RootGather::RootGather(const parallel::Communicator& comm, const std::vector<std::uint64_t>& points,
                       std::uint64_t size)
    : m_comm(comm), m_size(size) {
  m_total = comm.sum(static_cast<std::int64_t>(points.size()));
  check_message_size(m_total);
  m_local = static_cast<int>(points.size());
  if (comm.is_root()) m_counts.resize(static_cast<std::size_t>(comm.size()));
  MPI_Gather(&m_local, 1, MPI_INT, m_counts.data(), 1, MPI_INT, 0, comm.get());
  if (comm.is_root()) m_points.resize(static_cast<std::size_t>(m_total));
  const auto displacements = offsets(m_counts);
  MPI_Gatherv(points.data(), m_local, MPI_UINT64_T, m_points.data(), m_counts.data(),
              displacements.data(), MPI_UINT64_T, 0, comm.get());
}

std::vector<double> RootGather::gather(std::span<const double> values, int width, double fill) const {
  check_message_size(m_total * width);
  const auto counts = scaled(m_counts, width);
  const auto displacements = offsets(counts);
  std::vector<double> received(m_comm.is_root() ? static_cast<std::size_t>(m_total * width) : 0);
  MPI_Gatherv(values.data(), m_local * width, MPI_DOUBLE, received.data(), counts.data(),
              displacements.data(), MPI_DOUBLE, 0, m_comm.get());
  if (!m_comm.is_root()) return {};
  const auto w = static_cast<std::size_t>(width);
  std::vector<double> whole(static_cast<std::size_t>(m_size) * w, fill);
  for (std::size_t p = 0; p < m_points.size(); ++p)
    for (std::size_t c = 0; c < w; ++c) whole[static_cast<std::size_t>(m_points[p]) * w + c] = received[p * w + c];
  return whole;
}

}  // namespace bagnold::io
