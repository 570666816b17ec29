// SPDX-License-Identifier: BSD-3-Clause
// The scenes of `mesolight bench vlf-accuracy`: each one stresses a way the light field's finite
// resolution goes wrong, with a camera that sees it (metres, y up, diffuse, closed solids only,
// so that the field's one-sided surfaces and the path tracer agree on what is lit).
//   boxes     900 small boxes (8 to 20 cm) on a 10 m floor under a square light: faces far
//             smaller than the line spacing;
//   room      a furnished room lit only indirectly by an uplight on a wardrobe: thin shelves on a
//             wall, a tilted panel leaning on the back wall, a table, a small turned cube;
//   corridor  a 16 m corridor with 10 cm ribs every metre on both walls under three small
//             ceiling lights, the far one brightest: a large range of scales and brightness;
//   thin      a room with a 1 cm panel hung 3 cm before a wall, a thin fin, 5 cm cubes along
//             the walls and a box in a corner, under a ceiling light: contacts and gaps;
//   cornell   the Cornell box (MakeCornellBox) and its published camera;
//   props     not in the default list: an office furnished with nine models made for a game
//             (Debian's redeclipse-data), open meshes whose hidden faces were left out, unlike
//             the closed solids above: the light field on geometry nobody built for it.
#ifndef mesolight_VlfAccuracyScenes_h
#define mesolight_VlfAccuracyScenes_h

#include "PinholeCamera.h"
#include "TriangleScene.h"

#include <string>
#include <vector>

namespace mesolight
{

struct AccuracyScene
{
  std::string Name;
  std::string Description;
  TriangleScene Scene;
  PinholeCamera Camera;
  // The reference's paths per pixel are --samples times this: a scene lit only by many bounces
  // needs more for its reference noise to stay well below the field's error.
  int ReferenceSamplesScale = 1;
};

// The benchmark's default scenes, in its order (MakeAccuracyScene also takes "props").
std::vector<std::string> AccuracySceneNames();
// Throws std::invalid_argument for an unknown name, std::runtime_error when "props" cannot find
// its models.
AccuracyScene MakeAccuracyScene(const std::string& name);

// A user's OBJ + MTL scene (at least one emitter), named after the file's stem; the caller sets
// its camera (the benchmark's --camera, which needs the scene's bounds). Throws ObjSceneError.
AccuracyScene MakeObjAccuracyScene(const std::string& path);

} // namespace mesolight

#endif
