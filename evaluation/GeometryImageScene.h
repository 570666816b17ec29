// SPDX-License-Identifier: BSD-3-Clause
// A relief on the coarse mesh of a geometry image (Méndez Fernández, "Visualizing 3D models with
// fine-grain surface depth", §6), and its independent reference.
//
// One description builds three renderings of the same surface and depth map, each the standard
// relief scene (ReliefScene.h: material, albedo, camera, lights) with its wall replaced:
//  - the relief: vtkGeometryImageToMesh's coarse mesh drawn by vtkReliefMapper;
//  - the dense reference: the full-resolution geometry image displaced along its normals by the
//    depth map (DisplaceGeometryImage), one vertex per pixel, drawn by VTK's stock mapper;
//  - the coarse mesh plainly texture-mapped (stock mapper, no relief): the negative baseline.
// The `mesolight render --geometry-image` command draws the first.
#ifndef mesolight_GeometryImageScene_h
#define mesolight_GeometryImageScene_h

#include "MesolightEvaluationModule.h" // for the export macro
#include "ReliefScene.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace mesolight
{

struct GeometryImageSceneOptions
{
  ReliefSceneOptions Relief; // depth map (pattern or file), depth scale, method, view, lights
  // "procedural:cylinder" (or plane, sphere, wave, bump; Relief.Resolution pixels square, the
  // depth map's size: texel for texel) or a geometry image file (RGB = XYZ, float EXR/TIFF).
  std::string GeometryImage = "procedural:cylinder";
  int Stride = 20;        // regular sampling every Stride pixels
  double Tolerance = 0.0; // > 0: adaptive sampling to this world distance instead
  std::string ColorFile;  // an albedo image in the geometry image's parameterization
};

/**
 * The scene where a curved relief's outline matters (relief mapping on curved meshes, Oliveira &
 * Policarpo 2005): the procedural surface (cylinder, sphere, plane) at stride 8 of 256^2, the
 * HemisphereTorus depth map (its base 0.9 deep) at depth scale 0.06, seen from 55 degrees about
 * the cylinder's axis (ViewAzimuth 90), so the surface turns away from the viewer well inside
 * the texture, at the top of a 300x300 frame. Relief 32+8, self-shadowing off (the dense mesh has
 * none). Used by the CurvedReliefSilhouette tests and `mesolight bench curved-relief`.
 */
MESOLIGHTEVALUATION_EXPORT GeometryImageSceneOptions CurvedOutlineScene(const std::string& surface);

/** The geometry image a spec names ("procedural:NAME" or a file), or null with an error. */
MESOLIGHTEVALUATION_EXPORT vtkSmartPointer<vtkImageData> LoadGeometryImage(
  const std::string& spec, int resolution, std::string& error);

/** The coarse mesh of the options (vtkGeometryImageToMesh), or null with an error. */
MESOLIGHTEVALUATION_EXPORT vtkSmartPointer<vtkPolyData> MakeGeometryImageMesh(
  const GeometryImageSceneOptions& options, vtkImageData* geometry, std::string& error);

/** The relief on the coarse mesh; mesh (optional) receives the coarse mesh. */
MESOLIGHTEVALUATION_EXPORT bool BuildGeometryImageReliefScene(
  const GeometryImageSceneOptions& options, ReliefScene& scene, std::string& error,
  vtkSmartPointer<vtkPolyData>* mesh = nullptr);

/** The dense displaced reference (the depth map must have the geometry image's size). */
MESOLIGHTEVALUATION_EXPORT bool BuildGeometryImageDenseScene(
  const GeometryImageSceneOptions& options, ReliefScene& scene, std::string& error);

/** The coarse mesh plainly texture-mapped (no relief). */
MESOLIGHTEVALUATION_EXPORT bool BuildGeometryImageTexturedScene(
  const GeometryImageSceneOptions& options, ReliefScene& scene, std::string& error);

} // namespace mesolight

#endif
