// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the light-field snapshot reader (vtkVLF/LightField/core/Snapshot: the .vlf files of
// `mesolight vlf propagate`, read by `vlf render`, `vlf view`, `--resume`, vtkLightFieldActor and
// vtkVirtualLightField).
//
// Input: one mode byte, then bytes. Mode bit 0 clear: the bytes are the file as is (header
// checks). Set: they are the payload, wrapped in a header whose checksums match
// (SnapshotFileWithPayload), so mutations reach the checks of counts, indices and values that a
// checksum would otherwise hide. The file is read with a 256 MiB memory budget: a field that needs
// more must be refused (MemoryBudgetError) before it is allocated, which libFuzzer's
// -malloc_limit_mb checks. Any outcome but a field, SnapshotError or MemoryBudgetError is a bug.
#include "Snapshot.h"
#include "FuzzSupport.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace mesolight;
  if (size < 1)
  {
    return 0;
  }
  const std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  const std::string file = (data[0] & 1) ? vlf::SnapshotFileWithPayload(bytes) : bytes;
  const std::string path = fuzz::ScratchDirectory() + "/field.vlf";
  if (!fuzz::WriteFile(path, file.data(), file.size()))
  {
    std::abort(); // the scratch directory is unusable: not the reader's fault, but stop
  }
  try
  {
    const std::unique_ptr<vlf::LightField> field =
      vlf::ReadSnapshot(path, std::uint64_t(256) << 20);
    if (field->TotalDiffuse.size() != field->TexelCount())
    {
      std::abort();
    }
  }
  catch (const vlf::SnapshotError&)
  {
  }
  catch (const vlf::MemoryBudgetError&)
  {
  }
  return 0;
}
