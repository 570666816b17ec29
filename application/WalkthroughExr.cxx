// SPDX-License-Identifier: BSD-3-Clause
#include "WalkthroughExr.h"

#include "DisplayTransform.h"

#include "vtkLightFieldActor.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace mesolight
{

bool CaptureWalkthroughRadiance(vtkLightFieldActor* actor, vtkRenderWindow* window,
  RgbImage& radiance, std::string& error, int supersampling)
{
  const double exposure = actor->GetExposure();
  const int toneMap = actor->GetToneMap();
  const int* size = window->GetSize();
  const int width = size[0], height = size[1];
  const std::size_t values = static_cast<std::size_t>(width) * height * 3;
  radiance = RgbImage(width, height);
  std::vector<bool> done(values, false);
  // A code below this is unclipped (the clamp operator saturates at 255).
  const int unclipped = 250;
  actor->SetToneMap(vtkLightFieldActor::Clamp);
  bool ok = true;
  // Geometry mode draws no radiance (VTK lighting of the materials): one frame, its sRGB decoded.
  const bool geometry = actor->GetRenderMode() == vtkLightFieldActor::Geometry;
  const int first = geometry ? 0 : 6, last = geometry ? 0 : -8;
  // From the brightest exposure down: the first that leaves a value unclipped is the finest one.
  for (int step = first; step >= last && ok; --step)
  {
    const double scale = std::ldexp(1.0, 2 * step);
    actor->SetExposure(scale);
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ShouldRerenderOff();
    grab->ReadFrontBufferOn();
    grab->Update();
    vtkImageData* frame = grab->GetOutput();
    int dims[3];
    frame->GetDimensions(dims);
    if (dims[0] != width || dims[1] != height || frame->GetNumberOfScalarComponents() != 3)
    {
      error = "could not read the frame back for --exr";
      ok = false;
      break;
    }
    const auto* bytes = static_cast<const unsigned char*>(frame->GetScalarPointer());
    bool remaining = false;
    for (std::size_t v = 0; v < values; ++v)
    {
      if (done[v])
      {
        continue;
      }
      if (bytes[v] < unclipped || step == last)
      {
        radiance.Rgb[v] = static_cast<float>(FromSRGB(bytes[v] / 255.0) / scale);
        done[v] = true;
      }
      else
      {
        remaining = true;
      }
    }
    if (!remaining)
    {
      break;
    }
  }
  actor->SetExposure(exposure);
  actor->SetToneMap(toneMap);
  window->Render();
  const int s = std::max(1, supersampling);
  if (ok && s > 1)
  {
    RgbImage mean(width / s, height / s);
    for (int j = 0; j < mean.Height; ++j)
    {
      for (int i = 0; i < mean.Width; ++i)
      {
        float* out = mean.Pixel(i, j);
        for (int b = 0; b < s; ++b)
        {
          for (int a = 0; a < s; ++a)
          {
            const float* in = radiance.Pixel(s * i + a, s * j + b);
            for (int c = 0; c < 3; ++c)
            {
              out[c] += in[c] / static_cast<float>(s * s);
            }
          }
        }
      }
    }
    radiance = std::move(mean);
  }
  return ok;
}

} // namespace mesolight
