// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldObjectOptions.h"

#include "CommandLine.h"
#include "OutputFile.h"

#include "vtkLightFieldActor.h"
#include "vtkTriangleSceneConverter.h"

#include "ObjScene.h"
#include "ObjectGatherer.h"
#include "ObjectMesh.h"

#include "LightField.h"
#include "PatchComparison.h"
#include "Snapshot.h" // FileExists
#include "TriangleScene.h"

#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>

#include <sys/stat.h>

namespace mesolight
{
namespace vlf = mesolight::vlf;

namespace
{
// An object farther than this many field sizes from the origin has vertices whose products
// (areas, normals) overflow single precision.
constexpr double MaximumObjectReach = 1e15;
// An object this many field sizes outside the field is refused: nothing lights it there.
constexpr double MaximumObjectGap = 10.0;

bool IsDirectory(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}
} // namespace

void AddObjectOptions(CommandLine& cl)
{
  cl.AddValue("--object", "OBJECT",
    "a movable object in the field: sphere, cube (side 1, scaled to a fifth of the field) or "
    "FILE.obj (its own units)");
  cl.AddValue("--object-transform", "T",
    "tx,ty,tz[,rx,ry,rz[,s]]: the object's position (world units), orientation (degrees, as "
    "vtkProp3D::SetOrientation) and scale; default: the field's centre");
  cl.AddValue(
    "--object-colour", "R,G,B", "the object's diffuse reflectance, each in [0, 1]", "0.7,0.7,0.7");
  cl.AddValue("--shading", "S", "the object's shading: flat, lights or gather", "gather");
  cl.AddValue("--shadows", "MODE",
    "the object's shadows on the scene: none, black, blend (fixed alpha 0.5), field (the "
    "direct light it blocks), pcf or soft",
    "field");
  cl.AddValue("--shadow-emitters", "N",
    "how many of the scene's emitters (the strongest; more lamps merged down to them) cast the "
    "object's shadows, 1-8 (vtkLightFieldActor::SetShadowEmitterCount)",
    "4");
  cl.AddValue(
    "--subdivision", "N", "midpoint subdivision levels of the gathered object (0-3)", "0");
  cl.AddValue("--gather-directions", "SET",
    "directions the gather reads: all, half or importance (half, by the field's radiance)", "all");
  cl.AddValue("--gather-volume", "N",
    "0: gather at every vertex; N (2-128): read a precomputed irradiance volume of N points along "
    "the scene's longest side (built once, seconds; then about a microsecond per vertex)",
    "0");
  AddObjectReliefOptions(cl);
  // Every object option: without an object they would be silently ignored.
  for (const char* option :
    { "--object-transform", "--object-colour", "--shading", "--shadows", "--shadow-emitters",
      "--subdivision", "--gather-directions", "--gather-volume", "--object-relief" })
  {
    cl.AppliesOnlyWith(option, { "--object" });
  }
}

void ApplyPlacement(vtkActor* object, const ObjectPlacement& p)
{
  object->SetPosition(p.Position[0], p.Position[1], p.Position[2]);
  object->SetOrientation(p.Orientation[0], p.Orientation[1], p.Orientation[2]);
  object->SetScale(p.Scale);
}

vtkSmartPointer<vtkPolyData> ObjectPolyData(const vlf::ObjectMesh& mesh)
{
  return vtkTriangleSceneConverter::MeshToPolyData(mesh);
}

int SetUpObject(const CommandLine& cl, const char* command, vtkLightFieldActor* scene,
  vtkRenderer* renderer, MovableObject& object, std::vector<std::string>* inputs)
{
  if (!cl.Has("--object"))
  {
    return 0; // (the object options need --object: AddObjectOptions)
  }
  std::string error;
  int subdivision = 0;
  if (!cl.GetInt("--subdivision", 0, 3, subdivision, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  const int shading = vtkLightFieldObjectMapper::GetShadingFromString(cl.Get("--shading"));
  if (shading < 0)
  {
    std::cerr << command << ": --shading '" << cl.Get("--shading")
              << "' is not flat, lights or gather\n";
    return 2;
  }
  int gatherVolume = 0;
  if (!cl.GetInt("--gather-volume", 0, 128, gatherVolume, error) || gatherVolume == 1)
  {
    std::cerr << command << ": "
              << (error.empty() ? "--gather-volume 1 is not a grid: use 0 or 2-128" : error)
              << "\n";
    return 2;
  }
  const std::string directionSet = cl.Get("--gather-directions");
  const int gatherDirections = vtkLightFieldActor::GetGatherDirectionsFromString(directionSet);
  if (gatherDirections < 0)
  {
    std::cerr << command << ": --gather-directions '" << directionSet
              << "' is not all, half or importance\n";
    return 2;
  }
  const int shadows = vtkLightFieldActor::GetShadowModeFromString(cl.Get("--shadows"));
  if (shadows < 0)
  {
    std::cerr << command << ": --shadows '" << cl.Get("--shadows")
              << "' is not none, black, blend, field, pcf or soft\n";
    return 2;
  }
  int shadowEmitters = 4;
  if (!cl.GetInt("--shadow-emitters", 1, 8, shadowEmitters, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  double colour[3] = { 0.7, 0.7, 0.7 };
  {
    std::vector<double> values;
    if (!cl.GetDoubleList("--object-colour", 0.0, 1.0, values, error) || values.size() != 3)
    {
      std::cerr << command << ": --object-colour: "
                << (error.empty() ? "give three values R,G,B in [0, 1]" : error) << "\n";
      return 2;
    }
    std::copy(values.begin(), values.end(), colour);
  }
  double bounds[6];
  scene->GetBounds(bounds);
  const double extent =
    std::max(bounds[1] - bounds[0], std::max(bounds[3] - bounds[2], bounds[5] - bounds[4]));
  const std::string name = cl.Get("--object");
  vlf::ObjectMesh mesh;
  ObjectPlacement placement;
  for (int a = 0; a < 3; ++a)
  {
    placement.Position[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
  }
  if (name == "sphere" || name == "cube")
  {
    mesh = name == "sphere" ? vlf::MakeSphere(0.5f, 16, 32) : vlf::MakeCube(1.0f);
    placement.Scale = 0.2 * extent;
  }
  else
  {
    if (IsDirectory(name))
    {
      std::cerr << command << ": --object '" << name << "' is a directory, not an .obj file\n";
      return 2;
    }
    if (!vlf::FileExists(name))
    {
      std::cerr << command << ": --object '" << name
                << "' is not sphere, cube or an existing .obj file\n";
      return 2;
    }
    try
    {
      const mesolight::ObjSceneRead read = mesolight::ReadObjScene(name);
      mesh.Positions = read.Scene.Positions;
      mesh.Triangles.assign(read.Scene.Triangles.begin(), read.Scene.Triangles.end());
      if (read.Scene.TextureCoordinates.size() == mesh.Positions.size())
      {
        mesh.TextureCoordinates = read.Scene.TextureCoordinates; // a relief is laid out by them
      }
    }
    catch (const std::exception& e)
    {
      std::cerr << command << ": --object: " << e.what() << "\n";
      return 1;
    }
    if (inputs)
    {
      inputs->push_back(name);
    }
  }
  // Bad meshes are refused here with one line (the actor would refuse them too).
  const std::string problem = mesh.Validate();
  if (!problem.empty())
  {
    std::cerr << command << ": --object '" << name << "': " << problem << "\n";
    return 1;
  }
  if (const int status = CheckObjectRelief(cl, command, name, !mesh.TextureCoordinates.empty()))
  {
    return status;
  }
  if (cl.Has("--object-transform"))
  {
    error = ParsePlacement(cl.Get("--object-transform"), placement);
    if (!error.empty())
    {
      std::cerr << command << ": --object-transform: " << error << "\n";
      return 2;
    }
  }
  {
    // The object's farthest vertex, in field extents: beyond single precision's range its areas
    // and normals overflow (reported as zero area, rendered black), so refuse the transform.
    double radius = 0.0;
    for (const glm::vec3& p : mesh.Positions)
    {
      radius = std::max(radius, static_cast<double>(glm::length(p)));
    }
    const double reach = std::sqrt(placement.Position[0] * placement.Position[0] +
                           placement.Position[1] * placement.Position[1] +
                           placement.Position[2] * placement.Position[2]) +
      placement.Scale * radius;
    const double limit = MaximumObjectReach * std::max(extent, 1e-30);
    if (!(reach <= limit))
    {
      std::cerr << command << ": --object-transform is out of range: the object would reach "
                << reach << " world units from the origin, more than " << limit << " ("
                << MaximumObjectReach << " times the field's size " << extent
                << ", beyond single precision)\n";
      return 2;
    }
    // Far outside the field (1e6 beside a 555 box) the field has no light for the object, and
    // the view's clipping range, which holds both, clipped the whole field away: a black image.
    double gap = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double outside =
        std::max(bounds[2 * a] - placement.Position[a], placement.Position[a] - bounds[2 * a + 1]);
      gap += outside > 0.0 ? outside * outside : 0.0;
    }
    gap = std::sqrt(gap) - placement.Scale * radius;
    if (gap > MaximumObjectGap * extent)
    {
      std::cerr << command << ": --object-transform puts the object " << gap
                << " world units outside the light field, more than " << MaximumObjectGap
                << " times its size " << extent << " (no light there to shade it with)\n";
      return 2;
    }
  }
  object.Mapper->SetInputData(ObjectPolyData(mesh));
  object.Mapper->SetLightFieldActor(scene);
  object.Mapper->SetShading(shading);
  object.Mapper->SetGatherDirections(gatherDirections);
  scene->SetShadowMode(shadows);
  scene->SetShadowEmitterCount(shadowEmitters);
  object.Mapper->SetSubdivision(subdivision);
  object.Actor->SetMapper(object.Mapper);
  object.Actor->GetProperty()->SetDiffuseColor(colour);
  object.Actor->GetProperty()->SetDiffuse(1.0);
  object.Placement = placement;
  object.Step = extent > 0.0 ? extent / 20.0 : 1.0;
  ApplyPlacement(object.Actor, placement);
  scene->SetMovableObject(object.Actor);
  scene->SetObjectSubdivision(subdivision);
  scene->SetObjectGatherDirections(gatherDirections);
  scene->SetObjectIrradianceVolume(gatherVolume);
  renderer->AddActor(object.Actor);
  renderer->ResetCameraClippingRange();
  object.Active = true;
  return 0;
}

} // namespace mesolight
