// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTriangleSceneConverter
 * @brief   vtkPolyData <-> mesolight::TriangleMesh and TriangleScene: the one converter each way
 *
 * Every Mesolight class that turns polydata into a mesh of its cores, or a mesh back into
 * polydata, goes through here: MeshToPolyData / ToTriangleMesh for the geometry alone (points,
 * triangles, point normals, texture coordinates), ToPolyData / ToTriangleScene for a scene with
 * its materials.
 *
 * The light field's scenes (mesolight::TriangleScene, vtkScene/core/TriangleScene.h) as
 * vtkPolyData: triangles, and per cell the material arrays
 *  - "Diffuse" (3 floats, Kd), "Specular" (3, Ks, perfect specular), "Emission" (3, Ke,
 *    emitted radiance), "MaterialId" (int, index into the scene's materials),
 *  - "MaterialColours" (9 floats: Kd, Ks, Ke): the same colours in one array, which a Transform
 *    filter leaves alone (ParaView's transforms every 3-component array as a vector by default,
 *    scaling and rotating Kd and Ke); ToTriangleScene takes a cell's colours from it where it is
 *    and warns about cells whose 3-component arrays differ,
 *  - field data "MaterialNames" (strings, indexed by MaterialId),
 *  - point normals and texture coordinates when the scene has them,
 *  - when the scene names its surfaces (OBJ g/o, the Cornell box's floor, back, ...): cell
 *    array "SurfaceId" (int, index into field data "SurfaceNames"; -1 unnamed), so that a light
 *    field propagated from the polydata knows them (a relief on "floor").
 *
 * ToTriangleScene accepts any vtkPolyData: polygons and strips are triangulated (a warning says
 * how many), vertices and lines are dropped (a warning), missing material arrays get the default
 * grey material (Kd 0.5, no specular, no emission) with a warning, a 1-component array is taken as
 * grey. Cells with equal MaterialId share one material (without MaterialId, cells with equal
 * Diffuse/Specular/Emission do), unless their colours differ: scenes appended, whose ids collide,
 * keep each colour as a material of its own (a warning). Errors (no triangles, non-finite points,
 * arrays of the wrong size, negative colours) go through vtkErrorMacro and return false; warnings
 * through vtkWarningMacro (observe vtkCommand::ErrorEvent / WarningEvent to catch them).
 *
 * For code built in this tree (the ray tracer, the light field, the tool, the tests): the header
 * is not installed, since its signatures name the core types, whose headers are not either.
 */
#ifndef vtkTriangleSceneConverter_h
#define vtkTriangleSceneConverter_h

#include "MesolightSceneModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For ToPolyData

class vtkPolyData;
namespace mesolight
{
struct TriangleMesh;
struct TriangleScene;
}

class MESOLIGHTSCENE_EXPORT vtkTriangleSceneConverter : public vtkObject
{
public:
  static vtkTriangleSceneConverter* New();
  vtkTypeMacro(vtkTriangleSceneConverter, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The mesh's geometry as vtkPolyData, into `output` (replacing its contents): float points,
   * the triangles, and point data "Normals" and "TextureCoordinates" when the mesh has one per
   * point.
   */
  static void MeshToPolyData(const mesolight::TriangleMesh& mesh, vtkPolyData* output);
  static vtkSmartPointer<vtkPolyData> MeshToPolyData(const mesolight::TriangleMesh& mesh);

  /**
   * The geometry of `input` as a triangle mesh, as it is (no checks: the caller validates):
   * polygons and strips triangulated (on a copy; `input` is not touched), vertex and line cells
   * dropped; point normals (3 components) and texture coordinates (the first two components)
   * copied when there is one per point. Empty for a null or empty input.
   */
  static void ToTriangleMesh(vtkPolyData* input, mesolight::TriangleMesh& mesh);

  /**
   * The scene as vtkPolyData with the material arrays above, into `output` (replacing its
   * contents).
   */
  void ToPolyData(const mesolight::TriangleScene& scene, vtkPolyData* output);
  vtkSmartPointer<vtkPolyData> ToPolyData(const mesolight::TriangleScene& scene);

  /**
   * `input` as a triangle scene. Returns false (and reports with vtkErrorMacro) when it cannot
   * be used; `scene` is then left empty.
   */
  bool ToTriangleScene(vtkPolyData* input, mesolight::TriangleScene& scene);

  ///@{
  /**
   * Number of warnings the last ToTriangleScene call reported.
   */
  vtkGetMacro(LastWarningCount, int);
  ///@}

protected:
  vtkTriangleSceneConverter() = default;
  ~vtkTriangleSceneConverter() override = default;

private:
  vtkTriangleSceneConverter(const vtkTriangleSceneConverter&) = delete;
  void operator=(const vtkTriangleSceneConverter&) = delete;

  int LastWarningCount = 0;
};

#endif
