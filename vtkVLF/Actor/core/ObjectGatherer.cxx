// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectGatherer.h"

#include "MathConstants.h"
#include "ParallelFor.h"

#include <stdexcept>

namespace mesolight
{
namespace vlf
{

//------------------------------------------------------------------------------
ObjectGatherer::ObjectGatherer(const LightField& field)
  : Field(field)
{
}

//------------------------------------------------------------------------------
const ShadedObject& ObjectGatherer::Gather(
  const ObjectMesh& unitMesh, const GatherSettings& settings)
{
  const std::string problem = unitMesh.Validate();
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  this->Shaded.Mesh = unitMesh;
  if (this->Shaded.Mesh.Normals.empty())
  {
    this->Shaded.Mesh.ComputeNormals();
  }
  const std::size_t n = this->Shaded.Mesh.Points.size();
  this->Shaded.Irradiance.assign(n, glm::vec3(0.0f));
  this->Shaded.Radiance.assign(n, glm::vec3(0.0f));
  const Lookup lookup(this->Field);
  const glm::vec3 albedo = this->Shaded.Mesh.Kd / Pi<float>;
  ParallelFor(0, n, 16,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        const glm::vec3 e = lookup.Irradiance(
          this->Shaded.Mesh.Points[i], this->Shaded.Mesh.Normals[i], settings.Lookup);
        this->Shaded.Irradiance[i] = e;
        this->Shaded.Radiance[i] = albedo * e;
      }
    });
  this->Shaded.GatheredPoints = n;
  return this->Shaded;
}

} // namespace vlf
} // namespace mesolight
