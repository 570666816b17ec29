// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MemoryBudget.h
 * @brief Memory estimates before big allocations (plain C++17).
 *
 * A filter that allocates per texel estimates its peak before allocating and refuses, with the
 * size it needs, when that exceeds its budget: a clear error instead of an uncaught
 * std::bad_alloc (or the kernel's OOM killer) half-way through. A budget of 0 means the memory
 * the process can get: the cgroup limit when one is set, else the physical memory.
 */
#ifndef mesolight_MemoryBudget_h
#define mesolight_MemoryBudget_h

#include "MesolightCommonModule.h" // for the export macro

#include <cstdint>
#include <string>

namespace mesolight
{

/**
 * Bytes this process may use: the cgroup (v2 or v1) memory limit if set, else physical RAM; no
 * more than a virtual-memory limit (ulimit -v) leaves beyond what the process already maps.
 */
MESOLIGHTCOMMON_EXPORT std::uint64_t AvailableMemory();

/** The budget a filter applies: `budget` bytes when > 0, else AvailableMemory(). */
MESOLIGHTCOMMON_EXPORT std::uint64_t EffectiveMemoryBudget(std::int64_t budget);

/** "1.23 GiB" / "456 MiB" / "12 KiB" / "7 B". */
MESOLIGHTCOMMON_EXPORT std::string FormatBytes(std::uint64_t bytes);

/**
 * "" when `needed` bytes fit `budget` (see EffectiveMemoryBudget), else a sentence naming what
 * needs the memory, how much, and the budget.
 */
MESOLIGHTCOMMON_EXPORT std::string CheckMemoryBudget(
  const std::string& what, std::uint64_t needed, std::int64_t budget);

} // namespace mesolight

#endif
