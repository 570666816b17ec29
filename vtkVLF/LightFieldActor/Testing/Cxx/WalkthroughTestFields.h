// SPDX-License-Identifier: BSD-3-Clause
// Propagated fields of the mirror Cornell box shared by the walkthrough tests (built once per
// direction count and process).
#ifndef mesolight_WalkthroughTestFields_h
#define mesolight_WalkthroughTestFields_h

#include "LightField.h"
#include "Propagation.h"
#include "TriangleScene.h"

#include <map>
#include <memory>

namespace mesolight
{
namespace walkthroughtest
{

// A Cornell box field built once per scene and direction count with the test settings: 32 x 32
// lines per subfield in 4 x 4 tiles, 10 iterations (the Cornell box keeps ~9% of its light beyond
// 4 bounces; 10 leave ~1%).
template <TriangleScene (*MakeScene)()>
const vlf::LightField& CachedCornellField(std::size_t directions)
{
  static std::map<std::size_t, std::unique_ptr<vlf::LightField>> fields;
  std::unique_ptr<vlf::LightField>& field = fields[directions];
  if (!field)
  {
    vlf::LightFieldSettings settings;
    settings.Directions = directions;
    settings.RaysPerSide = 32;
    settings.TilesPerSide = 4;
    field = vlf::LightField::Build(MakeScene(), settings);
    vlf::Propagate(*field, 10);
  }
  return *field;
}

inline const vlf::LightField& MirrorCornellField(std::size_t directions)
{
  return CachedCornellField<MakeCornellBoxWithMirror>(directions);
}

// The plain Cornell box with the mirror fields' settings.
inline const vlf::LightField& PlainCornellField(std::size_t directions)
{
  return CachedCornellField<MakeCornellBox>(directions);
}

inline const vlf::LightField& DiffuseCornellField()
{
  static std::unique_ptr<vlf::LightField> field;
  if (!field)
  {
    vlf::LightFieldSettings settings;
    settings.Directions = 513;
    settings.RaysPerSide = 32;
    settings.TilesPerSide = 4;
    field = vlf::LightField::Build(MakeCornellBox(), settings);
    vlf::Propagate(*field, 4);
  }
  return *field;
}

} // namespace walkthroughtest
} // namespace mesolight

#endif
