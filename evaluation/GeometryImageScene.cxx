// SPDX-License-Identifier: BSD-3-Clause
#include "GeometryImageScene.h"

#include "GeometryImageMesh.h"
#include "ProceduralGeometryImages.h"
#include "vtkGeometryImageSource.h"
#include "vtkGeometryImageToMesh.h"
#include "vtkGeometryImageToMeshCore.h"
#include "vtkMessageCollector.h"
#include "vtkOIIOImageReader.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <cmath>
#include <string>

namespace mesolight
{
namespace
{
const std::string Procedural = "procedural:";

bool IsProcedural(const std::string& spec)
{
  return spec.compare(0, Procedural.size(), Procedural) == 0;
}

// Replaces the standard scene's wall by mesh; a geometry image file gets a camera on its bounds
// (the procedural surfaces are framed like the wall, so the standard camera fits them).
void UseMesh(const GeometryImageSceneOptions& options, ReliefScene& scene, vtkPolyData* mesh)
{
  scene.Actor->GetMapper()->SetInputDataObject(mesh);
  if (!IsProcedural(options.GeometryImage))
  {
    scene.Renderer->ResetCamera(mesh->GetBounds());
  }
}

bool ApplyColour(const GeometryImageSceneOptions& options, ReliefScene& scene, std::string& error)
{
  if (options.ColorFile.empty())
  {
    return true;
  }
  vtkNew<MessageCollector> errors;
  vtkNew<vtkOIIOImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(options.ColorFile.c_str());
  reader->Update();
  if (!errors->Errors.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    error = "cannot read the colour image '" + options.ColorFile + "'" +
      (errors->Errors.empty() ? "" : ": " + errors->ErrorText());
    return false;
  }
  // A NaN or infinite texel would reach the screen as black or not at all (the texture upload
  // converts it), so it is refused by position (the reader puts the top row last).
  vtkDataArray* texels = reader->GetOutput()->GetPointData()->GetScalars();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  for (vtkIdType t = 0; texels && t < texels->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < texels->GetNumberOfComponents(); ++c)
    {
      if (!std::isfinite(texels->GetComponent(t, c)))
      {
        error = "the colour image '" + options.ColorFile + "' has a NaN or infinite value at " +
          "texel (" + std::to_string(t % dims[0]) + ", " +
          std::to_string(dims[1] - 1 - t / dims[0]) + ") (column, row from the top), channel " +
          std::to_string(c) + "; it would render black";
        return false;
      }
    }
  }
  vtkNew<vtkImageData> colour;
  colour->DeepCopy(reader->GetOutput());
  scene.Albedo->SetInputData(colour);
  // Float images (EXR albedo from depth hallucination) are colours in [0, 1], not scalars to
  // map through a lookup table, which is what vtkTexture does with them by default.
  scene.Albedo->SetColorModeToDirectScalars();
  return true;
}

bool PrepareGeometry(const GeometryImageSceneOptions& options, const ReliefScene& scene,
  vtkSmartPointer<vtkImageData>& geometry, std::string& error)
{
  int dims[3] = { options.Relief.Resolution, options.Relief.Resolution, 1 };
  if (scene.ReliefTexture)
  {
    scene.ReliefTexture->GetDimensions(dims); // procedural surfaces: texel for texel
  }
  geometry = LoadGeometryImage(options.GeometryImage, dims[0], error);
  return geometry != nullptr;
}
} // namespace

//------------------------------------------------------------------------------
GeometryImageSceneOptions CurvedOutlineScene(const std::string& surface)
{
  GeometryImageSceneOptions o;
  o.GeometryImage = Procedural + surface;
  o.Relief.Pattern = "HemisphereTorus";
  o.Relief.Resolution = 256;
  o.Relief.Width = 300;
  o.Relief.Height = 300;
  o.Relief.DepthScale = 0.06;
  o.Relief.SelfShadowing = false;
  o.Relief.ViewAngle = 55.0;
  o.Relief.ViewAzimuth = 90.0;
  o.Relief.ViewDistance = 2.4;
  o.Relief.LinearSteps = 32;
  o.Relief.RefinementSteps = 8;
  o.Stride = 8;
  return o;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> LoadGeometryImage(
  const std::string& spec, int resolution, std::string& error)
{
  vtkNew<MessageCollector> errors;
  vtkSmartPointer<vtkImageData> image;
  if (IsProcedural(spec))
  {
    vtkNew<vtkGeometryImageSource> source;
    source->AddObserver(vtkCommand::ErrorEvent, errors);
    if (!source->SetSurfaceByName(spec.substr(Procedural.size()).c_str()))
    {
      error = "unknown procedural geometry image '" + spec +
        "' (procedural:" + GeometrySurfaceNames() + ")";
      return nullptr;
    }
    source->SetResolution(resolution, resolution);
    source->Update();
    image = source->GetOutput();
  }
  else
  {
    vtkNew<vtkOIIOImageReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->SetFileName(spec.c_str());
    reader->Update();
    image = reader->GetOutput();
  }
  if (!errors->Errors.empty() || !image || image->GetNumberOfPoints() == 0)
  {
    error = "cannot read the geometry image '" + spec + "'" +
      (errors->Errors.empty() ? "" : ": " + errors->ErrorText());
    return nullptr;
  }
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(image);
  return copy;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> MakeGeometryImageMesh(
  const GeometryImageSceneOptions& options, vtkImageData* geometry, std::string& error)
{
  vtkNew<MessageCollector> errors;
  vtkNew<vtkGeometryImageToMesh> mesher;
  mesher->AddObserver(vtkCommand::ErrorEvent, errors);
  mesher->SetInputData(geometry);
  mesher->SetStride(options.Stride);
  mesher->SetTolerance(options.Tolerance);
  mesher->Update();
  if (!errors->Errors.empty() || mesher->GetOutput()->GetNumberOfPolys() == 0)
  {
    error = errors->Errors.empty() ? "the geometry image gave no triangles" : errors->ErrorText();
    return nullptr;
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(mesher->GetOutput());
  return mesh;
}

//------------------------------------------------------------------------------
bool BuildGeometryImageReliefScene(const GeometryImageSceneOptions& options, ReliefScene& scene,
  std::string& error, vtkSmartPointer<vtkPolyData>* meshOut)
{
  vtkSmartPointer<vtkImageData> geometry;
  if (!BuildReliefScene(options.Relief, scene, error) ||
    !PrepareGeometry(options, scene, geometry, error) || !ApplyColour(options, scene, error))
  {
    return false;
  }
  vtkSmartPointer<vtkPolyData> mesh = MakeGeometryImageMesh(options, geometry, error);
  if (!mesh)
  {
    return false;
  }
  // The geometry image's borders are the texture's: silhouettes cut the relief there.
  UseMesh(options, scene, mesh);
  if (meshOut)
  {
    *meshOut = mesh;
  }
  return true;
}

//------------------------------------------------------------------------------
bool BuildGeometryImageDenseScene(
  const GeometryImageSceneOptions& options, ReliefScene& scene, std::string& error)
{
  vtkSmartPointer<vtkImageData> geometry;
  if (!BuildDenseReferenceScene(options.Relief, scene, error) ||
    !PrepareGeometry(options, scene, geometry, error) || !ApplyColour(options, scene, error))
  {
    return false;
  }
  GeometryImage surface;
  if (!vtkGeometryImageToMeshCore::ToGeometryImage(geometry, nullptr, surface, error))
  {
    return false;
  }
  // Depth per pixel: the relief texture's A channel, texel for texel.
  int dims[3];
  scene.ReliefTexture->GetDimensions(dims);
  vtkDataArray* relief = scene.ReliefTexture->GetPointData()->GetScalars();
  if (dims[0] != surface.Width || dims[1] != surface.Height || !relief ||
    relief->GetNumberOfComponents() != 4)
  {
    error = "the dense reference needs a depth map of the geometry image's size (" +
      std::to_string(surface.Width) + " x " + std::to_string(surface.Height) + "), got " +
      std::to_string(dims[0]) + " x " + std::to_string(dims[1]);
    return false;
  }
  std::vector<float> depth(surface.Positions.size());
  for (size_t k = 0; k < depth.size(); ++k)
  {
    depth[k] = static_cast<float>(relief->GetComponent(static_cast<vtkIdType>(k), 3));
  }
  GeometryImage displaced;
  try
  {
    displaced = DisplaceGeometryImage(surface, depth, options.Relief.DepthScale);
  }
  catch (const GeometryImageMeshError& e)
  {
    error = e.what();
    return false;
  }
  vtkNew<vtkImageData> image;
  image->SetDimensions(displaced.Width, displaced.Height, 1);
  vtkNew<vtkFloatArray> positions;
  positions->SetNumberOfComponents(3);
  positions->SetNumberOfTuples(static_cast<vtkIdType>(displaced.Positions.size()));
  for (size_t k = 0; k < displaced.Positions.size(); ++k)
  {
    const glm::dvec3& p = displaced.Positions[k];
    positions->SetTuple3(static_cast<vtkIdType>(k), p.x, p.y, p.z);
  }
  image->GetPointData()->SetScalars(positions);
  // One vertex per pixel, shaded with its triangles' own normals (VTK derives them per fragment
  // when the mesh has none), as the relief mapper shades the surface it marches.
  GeometryImageSceneOptions dense = options;
  dense.Stride = 1;
  dense.Tolerance = 0.0;
  vtkSmartPointer<vtkPolyData> mesh = MakeGeometryImageMesh(dense, image, error);
  if (!mesh)
  {
    return false;
  }
  mesh->GetPointData()->SetNormals(nullptr);
  UseMesh(options, scene, mesh);
  return true;
}

//------------------------------------------------------------------------------
bool BuildGeometryImageTexturedScene(
  const GeometryImageSceneOptions& options, ReliefScene& scene, std::string& error)
{
  vtkSmartPointer<vtkImageData> geometry;
  if (!BuildTexturedPlaneScene(options.Relief, scene, error) ||
    !PrepareGeometry(options, scene, geometry, error) || !ApplyColour(options, scene, error))
  {
    return false;
  }
  vtkSmartPointer<vtkPolyData> mesh = MakeGeometryImageMesh(options, geometry, error);
  if (!mesh)
  {
    return false;
  }
  UseMesh(options, scene, mesh);
  return true;
}

} // namespace mesolight
