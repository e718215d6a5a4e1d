#pragma once
// A parallel snapshot file whose writes failed (a full disk) is left open, never closed: HDF5
// 1.10's H5Fclose flushes the file's metadata again, and when that flush fails it crashes (signal
// 11) or waits in a collective. HDF5 closes the files still open when the library shuts down
// (at MPI_Finalize or at exit), so a program that left one open must end through
// `exit_leaving_failed_files_open`, which skips that shutdown.

#include <hdf5.h>

namespace bagnold::io {

// Keeps `file` open for good (the writer has given up on it) and remembers that one is.
void leave_failed_file_open(hid_t file);
bool a_failed_file_is_open();
// Flushes the standard streams and ends the process with `code` without shutting down HDF5 or
// MPI. Every rank must call it, after the last collective call of the run.
[[noreturn]] void exit_leaving_failed_files_open(int code);

}  // namespace bagnold::io
