// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldSceneCache.h"

#include "vtkLightFieldMapper.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"

#include "EmitterLights.h"
#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "TextureAtlas.h"
#include "TriangleScene.h"
#include "WalkthroughTracer.h"

#include <algorithm>
#include <cmath>
#include <exception>

namespace vlf = mesolight::vlf;

namespace
{
// The field's scene in world coordinates, three points per triangle (each carries its own
// surface's atlas coordinates), face normals, Kd colours for the geometry mode.
vtkSmartPointer<vtkPolyData> MakeScene(const vlf::LightField& field, const vlf::TextureAtlas& atlas,
  const std::vector<bool>& hidden = {})
{
  const mesolight::TriangleScene& scene = field.Scene();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName(vtkLightFieldMapper::GetAtlasCoordinatesName());
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("GeometryColour");
  colours->SetNumberOfComponents(3);
  // Shadows of the movable object: each receiver's unit-sphere point, normal and Kd
  // (vtkLightFieldShadowFS.glsl).
  vtkNew<vtkFloatArray> shadowPoints;
  shadowPoints->SetName("mlShadowPoint");
  shadowPoints->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> shadowNormals;
  shadowNormals->SetName("mlShadowNormal");
  shadowNormals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> shadowKd;
  shadowKd->SetName("mlShadowKd");
  shadowKd->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> polys;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const std::uint32_t s = field.SurfaceOfTriangle(t);
    if (s == vlf::NoSurface || (!hidden.empty() && hidden[t]))
    {
      continue;
    }
    const mesolight::SceneMaterial& m = field.MaterialOf(s);
    glm::vec3 colour = m.Diffuse;
    if (std::max(m.Emission.x, std::max(m.Emission.y, m.Emission.z)) > 0.0f)
    {
      colour = glm::vec3(1.0f);
    }
    else if (std::max(m.Specular.x, std::max(m.Specular.y, m.Specular.z)) > 0.0f)
    {
      colour = glm::vec3(0.55f, 0.65f, 0.8f); // mirrors: a light steel blue in geometry mode
    }
    const glm::vec3 n = field.Surfaces()[s].Normal;
    vtkIdType ids[3];
    for (int corner = 0; corner < 3; ++corner)
    {
      const glm::vec3 unit = scene.Vertex(t, corner);
      const glm::vec3 world = vlf::ToWorld(field, unit);
      ids[corner] = points->InsertNextPoint(world.x, world.y, world.z);
      const glm::vec2 tc = atlas.TextureCoordinates(s, unit);
      tcoords->InsertNextTuple2(tc.x, tc.y);
      normals->InsertNextTuple3(n.x, n.y, n.z);
      shadowPoints->InsertNextTuple3(unit.x, unit.y, unit.z);
      shadowNormals->InsertNextTuple3(n.x, n.y, n.z);
      shadowKd->InsertNextTuple3(m.Diffuse.x, m.Diffuse.y, m.Diffuse.z);
      colours->InsertNextTuple3(std::lround(255.0f * std::min(1.0f, colour.x)),
        std::lround(255.0f * std::min(1.0f, colour.y)),
        std::lround(255.0f * std::min(1.0f, colour.z)));
    }
    polys->InsertNextCell(3, ids);
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->SetNormals(normals);
  poly->GetPointData()->SetScalars(colours);
  poly->GetPointData()->AddArray(tcoords);
  poly->GetPointData()->AddArray(shadowPoints);
  poly->GetPointData()->AddArray(shadowNormals);
  poly->GetPointData()->AddArray(shadowKd);
  return poly;
}
} // namespace

//------------------------------------------------------------------------------
vtkLightFieldSceneCache::vtkLightFieldSceneCache() = default;

//------------------------------------------------------------------------------
vtkLightFieldSceneCache::~vtkLightFieldSceneCache() = default;

//------------------------------------------------------------------------------
bool vtkLightFieldSceneCache::Build(const mesolight::vlf::LightField* field, std::string& error)
{
  this->Field = nullptr;
  this->Tracer.reset();
  this->Atlas.reset();
  this->Scene = nullptr;
  this->Lights.reset();
  this->Hidden.clear();
  ++this->AtlasVersion;
  if (!field)
  {
    return true;
  }
  try
  {
    this->Tracer.reset(new vlf::WalkthroughTracer(*field));
    this->Atlas.reset(new vlf::TextureAtlas(*field));
    this->Scene = MakeScene(*field, *this->Atlas);
    this->Field = field;
  }
  catch (const std::exception& e)
  {
    this->Tracer.reset();
    this->Atlas.reset();
    this->Scene = nullptr;
    error = std::string("cannot show the light field: ") + e.what();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldSceneCache::SetHiddenSurfaces(
  const std::vector<std::string>& names, std::string& error)
{
  if (!this->Field || !this->Atlas || names == this->Hidden)
  {
    return true;
  }
  const mesolight::TriangleScene& scene = this->Field->Scene();
  std::vector<bool> hidden(scene.TriangleCount(), false);
  bool known = true;
  for (const std::string& name : names)
  {
    try
    {
      for (const std::size_t t : mesolight::SurfaceTriangles(scene, name))
      {
        hidden[t] = true;
      }
    }
    catch (const mesolight::SceneSurfaceError& e)
    {
      error = std::string("cannot hide a surface: ") + e.what();
      known = false;
    }
  }
  this->Scene = MakeScene(*this->Field, *this->Atlas, hidden);
  this->Hidden = names;
  return known;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLightFieldSceneCache::GetScene() const
{
  return this->Scene;
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightApproximation* vtkLightFieldSceneCache::GetEmitterLights()
{
  if (!this->Field)
  {
    return nullptr;
  }
  if (!this->Lights)
  {
    this->Lights.reset(new vlf::LightApproximation(vlf::EstimateEmitterLights(*this->Field)));
  }
  return this->Lights.get();
}
