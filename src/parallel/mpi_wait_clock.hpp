#pragma once
// Wall seconds this rank has spent in MPI calls that wait for other ranks: reductions,
// broadcasts, gathers, scans, barriers, blocking receives and the waits on non-blocking
// messages (MPI_Wait, Waitall, Waitany, Waitsome). The program defines those MPI functions
// through MPI's profiling interface (each calls its PMPI_ twin inside a clock), so the calls
// PETSc and hypre make are counted too. Local; a call made while another is timed is not
// counted twice.

namespace bagnold::parallel {

double mpi_wait_seconds();
// This thread's CPU seconds since an arbitrary start (CLOCK_THREAD_CPUTIME_ID; a system call,
// so not for every MPI call).
double thread_cpu_seconds();

}  // namespace bagnold::parallel
