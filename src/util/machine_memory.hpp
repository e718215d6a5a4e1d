#pragma once
// The memory of the machine (node) this process runs on, for refusing a run it cannot hold.
// Linux: the physical memory from sysconf(_SC_PHYS_PAGES) × the page size, the memory available
// now from /proc/meminfo's MemAvailable (what the kernel can give without swapping). A limit a
// batch system sets through cgroups is not read.

namespace bagnold {

struct MachineMemory {
  double physical = 0.0;   // [B]
  double available = 0.0;  // [B]; the physical memory where /proc/meminfo cannot be read
};

MachineMemory machine_memory();

}  // namespace bagnold
