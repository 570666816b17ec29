// SPDX-License-Identifier: BSD-3-Clause
// The scene on which TestReliefAgainstDenseMesh and TestReliefReference compare with the dense
// displaced mesh: the Bricks wall filling most of a 400x400 view at 55 degrees, without
// self-shadowing (the dense mesh drawn by VTK's stock mapper has none), and the comparison.
#ifndef mesolight_DenseMeshTestScene_h
#define mesolight_DenseMeshTestScene_h

#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"

#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <functional>
#include <iostream>
#include <string>

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

// Renders the relief variant and the dense reference of the same options and compares them
// over the coarse mesh's footprint (depth tolerance: 5% of the relief's world depth). `lights`,
// when given, replaces the lights of both scenes.
inline FrameDifference CompareWithDenseMesh(const ReliefSceneOptions& options,
  const std::string& tag, const std::function<void(vtkRenderer*)>& lights = {})
{
  std::string error;
  ReliefScene dense, relief, coarse;
  EXPECT_TRUE(BuildDenseReferenceScene(options, dense, error)) << error;
  EXPECT_TRUE(BuildReliefScene(options, relief, error)) << error;
  EXPECT_TRUE(BuildTexturedPlaneScene(options, coarse, error)) << error;
  if (lights)
  {
    lights(dense.Renderer);
    lights(relief.Renderer);
  }
  auto coarseWindow = MakeOffscreenWindow(options, coarse.Renderer);
  const Frame footprint = CaptureFrame(coarseWindow);
  auto denseWindow = MakeOffscreenWindow(options, dense.Renderer);
  const Frame reference = CaptureFrame(denseWindow);
  auto reliefWindow = MakeOffscreenWindow(options, relief.Renderer);
  const Frame frame = CaptureFrame(reliefWindow);
  WritePng(reference, OutputPath(tag + "-dense.png").c_str());
  WritePng(frame, OutputPath(tag + "-relief.png").c_str());
  const FrameDifference d = CompareFrames(frame, reference, 0.05 * options.DepthScale, &footprint);
  std::cout << "[" << tag << "] mean colour error " << d.MeanColorError << " levels, PSNR "
            << d.Psnr << " dB, silhouette mismatch " << d.SilhouetteMismatch << "%, depth mismatch "
            << d.DepthMismatch << "%, mean depth error " << d.MeanDepthError << std::endl;
  return d;
}

} // namespace test
} // namespace mesolight

#endif
