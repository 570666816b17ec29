// SPDX-License-Identifier: BSD-3-Clause
// A relief surface lit by a virtual light field, on the CPU, from Mesolight's cores: the relief
// side (ReliefShading: a height field on a planar surface, shaded at its perturbed normal from
// SH9 probes and emitter samples) and the light-field side (FieldIrradiance: the field's incident
// radiance at a point as SH9) meet here, as they do in `mesolight vlf render --relief`
// (docs/vlf.md, "Relief surfaces in a light field").
//
//   ReliefInLightField out.png      the Cornell box's back wall as bricks, 256 x 256
//
// The cores' headers are private to the Mesolight tree, so this example builds in the tree only
// (examples/cxx/CMakeLists.txt); an installed Mesolight offers the same through the tool.
#include "EmbreeScene.h"
#include "FieldIrradiance.h"
#include "LightField.h"
#include "PatchComparison.h" // ToUnit
#include "Propagation.h"
#include "ReliefShading.h"
#include "TriangleScene.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace vlf = mesolight::vlf;

int main(int argc, char* argv[])
{
  const char* out = argc > 1 ? argv[1] : "relief-in-light-field.png";

  // 1. The field of the Cornell box, propagated with the wall's flat (macro) geometry.
  vlf::LightFieldSettings settings;
  settings.Directions = 513;
  settings.RaysPerSide = 32;
  std::unique_ptr<vlf::LightField> field =
    vlf::LightField::Build(mesolight::MakeCornellBox(), settings);
  vlf::Propagate(*field, 4);
  const mesolight::TriangleScene& scene = field->Scene(); // unit-sphere coordinates

  // 2. The back wall by name, its texture frame from its plane (u along x, v up), bricks 2 %
  //    of the wall's width deep: depth 0 on the bricks, 1 in the mortar.
  const std::vector<std::size_t> wall = mesolight::SurfaceTriangles(scene, "back");
  mesolight::ReliefFrame frame;
  frame.Origin = vlf::ToUnit(*field, { 556.0f, 0.0f, 559.2f });
  frame.AxisU = glm::dvec3(vlf::ToUnit(*field, { 0.0f, 0.0f, 559.2f })) - frame.Origin;
  frame.AxisV = glm::dvec3(vlf::ToUnit(*field, { 556.0f, 548.8f, 559.2f })) - frame.Origin;
  frame.Normal = glm::normalize(glm::dvec3(scene.FaceNormal(wall[0])));
  frame.DepthScale = 0.02;
  const int n = 256;
  std::vector<float> depth(static_cast<std::size_t>(n) * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int row = j / 16, shifted = (i + (row % 2) * 16) % 32;
      const bool mortar = j % 16 < 2 || shifted < 2;
      depth[static_cast<std::size_t>(j) * n + i] = mortar ? 1.0f : 0.0f;
    }
  }
  const mesolight::HeightField bricks(n, n, depth);

  // 3. The lighting, as data the relief takes without knowing the field: SH9 probes of the
  //    incident radiance without the emitters' own (the indirect light), and samples of the
  //    emitters for the direct light, which the relief shadows itself.
  mesolight::ReliefLighting lighting;
  lighting.ProbesU = lighting.ProbesV = 8;
  vlf::IncidentOptions indirect;
  indirect.Ignore = field->SurfaceOfTriangle(wall[0]);
  indirect.Emission = false;
  for (int b = 0; b < 8; ++b)
  {
    for (int a = 0; a < 8; ++a)
    {
      const glm::vec3 p(frame.Point((a + 0.5) / 8, (b + 0.5) / 8, 0.0) + 1e-3 * frame.Normal);
      lighting.Probes.push_back(
        vlf::ProjectIncidentSH9(vlf::IncidentRadianceSamples(*field, p, indirect)));
    }
  }
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const glm::vec3 ke = scene.MaterialOf(t).Emission;
    if (ke.x + ke.y + ke.z > 0.0f) // one sample per emitter triangle, at its centroid
    {
      mesolight::ReliefEmitterSample e;
      e.Position = glm::dvec3(scene.Vertex(t, 0) + scene.Vertex(t, 1) + scene.Vertex(t, 2)) / 3.0;
      e.Normal = glm::normalize(glm::dvec3(scene.FaceNormal(t)));
      e.RadianceArea = glm::dvec3(ke) * static_cast<double>(scene.Area(t));
      lighting.Emitters.push_back(e);
    }
  }
  const mesolight::EmbreeScene embree(scene);
  lighting.SceneVisible = [&embree](const glm::dvec3& from, const glm::dvec3& to)
  {
    mesolight::SceneRay ray;
    ray.Origin = glm::vec3(from);
    ray.Direction = glm::vec3(glm::normalize(to - from));
    ray.TNear = 1e-4f;
    ray.TFar = static_cast<float>(glm::length(to - from) * 0.9999);
    return !embree.Occluded(ray);
  };
  // The light the relief reflects onto itself: its own diffuse albedo.
  lighting.Albedo = glm::dvec3(scene.MaterialOf(wall[0]).Diffuse);

  // 4. Look straight at the wall from the room and shade every pixel: Kd / pi times the
  //    irradiance (SH9 at the perturbed normal plus the self-shadowed emitters).
  const glm::vec3 albedo = scene.MaterialOf(wall[0]).Diffuse;
  const glm::dvec3 eye = frame.Point(0.5, 0.5, 0.0) + 1.2 * frame.Normal;
  vtkNew<vtkUnsignedCharArray> rgb;
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(n * n);
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      const glm::dvec3 target = frame.Point((x + 0.5) / n, (y + 0.5) / n, 0.0);
      const auto shade =
        mesolight::ShadeReliefRay(bricks, frame, lighting, eye, glm::normalize(target - eye));
      glm::dvec3 radiance(0.0);
      if (shade)
      {
        radiance = glm::dvec3(albedo) * (shade->Indirect + shade->Direct) / 3.14159265358979;
      }
      for (int c = 0; c < 3; ++c)
      {
        const double srgb = std::pow(std::clamp(2.0 * radiance[c], 0.0, 1.0), 1.0 / 2.2);
        rgb->SetComponent(static_cast<vtkIdType>(y) * n + x, c, std::round(255.0 * srgb));
      }
    }
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, 1);
  image->GetPointData()->SetScalars(rgb);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(out);
  writer->Write();
  std::cout << "wrote " << out << "\n";
  return writer->GetErrorCode() == 0 ? 0 : 1;
}
