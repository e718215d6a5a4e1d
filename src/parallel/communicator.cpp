#include "src/parallel/communicator.hpp"

namespace bagnold::parallel {

MpiSession::MpiSession(int& argc, char**& argv) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) MPI_Init(&argc, &argv);
}

MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized) MPI_Finalize();
}

Communicator::Communicator(MPI_Comm comm) : m_comm(comm) {
  MPI_Comm_rank(comm, &m_rank);
  MPI_Comm_size(comm, &m_size);
}

namespace {
template <class T>
T all_reduce(T x, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  T out{};
  MPI_Allreduce(&x, &out, 1, type, op, comm);
  return out;
}
}  // namespace

double Communicator::sum(double x) const { return all_reduce(x, MPI_DOUBLE, MPI_SUM, m_comm); }
std::int64_t Communicator::sum(std::int64_t x) const {
  return all_reduce(x, MPI_INT64_T, MPI_SUM, m_comm);
}
double Communicator::max(double x) const { return all_reduce(x, MPI_DOUBLE, MPI_MAX, m_comm); }
std::int64_t Communicator::max(std::int64_t x) const {
  return all_reduce(x, MPI_INT64_T, MPI_MAX, m_comm);
}
std::int64_t Communicator::min(std::int64_t x) const {
  return all_reduce(x, MPI_INT64_T, MPI_MIN, m_comm);
}

void Communicator::sum_in_place(std::vector<double>& values) const {
  sum_in_place(values.data(), values.size());
}

void Communicator::sum_in_place(double* values, std::size_t count) const {
  MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), MPI_DOUBLE, MPI_SUM, m_comm);
}

void Communicator::broadcast(std::string& text, int root) const {
  long size = static_cast<long>(text.size());
  MPI_Bcast(&size, 1, MPI_LONG, root, m_comm);
  text.resize(static_cast<std::size_t>(size));
  if (size > 0) MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, root, m_comm);
}

void Communicator::sum_in_place(std::vector<std::int64_t>& values) const {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_INT64_T, MPI_SUM,
                m_comm);
}

std::int64_t Communicator::exclusive_scan(std::int64_t x) const {
  std::int64_t out = 0;
  MPI_Exscan(&x, &out, 1, MPI_INT64_T, MPI_SUM, m_comm);
  return m_rank == 0 ? 0 : out;
}

std::vector<std::int64_t> Communicator::all_gather(std::int64_t x) const {
  std::vector<std::int64_t> out(static_cast<std::size_t>(m_size));
  MPI_Allgather(&x, 1, MPI_INT64_T, out.data(), 1, MPI_INT64_T, m_comm);
  return out;
}

double Communicator::sum_on_node(double x) const {
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(m_comm, MPI_COMM_TYPE_SHARED, m_rank, MPI_INFO_NULL, &node);
  const double sum = all_reduce(x, MPI_DOUBLE, MPI_SUM, node);
  MPI_Comm_free(&node);
  return sum;
}

void Communicator::barrier() const { MPI_Barrier(m_comm); }

}  // namespace bagnold::parallel
