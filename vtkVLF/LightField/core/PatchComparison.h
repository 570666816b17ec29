// SPDX-License-Identifier: BSD-3-Clause
// PatchComparison: the light field's diffuse radiance per patch (a planar surface: a Cornell box
// wall, a block face, the light) against any reference -- the path tracer's
// DiffuseRadianceLeaving (Le + Kd/pi * irradiance), an analytic formula, a constant.
//
// Each patch gets `samples` points spread over its triangles in proportion to their areas (a
// deterministic R2 low-discrepancy sequence, so runs are repeatable); at each the field's total
// diffuse texture (bilinear) is compared with the reference at the same point in the
// ORIGINAL (world) coordinates of the scene given to LightField::Build.
#ifndef mesolight_vlf_PatchComparison_h
#define mesolight_vlf_PatchComparison_h

#include "LightField.h"

#include <functional>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

// Reference diffuse radiance leaving triangle `triangle` at `worldPoint` (world coordinates).
using ReferenceRadiance =
  std::function<glm::vec3(std::uint32_t triangle, const glm::vec3& worldPoint)>;

struct PatchError
{
  std::uint32_t Surface = 0;
  std::string Name;  // "white, normal +y" (material name and dominant normal axis)
  double Area = 0.0; // world units squared
  std::size_t Samples = 0;
  glm::vec3 Field{ 0.0f };     // mean diffuse radiance of the light field over the samples
  glm::vec3 Reference{ 0.0f }; // mean reference radiance
  double MeanError = 0.0;      // |sum_c (Field_c - Reference_c)| / sum_c Reference_c
  double PointError = 0.0;     // RMS over samples of the per-point relative error (summed channels)
};

struct PatchComparisonResult
{
  std::vector<PatchError> Patches;
  double AreaWeightedMeanError = 0.0; // over non-emitting patches
  double WorstMeanError = 0.0;        // over non-emitting patches
  // A table, one patch a line: name, area, samples, field RGB, reference RGB, errors.
  std::string Table() const;
  // CSV with a header line, the same columns.
  std::string Csv() const;
};

// Throws std::invalid_argument when samples < 1 or the reference is empty.
PatchComparisonResult ComparePatches(
  const LightField& field, const ReferenceRadiance& reference, int samples);

// World-space point of a unit-sphere point of the field and back.
glm::vec3 ToWorld(const LightField& field, const glm::vec3& unit);
glm::vec3 ToUnit(const LightField& field, const glm::vec3& world);

} // namespace vlf
} // namespace mesolight

#endif
