// SPDX-License-Identifier: BSD-3-Clause
#include "TraceRelief.h"

#include "CommandLine.h"

#include "EmbreeScene.h"
#include "SurfaceRelief.h"
#include "TriangleScene.h"
#include "vtkMessageCollector.h"
#include "vtkOIIOImageReader.h"
#include "vtkReliefTextureFilter.h"

#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <iostream>

namespace mesolight
{

void AddTraceReliefOptions(CommandLine& cl)
{
  cl.AddValue("--relief", "SURFACE=DEPTH_IMAGE",
    "FILE.obj, cornell: a relief on a named planar surface, traced as a dense displaced mesh "
    "(one vertex per texel, sides closed)");
  cl.AddValue("--relief-depth-scale", "K",
    "world depth of depth 1 / world width of the relief's texture (vtkReliefProperty's units "
    "and default)",
    "0.05");
  cl.AddFlag("--relief-height", "the relief image stores height (white = high), not depth");
  cl.AddFlag("--relief-normalize", CommandLine::ReliefNormalizeHelp);
  cl.AddValue("--relief-subdivision", "N", "grid lines of the dense mesh per texel", "1");
  cl.AddValue("--relief-mask", "FILE.exr",
    "also write the share of each pixel covered by the relief surface (1 = all of it)");
  for (const char* option : { "--relief-depth-scale", "--relief-mask", "--relief-height",
         "--relief-normalize", "--relief-subdivision" })
  {
    cl.AppliesOnlyWith(option, { "--relief" });
  }
}

bool ReadDepthMapImage(const std::string& file, bool isHeight, bool normalize,
  std::vector<float>& depth, int& width, int& height, std::string& error)
{
  vtkNew<MessageCollector> errors;
  vtkNew<vtkOIIOImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(file.c_str());
  vtkNew<vtkReliefTextureFilter> bake;
  bake->AddObserver(vtkCommand::ErrorEvent, errors);
  bake->SetInputConnection(reader->GetOutputPort());
  bake->SetInvertInput(isHeight);
  bake->SetNormalizeRange(normalize);
  bake->Update();
  vtkImageData* relief = bake->GetOutput();
  vtkDataArray* scalars = relief ? relief->GetPointData()->GetScalars() : nullptr;
  if (!errors->Errors.empty() || !scalars || scalars->GetNumberOfComponents() != 4)
  {
    error = errors->Errors.empty() ? "cannot read the depth image " + file : errors->ErrorText();
    return false;
  }
  int dims[3];
  relief->GetDimensions(dims);
  width = dims[0];
  height = dims[1];
  depth.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t k = 0; k < depth.size(); ++k)
  {
    depth[k] = static_cast<float>(scalars->GetComponent(static_cast<vtkIdType>(k), 3));
  }
  return true;
}

bool ApplyTraceRelief(
  const CommandLine& cl, TriangleScene& scene, std::string& surface, std::string& error)
{
  surface.clear();
  if (!cl.Has("--relief"))
  {
    return true; // (the relief options need --relief: AddTraceReliefOptions)
  }
  const std::string spec = cl.Get("--relief");
  const std::size_t equals = spec.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == spec.size())
  {
    error = "--relief takes SURFACE=DEPTH_IMAGE (e.g. back=bricks.png), not '" + spec + "'";
    return false;
  }
  double scale = 0.05;
  int subdivision = 1;
  if (!cl.GetDouble("--relief-depth-scale", 0.0, 100.0, scale, error) ||
    !cl.GetInt("--relief-subdivision", 1, 16, subdivision, error))
  {
    return false;
  }
  DepthMap map;
  if (!ReadDepthMapImage(spec.substr(equals + 1), cl.Has("--relief-height"),
        cl.Has("--relief-normalize"), map.Depth, map.Width, map.Height, error))
  {
    return false;
  }
  surface = spec.substr(0, equals);
  SurfaceReliefSettings settings;
  settings.DepthScale = static_cast<float>(scale);
  settings.Subdivision = subdivision;
  try
  {
    SurfaceReliefResult result = DisplaceSurface(scene, surface, map, settings);
    std::cout << "relief on '" << surface << "': " << map.Width << "x" << map.Height
              << " depth texels, " << result.SurfaceTriangles << " displaced and "
              << result.SideTriangles
              << " side triangles, depth 1 = " << scale * glm::length(result.Plane.AxisU)
              << " world units\n";
    scene = std::move(result.Scene);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  return true;
}

RgbImage SurfaceMask(const TriangleScene& scene, const EmbreeScene& embree,
  const std::string& surface, const PinholeCamera& camera, int width, int height)
{
  RgbImage mask(width, height);
  std::vector<bool> onSurface(scene.TriangleCount(), false);
  for (std::size_t t : SurfaceTriangles(scene, surface))
  {
    onSurface[t] = true;
  }
  constexpr int n = 4;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      int inside = 0;
      for (int b = 0; b < n; ++b)
      {
        for (int a = 0; a < n; ++a)
        {
          const SceneHit hit =
            embree.Intersect(camera.Ray(i + (a + 0.5f) / n, j + (b + 0.5f) / n, width, height));
          inside += hit.Triangle != SceneHit::None && onSurface[hit.Triangle] ? 1 : 0;
        }
      }
      float* px = mask.Pixel(i, j);
      px[0] = px[1] = px[2] = static_cast<float>(inside) / (n * n);
    }
  }
  return mask;
}

} // namespace mesolight
