// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench walkthrough`: the frame time of every walkthrough mode (vtkLightFieldActor)
// split into stages, with CSV and a chart (docs/walkthrough.md).
#ifndef mesolight_WalkthroughBenchmark_h
#define mesolight_WalkthroughBenchmark_h

#include <memory>
#include <string>
#include <vector>

class vtkRenderWindow;

namespace mesolight
{
struct TriangleScene;
namespace vlf
{
class LightField;
}
}

namespace mesolight
{
/** mesolight bench walkthrough [FIELD] [--size 800x800] [--frames N] [--csv F] [--plot F.png] */
int RunWalkthroughBenchmark(const std::vector<std::string>& args);

/** A field of `scene` propagated for the benchmarks: `directions` x `rays`^2 lines in
 * (rays / 8)^2 tiles, `iterations` iterations. */
std::unique_ptr<vlf::LightField> BenchField(
  const TriangleScene& scene, int directions, int rays, int iterations);
/** Waits until the GPU finished the window's commands (frame times include the draw). */
void WaitForGpu(vtkRenderWindow* window);
} // namespace mesolight

#endif
