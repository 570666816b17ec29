// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefReference.h"

#include "BoundTraversalOracle.h"
#include "HeightFieldTracer.h"
#include "ImageCompare.h"
#include "ParallelFor.h"
#include "ReliefScene.h"
#include "vtkMinDepthPyramidTexture.h"
#include "vtkReliefPlaneFilter.h"

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>

namespace mesolight
{

//------------------------------------------------------------------------------
void ReliefReference::HitPosition(size_t p, double position[3]) const
{
  const double aspect = this->WallHeight;
  position[0] = this->HitU[p];
  position[1] = this->HitV[p] * aspect;
  position[2] = -this->HitD[p] * this->DepthScale;
}

long long ReliefReference::CountFootprint() const
{
  long long n = 0;
  for (unsigned char s : this->State)
  {
    n += s != OutsideFootprint;
  }
  return n;
}

long long ReliefReference::CountCovered() const
{
  long long n = 0;
  for (unsigned char s : this->State)
  {
    n += s == Covered;
  }
  return n;
}

//------------------------------------------------------------------------------
ReliefReferenceInput MakeReliefReferenceInput(
  const ReliefScene& scene, const ReliefSceneOptions& options, double depthScale)
{
  ReliefReferenceInput input;
  input.Camera = scene.Renderer ? scene.Renderer->GetActiveCamera() : nullptr;
  input.Width = options.Width;
  input.Height = options.Height;
  input.Relief = scene.ReliefTexture;
  input.DepthScale = depthScale > 0.0 ? depthScale : options.DepthScale;
  vtkLightCollection* lights = scene.Renderer ? scene.Renderer->GetLights() : nullptr;
  vtkLight* light = nullptr;
  if (lights)
  {
    lights->InitTraversal();
    light = lights->GetNextItem();
  }
  if (light && light->GetSwitch())
  {
    double position[3], focal[3];
    light->GetTransformedPosition(position);
    light->GetTransformedFocalPoint(focal);
    input.HasLight = true;
    input.LightPositional = light->GetPositional() != 0;
    for (int i = 0; i < 3; ++i)
    {
      input.Light[i] = input.LightPositional ? position[i] : position[i] - focal[i];
    }
  }
  return input;
}

//------------------------------------------------------------------------------
bool ComputeReliefReference(
  const ReliefReferenceInput& input, ReliefReference& reference, std::string& error)
{
  const auto start = std::chrono::steady_clock::now();
  if (!input.Camera || input.Width < 1 || input.Height < 1)
  {
    error = "reference: no camera or an empty window";
    return false;
  }
  if (!(input.DepthScale > 0.0) || !std::isfinite(input.DepthScale))
  {
    error = "reference: the depth scale must be positive";
    return false;
  }
  vtkDataArray* scalars = input.Relief ? input.Relief->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (input.Relief)
  {
    input.Relief->GetDimensions(dims);
  }
  if (!scalars || dims[0] < 1 || dims[1] < 1 ||
    (scalars->GetNumberOfComponents() != 4 && scalars->GetNumberOfComponents() != 1) ||
    scalars->GetNumberOfTuples() != vtkIdType(dims[0]) * dims[1])
  {
    error = "reference: the relief texture needs RGBA (depth in A) or one depth component";
    return false;
  }

  // The height field: the relief image's depth channel, row 0 at v ~ 0 (VTK's row order).
  const int tw = dims[0], th = dims[1];
  const int depthComponent = scalars->GetNumberOfComponents() - 1;
  std::vector<float> depth(size_t(tw) * th);
  for (vtkIdType i = 0; i < vtkIdType(depth.size()); ++i)
  {
    depth[size_t(i)] = static_cast<float>(scalars->GetComponent(i, depthComponent));
  }
  std::unique_ptr<HeightField> field;
  try
  {
    field = std::make_unique<HeightField>(tw, th, std::move(depth));
  }
  catch (const std::exception& e)
  {
    error = std::string("reference: ") + e.what();
    return false;
  }

  const int W = input.Width, H = input.Height;
  const size_t pixels = size_t(W) * H;
  reference.Width = W;
  reference.Height = H;
  reference.TextureWidth = tw;
  reference.TextureHeight = th;
  reference.WallHeight = vtkReliefPlaneFilter::GetGroundProportions(input.Relief);
  reference.DepthScale = input.DepthScale;
  reference.State.assign(pixels, ReliefReference::OutsideFootprint);
  reference.HitU.assign(pixels, 0.0);
  reference.HitV.assign(pixels, 0.0);
  reference.HitD.assign(pixels, 0.0);
  reference.EyeDepth.assign(pixels, 0.0);
  reference.Unshadowed.assign(pixels, 0);
  reference.FacesLight.assign(pixels, 0);
  reference.BoundReachingCells.assign(pixels, -1);
  reference.OracleFetchesStoredLevels.assign(pixels, -1);
  reference.OracleFetchesAllLevels.assign(pixels, -1);

  // Pixel centres to world rays through the inverse of the camera's composite projection (the
  // matrix VTK renders with: world -> normalized device coordinates, depth in [-1, 1]).
  vtkNew<vtkMatrix4x4> toWorld;
  toWorld->DeepCopy(input.Camera->GetCompositeProjectionTransformMatrix(double(W) / H, -1.0, 1.0));
  toWorld->Invert();
  double m[16];
  vtkMatrix4x4::DeepCopy(m, toWorld);
  double view[16];
  vtkMatrix4x4::DeepCopy(view, input.Camera->GetViewTransformMatrix());

  const double aspect = reference.WallHeight; // wall height / width
  const double s = input.DepthScale;
  const double uLow = 0.5 / tw, uHigh = 1.0 - 0.5 / tw;
  const double vLow = 0.5 / th, vHigh = 1.0 - 0.5 / th;
  const HeightField& hf = *field;
  // Built only when asked for: it holds the whole min-depth pyramid.
  std::unique_ptr<BoundTraversalOracle> oracle;
  if (input.CountTraversalFetches)
  {
    oracle = std::make_unique<BoundTraversalOracle>(hf);
  }
  // The compact storage keeps the bounds of levels FirstLevel - 1 and coarser (each stored
  // texel holds its children's).
  const int storedBoundLevel = vtkMinDepthPyramidTexture::FirstLevel - 1;

  const auto unproject = [&m](double x, double y, double z, glm::dvec3& out)
  {
    const double in[4] = { x, y, z, 1.0 };
    double r[4];
    for (int row = 0; row < 4; ++row)
    {
      r[row] =
        m[4 * row] * in[0] + m[4 * row + 1] * in[1] + m[4 * row + 2] * in[2] + m[4 * row + 3];
    }
    out = glm::dvec3(r[0], r[1], r[2]) / r[3];
  };

  mesolight::ParallelFor(0, static_cast<std::size_t>(H), 0,
    [&](std::size_t rowBegin, std::size_t rowEnd)
    {
      for (std::size_t y = rowBegin; y < rowEnd; ++y)
      {
        for (int x = 0; x < W; ++x)
        {
          const size_t p = size_t(y) * W + x;
          const double nx = 2.0 * (x + 0.5) / W - 1.0;
          const double ny = 2.0 * (y + 0.5) / H - 1.0;
          glm::dvec3 front, back;
          unproject(nx, ny, -1.0, front);
          unproject(nx, ny, 1.0, back);
          const glm::dvec3 dir = back - front;
          if (!(dir.z < 0.0) || front.z < 0.0)
          {
            continue; // parallel to the wall, seen from behind, or the wall is clipped
          }
          const double tWall = -front.z / dir.z;
          const double wx = front.x + tWall * dir.x;
          const double wy = front.y + tWall * dir.y;
          const double u0 = wx, v0 = wy / aspect;
          if (u0 < uLow || u0 > uHigh || v0 < vLow || v0 > vHigh)
          {
            continue;
          }
          reference.State[p] = ReliefReference::Uncovered;
          // Texture space: per unit of ray parameter the ray descends one full depth unit.
          const glm::dvec3 q(dir.x, dir.y / aspect, -dir.z / s);
          const glm::dvec3 span = q / q.z;
          const auto hit = IntersectFirst(hf, glm::dvec3(u0, v0, 0.0), span, 2.0);
          if (!hit)
          {
            continue; // cannot happen for depths in [0, 1]
          }
          const glm::dvec3& h = hit->point;
          if (h.x < uLow || h.x > uHigh || h.y < vLow || h.y > vHigh)
          {
            continue; // silhouette: the hit leaves the mesh's texel-centre domain
          }
          reference.State[p] = ReliefReference::Covered;
          reference.HitU[p] = h.x;
          reference.HitV[p] = h.y;
          reference.HitD[p] = h.z;
          if (oracle)
          {
            const glm::dvec3 entry(u0, v0, 0.0);
            reference.BoundReachingCells[p] = CountBoundReachingCells(hf, entry, span, hit->t);
            reference.OracleFetchesStoredLevels[p] =
              oracle->Fetches(entry, span, hit->t, storedBoundLevel);
            reference.OracleFetchesAllLevels[p] = oracle->Fetches(entry, span, hit->t, 0);
          }
          const double world[3] = { h.x, h.y * aspect, -h.z * s };
          const double eyeZ =
            view[8] * world[0] + view[9] * world[1] + view[10] * world[2] + view[11];
          reference.EyeDepth[p] = -eyeZ;
          if (!input.HasLight)
          {
            continue;
          }
          double l[3];
          for (int i = 0; i < 3; ++i)
          {
            l[i] = input.LightPositional ? input.Light[i] - world[i] : input.Light[i];
          }
          // Normal of the bilinear surface (u, aspect v, -s d(u, v)): dP/du x dP/dv.
          const glm::dvec2 g = hf.GradientAt(h.x, h.y);
          const double n[3] = { s * aspect * g.x, s * g.y, aspect };
          reference.FacesLight[p] = n[0] * l[0] + n[1] * l[1] + n[2] * l[2] > 0.0;
          const glm::dvec3 toLight(l[0], l[1] / aspect, -l[2] / s);
          reference.Unshadowed[p] = Visible(hf, h, toLight);
        }
      }
    });
  reference.Seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

//------------------------------------------------------------------------------
HitComparison CompareHits(const ReliefReference& reference, const Frame& hitU, const Frame& hitV)
{
  HitComparison c;
  const size_t pixels = size_t(reference.Width) * reference.Height;
  if (hitU.Width != reference.Width || hitU.Height != reference.Height ||
    hitV.Width != reference.Width || hitV.Height != reference.Height ||
    hitU.Depth.size() != pixels || hitV.Depth.size() != pixels)
  {
    c.SilhouetteMismatch = 100.0;
    return c;
  }
  std::vector<double> errors;
  long long onlyOne = 0;
  for (size_t p = 0; p < pixels; ++p)
  {
    if (!reference.InFootprint(p))
    {
      continue;
    }
    ++c.Footprint;
    double u = 0.0, v = 0.0;
    const bool gpu = DecodeHitCoordinate(hitU, p, u) && DecodeHitCoordinate(hitV, p, v);
    const bool cpu = reference.IsCovered(p);
    if (gpu != cpu)
    {
      ++onlyOne;
    }
    if (gpu && cpu)
    {
      const double du = (u - reference.HitU[p]) * reference.TextureWidth;
      const double dv = (v - reference.HitV[p]) * reference.TextureHeight;
      errors.push_back(std::sqrt(du * du + dv * dv));
    }
  }
  c.CoveredBoth = static_cast<long long>(errors.size());
  c.SilhouetteMismatch = c.Footprint > 0 ? 100.0 * double(onlyOne) / double(c.Footprint) : 0.0;
  if (!errors.empty())
  {
    double sum = 0.0;
    for (double e : errors)
    {
      sum += e;
    }
    c.MeanTexels = sum / double(errors.size());
    const size_t k =
      std::min(errors.size() - 1, size_t(std::ceil(0.99 * double(errors.size()))) - 1);
    std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(k), errors.end());
    c.P99Texels = errors[k];
    c.MaxTexels = *std::max_element(errors.begin() + std::ptrdiff_t(k), errors.end());
  }
  return c;
}

//------------------------------------------------------------------------------
double CompareLightVisibility(
  const ReliefReference& reference, const Frame& visibility, long long* coveredBoth)
{
  const size_t pixels = size_t(reference.Width) * reference.Height;
  long long both = 0, differ = 0;
  if (visibility.Width == reference.Width && visibility.Height == reference.Height &&
    visibility.Depth.size() == pixels)
  {
    for (size_t p = 0; p < pixels; ++p)
    {
      if (!reference.IsCovered(p) || !visibility.Covered(p))
      {
        continue;
      }
      ++both;
      const bool gpuLit = visibility.Rgb[3 * p] > 127;
      differ += gpuLit != reference.LightVisible(p);
    }
  }
  if (coveredBoth)
  {
    *coveredBoth = both;
  }
  return both > 0 ? 100.0 * double(differ) / double(both) : 0.0;
}

} // namespace mesolight
