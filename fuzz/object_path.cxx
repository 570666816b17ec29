// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the movable object's path file (`mesolight vlf view --path FILE.csv`) and its
// placement text (--object-transform), application/ObjectPath.
//
// Input: the file's text; it is also given whole to ParsePlacement. A placement accepted must
// hold finite numbers and a positive scale; anything else aborts.
#include "ObjectPath.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
void CheckPlacement(const mesolight::ObjectPlacement& p)
{
  bool ok = std::isfinite(p.Scale) && p.Scale > 0.0;
  for (int a = 0; a < 3; ++a)
  {
    ok = ok && std::isfinite(p.Position[a]) && std::isfinite(p.Orientation[a]);
  }
  if (!ok)
  {
    std::abort();
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace mesolight;
  const std::string text(reinterpret_cast<const char*>(data), size);
  ObjectPlacement base;
  base.Scale = 0.25;
  std::istringstream in(text);
  std::vector<ObjectPlacement> path;
  std::string error;
  if (ReadPath(in, "fuzz.csv", base, path, error))
  {
    if (path.empty())
    {
      std::abort();
    }
    for (const ObjectPlacement& p : path)
    {
      CheckPlacement(p);
    }
  }
  else if (error.empty())
  {
    std::abort();
  }
  ObjectPlacement placement = base;
  if (ParsePlacement(text, placement).empty())
  {
    CheckPlacement(placement);
  }
  return 0;
}
