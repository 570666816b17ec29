// SPDX-License-Identifier: BSD-3-Clause
#include "MemoryBudget.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sys/resource.h>
#include <unistd.h>

namespace mesolight
{

namespace
{
// A cgroup limit file holds a byte count, or "max" (v2) / a huge number (v1) when unlimited.
std::uint64_t ReadLimit(const char* file)
{
  std::ifstream in(file);
  std::uint64_t value = 0;
  if (in >> value && value > 0 && value < (std::uint64_t(1) << 60))
  {
    return value;
  }
  return 0;
}
} // namespace

std::uint64_t AvailableMemory()
{
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGE_SIZE);
  std::uint64_t memory = pages > 0 && pageSize > 0
    ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(pageSize)
    : (std::uint64_t(4) << 30);
  for (const char* file :
    { "/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes" })
  {
    const std::uint64_t limit = ReadLimit(file);
    if (limit > 0)
    {
      memory = std::min(memory, limit);
    }
  }
  // A virtual-memory limit (ulimit -v, RLIMIT_AS) bounds what may still be mapped: the limit
  // less the address space this process already maps (/proc/self/statm's first field, pages).
  struct rlimit limit = {};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
  {
    std::uint64_t mappedPages = 0;
    std::ifstream statm("/proc/self/statm");
    statm >> mappedPages;
    const std::uint64_t mapped =
      mappedPages * static_cast<std::uint64_t>(pageSize > 0 ? pageSize : 4096);
    const auto cap = static_cast<std::uint64_t>(limit.rlim_cur);
    memory = std::min(memory, cap > mapped ? cap - mapped : 0);
  }
  return memory;
}

std::uint64_t EffectiveMemoryBudget(std::int64_t budget)
{
  return budget > 0 ? static_cast<std::uint64_t>(budget) : AvailableMemory();
}

std::string FormatBytes(std::uint64_t bytes)
{
  const char* units[] = { "B", "KiB", "MiB", "GiB", "TiB" };
  double value = static_cast<double>(bytes);
  int unit = 0;
  while (value >= 1024.0 && unit < 4)
  {
    value /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof(text), unit >= 3 ? "%.2f %s" : "%.0f %s", value, units[unit]);
  return text;
}

std::string CheckMemoryBudget(const std::string& what, std::uint64_t needed, std::int64_t budget)
{
  const std::uint64_t limit = EffectiveMemoryBudget(budget);
  if (needed <= limit)
  {
    return "";
  }
  return what + " needs about " + FormatBytes(needed) + " of memory, more than the " +
    (budget > 0 ? "memory budget of " : "memory available, ") + FormatBytes(limit) +
    (budget > 0 ? "; raise the budget or use a smaller image" : "; use a smaller image");
}

} // namespace mesolight
