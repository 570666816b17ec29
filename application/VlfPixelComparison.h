// SPDX-License-Identifier: BSD-3-Clause
// The light field against the path tracer per camera pixel (`mesolight bench vlf-accuracy`):
// each pixel's primary hit, the reference's two independent halves there, the field's diffuse
// radiance there, and where the error lies.
#pragma once
#include "EmbreeScene.h" // SceneHit
#include "RgbImage.h"
#include "VlfAccuracyScenes.h"
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{
class LightField;
}

// A pixel the comparison uses: the front of a diffuse, non-emitting triangle.
struct PixelHit
{
  std::uint32_t Triangle = SceneHit::None;
  glm::vec3 Point{ 0.0f };
};

struct PixelError
{
  std::size_t Pixels = 0; // lit pixels compared
  double Mean = 0.0;      // mean |field - ref| / ref
  double P95 = 0.0;
  double Black = 0.0;          // share of lit pixels where the field is below 10% of ref
  double ReferenceNoise = 0.0; // mean |a - b| / (a + b): the reference's own relative error
};

std::vector<PixelHit> PrimaryHits(const AccuracyScene& s, const EmbreeScene& embree, int w, int h);

// Half of the reference: `samples` paths per pixel, seeds of half `half`.
RgbImage ReferenceHalf(const EmbreeScene& embree, const std::vector<PixelHit>& hits, int w, int h,
  int samples, int half);

// Lit pixels: reference above 1% of the mean over the compared pixels (shadows so deep that a
// relative error means nothing are left out; black-where-lit counts the rest).
PixelError ComparePixels(
  const std::vector<PixelHit>& hits, const RgbImage& field, const RgbImage& a, const RgbImage& b);

// The bias, edge against interior pixels, small against large surfaces (one comment line).
std::string ErrorBreakdown(const vlf::LightField& field, const std::vector<PixelHit>& hits, int w,
  int h, const RgbImage& image, const RgbImage& a, const RgbImage& b);

// The error by surface class (large or small, facing up, sideways or down) and position
// (inside, at a contact, at a border).
std::string ClassBreakdown(const vlf::LightField& field, const AccuracyScene& scene,
  const EmbreeScene& embree, const std::vector<PixelHit>& hits, float texelWorld,
  const RgbImage& image, const RgbImage& a, const RgbImage& b);

// The field's total diffuse radiance at each pixel's hit (what the walkthrough draws).
RgbImage FieldImage(const vlf::LightField& field, const std::vector<PixelHit>& hits, int w, int h);
} // namespace mesolight
