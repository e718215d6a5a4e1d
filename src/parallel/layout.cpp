#include "src/parallel/layout.hpp"

#include <algorithm>
#include <stdexcept>

namespace bagnold::parallel {

using grid::CellKind;
using grid::Index3;
using grid::Natural;

namespace {
constexpr int halo_depth = 2;  // enough for TVD stencils (i ± 2)

const Index3 face_offsets[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
}  // namespace

Layout::Layout(const grid::StructuredGrid& grid, const grid::CellFlags& flags,
               const std::vector<int>& owner, const Communicator& comm)
    : m_grid(&grid), m_comm(comm) {
  const int me = comm.rank();
  const auto n = static_cast<std::size_t>(grid.extended_cell_count());

  // 1. Owned cells: fluid first, then boundary, each in natural order.
  for (auto want : {CellKind::fluid, CellKind::boundary}) {
    for (std::size_t c = 0; c < n; ++c)
      if (owner[c] == me && flags.kind[c] == want) m_natural.push_back(static_cast<Natural>(c));
    if (want == CellKind::fluid) m_owned_fluid = static_cast<int>(m_natural.size());
  }
  m_owned = static_cast<int>(m_natural.size());
  for (int l = 0; l < m_owned; ++l) m_local_of.emplace(m_natural[static_cast<std::size_t>(l)], l);

  // 2. Halo: stored cells of other ranks within halo_depth of an owned cell.
  std::vector<Natural> halo;
  for (int l = 0; l < m_owned; ++l) {
    const Index3 ijk = grid.index3(m_natural[static_cast<std::size_t>(l)]);
    for (int dk = -halo_depth; dk <= halo_depth; ++dk)
      for (int dj = -halo_depth; dj <= halo_depth; ++dj)
        for (int di = -halo_depth; di <= halo_depth; ++di) {
          Index3 other;
          if (!grid.step(ijk, {di, dj, dk}, other)) continue;
          const Natural o = grid.natural(other);
          const int o_owner = owner[static_cast<std::size_t>(o)];
          if (o_owner >= 0 && o_owner != me) halo.push_back(o);
        }
  }
  std::sort(halo.begin(), halo.end(), [&](Natural a, Natural b) {
    const int ra = owner[static_cast<std::size_t>(a)], rb = owner[static_cast<std::size_t>(b)];
    return ra != rb ? ra < rb : a < b;
  });
  halo.erase(std::unique(halo.begin(), halo.end()), halo.end());
  for (const Natural h : halo) {
    m_local_of.emplace(h, static_cast<int>(m_natural.size()));
    m_natural.push_back(h);
  }

  // 3. Per-cell data and the face-neighbour table.
  const std::size_t local = m_natural.size();
  m_kind.resize(local);
  m_region.resize(local);
  m_neighbours.assign(local * 6, -1);
  for (std::size_t l = 0; l < local; ++l) {
    const auto c = static_cast<std::size_t>(m_natural[l]);
    m_kind[l] = flags.kind[c];
    m_region[l] = flags.region[c];
    const Index3 ijk = grid.index3(m_natural[l]);
    for (int f = 0; f < 6; ++f) {
      Index3 other;
      if (grid.step(ijk, face_offsets[f], other)) m_neighbours[l * 6 + static_cast<std::size_t>(f)] = find(grid.natural(other));
    }
  }

  // 4. Global fluid numbering, contiguous per rank; halo cells learn theirs from their owners.
  m_fluid_offset = comm.exclusive_scan(m_owned_fluid);
  m_fluid_total = comm.sum(std::int64_t{m_owned_fluid});
  m_global_fluid.assign(local, -1);
  for (int l = 0; l < m_owned_fluid; ++l)
    m_global_fluid[static_cast<std::size_t>(l)] = m_fluid_offset + l;

  build_halo_plan(owner);
  exchange_halo<std::int64_t>(*this, m_global_fluid);
}

int Layout::find(Natural n) const {
  const auto it = m_local_of.find(n);
  return it == m_local_of.end() ? -1 : it->second;
}

void Layout::build_halo_plan(const std::vector<int>& owner) {
  const int size = m_comm.size();
  // Halo cells are grouped by owner: one receive range per peer.
  std::vector<int> receive_count(static_cast<std::size_t>(size), 0);
  for (int l = m_owned; l < local_count(); ++l)
    ++receive_count[static_cast<std::size_t>(owner[static_cast<std::size_t>(natural(l))])];
  // Tell each owner which of its cells we hold (by natural index); it replies with nothing but
  // builds its send list from the request.
  std::vector<int> send_count(static_cast<std::size_t>(size), 0);
  MPI_Alltoall(receive_count.data(), 1, MPI_INT, send_count.data(), 1, MPI_INT, m_comm.get());
  std::vector<int> request_displ(static_cast<std::size_t>(size) + 1, 0),
      reply_displ(static_cast<std::size_t>(size) + 1, 0);
  for (int r = 0; r < size; ++r) {
    request_displ[static_cast<std::size_t>(r) + 1] =
        request_displ[static_cast<std::size_t>(r)] + receive_count[static_cast<std::size_t>(r)];
    reply_displ[static_cast<std::size_t>(r) + 1] =
        reply_displ[static_cast<std::size_t>(r)] + send_count[static_cast<std::size_t>(r)];
  }
  std::vector<Natural> wanted(m_natural.begin() + m_owned, m_natural.end());
  std::vector<Natural> asked(static_cast<std::size_t>(reply_displ.back()));
  MPI_Alltoallv(wanted.data(), receive_count.data(), request_displ.data(), MPI_INT64_T,
                asked.data(), send_count.data(), reply_displ.data(), MPI_INT64_T, m_comm.get());
  for (int r = 0; r < size; ++r) {
    const auto ur = static_cast<std::size_t>(r);
    if (receive_count[ur] == 0 && send_count[ur] == 0) continue;
    HaloPlan::Peer peer;
    peer.rank = r;
    peer.receive_begin = m_owned + request_displ[ur];
    peer.receive_end = m_owned + request_displ[ur + 1];
    for (int i = reply_displ[ur]; i < reply_displ[ur + 1]; ++i) {
      const int l = find(asked[static_cast<std::size_t>(i)]);
      if (l < 0 || l >= m_owned) throw std::logic_error("halo request for a cell not owned here");
      peer.send.push_back(l);
    }
    m_halo.peers.push_back(std::move(peer));
  }
}

template <class T>
void exchange_halo(const Layout& layout, std::span<T> values) {
  if (static_cast<int>(values.size()) != layout.local_count())
    throw std::logic_error("exchange_halo: field size does not match the layout");
  const auto& peers = layout.halo().peers;
  // Kept between calls (one set per value type): an exchange in the outer iteration allocates
  // nothing once the buffers have grown to the peers' sizes.
  static thread_local std::vector<std::vector<T>> send_buffers;
  static thread_local std::vector<MPI_Request> requests;
  send_buffers.resize(peers.size());
  requests.clear();
  requests.reserve(2 * peers.size());
  const MPI_Comm comm = layout.comm().get();
  constexpr int tag = 7401;
  for (std::size_t p = 0; p < peers.size(); ++p) {
    const auto& peer = peers[p];
    const int count = peer.receive_end - peer.receive_begin;
    if (count > 0) {
      requests.emplace_back();
      MPI_Irecv(values.data() + peer.receive_begin, count, mpi_type<T>(), peer.rank, tag, comm,
                &requests.back());
    }
  }
  for (std::size_t p = 0; p < peers.size(); ++p) {
    const auto& peer = peers[p];
    if (peer.send.empty()) continue;
    auto& buffer = send_buffers[p];
    buffer.clear();
    buffer.reserve(peer.send.size());
    for (const int l : peer.send) buffer.push_back(values[static_cast<std::size_t>(l)]);
    requests.emplace_back();
    MPI_Isend(buffer.data(), static_cast<int>(buffer.size()), mpi_type<T>(), peer.rank, tag, comm,
              &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

template void exchange_halo<double>(const Layout&, std::span<double>);
template void exchange_halo<float>(const Layout&, std::span<float>);
template void exchange_halo<int>(const Layout&, std::span<int>);
template void exchange_halo<std::int64_t>(const Layout&, std::span<std::int64_t>);
template void exchange_halo<std::uint8_t>(const Layout&, std::span<std::uint8_t>);

}  // namespace bagnold::parallel
