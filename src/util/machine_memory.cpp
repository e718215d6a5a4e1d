#include "src/util/machine_memory.hpp"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace bagnold {

MachineMemory machine_memory() {
  MachineMemory m;
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page_size > 0) m.physical = static_cast<double>(pages) * static_cast<double>(page_size);
  m.available = m.physical;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    std::istringstream fields(line);
    std::string name;
    double kib = 0.0;
    if (fields >> name >> kib && name == "MemAvailable:") {
      m.available = kib * 1024.0;
      break;
    }
  }
  return m;
}

}  // namespace bagnold
