// SPDX-License-Identifier: BSD-3-Clause
// The scene on which TestReliefAgainstDenseMesh and TestReliefReference compare with the dense
// displaced mesh: the Bricks wall filling most of a 400x400 view at 55 degrees, without
// self-shadowing (the dense mesh drawn by VTK's stock mapper has none).
#ifndef mesolight_DenseMeshTestScene_h
#define mesolight_DenseMeshTestScene_h

#include "ReliefScene.h"

namespace mesolight
{
namespace test
{

inline ReliefSceneOptions DenseMeshTestScene()
{
  ReliefSceneOptions o;
  o.Pattern = "Bricks";
  o.Resolution = 256;
  o.Width = 400;
  o.Height = 400;
  o.DepthScale = 0.04;
  o.SelfShadowing = false;
  o.ViewAngle = 55.0;
  o.ViewDistance = 2.2; // the wall fills most of the view
  return o;
}

} // namespace test
} // namespace mesolight

#endif
