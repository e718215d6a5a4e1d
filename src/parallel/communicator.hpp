#pragma once
// A thin view of an MPI communicator, and the RAII session that initializes and finalizes MPI.

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace bagnold::parallel {

class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
};

class Communicator {
 public:
  explicit Communicator(MPI_Comm comm = MPI_COMM_WORLD);
  MPI_Comm get() const { return m_comm; }
  int rank() const { return m_rank; }
  int size() const { return m_size; }
  bool is_root() const { return m_rank == 0; }

  double sum(double x) const;
  std::int64_t sum(std::int64_t x) const;
  double max(double x) const;
  std::int64_t max(std::int64_t x) const;
  std::int64_t min(std::int64_t x) const;
  // Elementwise sum over ranks, in place.
  void sum_in_place(std::vector<double>& values) const;
  void sum_in_place(double* values, std::size_t count) const;
  void sum_in_place(std::vector<std::int64_t>& values) const;
  // Every rank gets `root`'s text.
  void broadcast(std::string& text, int root) const;
  // Exclusive prefix sum of `x` over ranks (0 on rank 0).
  std::int64_t exclusive_scan(std::int64_t x) const;
  std::vector<std::int64_t> all_gather(std::int64_t x) const;
  // Sum of `x` over the ranks on this rank's node (that share its memory).
  double sum_on_node(double x) const;
  void barrier() const;

 private:
  MPI_Comm m_comm;
  int m_rank = 0;
  int m_size = 1;
};

}  // namespace bagnold::parallel
