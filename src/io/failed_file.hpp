#pragma once
// A snapshot file whose writes failed (a full disk) is left open, never closed: HDF5 1.10's
// H5Fclose flushes the file's metadata again, and when that flush fails it returns an error and
// the identifier stays registered; HDF5's shutdown (at MPI_Finalize or at exit) then closes it
// again and crashes (signal 11 in H5F__close_cb, with the serial driver as with MPI-IO). So a program that left one open must end through
// `exit_leaving_failed_files_open`, which skips that shutdown, and so must every other rank.

#include <hdf5.h>

namespace bagnold::io {

// Keeps `file` open for good (the writer has given up on it) and remembers that one is. Every
// rank calls it after an agreed failure, the rank that wrote the file with its id, the others
// with -1, so that all of them end through exit_leaving_failed_files_open.
void leave_failed_file_open(hid_t file);
bool a_failed_file_is_open();
// Flushes the standard streams and ends the process with `code` without shutting down HDF5 or
// MPI. Every rank must call it, after the last collective call of the run.
[[noreturn]] void exit_leaving_failed_files_open(int code);

}  // namespace bagnold::io
