// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefGeometryCache
 * @brief   The geometry a relief shader draws, prepared once per input polydata: triangles,
 *          point normals, float point tangents and the relief texture coordinates.
 *
 * Prepare() returns a copy of the input (sharing its points) with what the relief shader reads:
 * triangles only, point normals (vtkPolyDataNormals when missing), float point tangents
 * (vtkPolyDataTangents when missing; VTK's OpenGL mappers upload tangents only as floats), a
 * usable frame at degenerate triangles, and the texture coordinates as a float array named
 * GetReliefTCoordsName() (vertex attribute mlTCoordMC; VTK uploads "tcoord" only when the actor
 * has a texture), and on a curved mesh the per-vertex quadrics of relief mapping on curved
 * surfaces as a float array named GetReliefQuadricsName() (vertex attribute mlQuadricMC; none on
 * a flat mesh). Prepared copies are kept per input until the input is modified or forgotten
 * (KeepOnly).
 */

#ifndef vtkReliefGeometryCache_h
#define vtkReliefGeometryCache_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for Prepared

#include <map>    // for Prepared
#include <vector> // for KeepOnly

class vtkPolyData;

class MESOLIGHTRELIEF_EXPORT vtkReliefGeometryCache : public vtkObject
{
public:
  static vtkReliefGeometryCache* New();
  vtkTypeMacro(vtkReliefGeometryCache, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The prepared copy of the input, made when the input is new or modified since; null (with an
   * error) if the input cannot carry a relief (no texture coordinates, no polygons, non-finite
   * texture coordinates).
   */
  vtkPolyData* Prepare(vtkPolyData* input);

  /** Forget the prepared copies of inputs other than these (composite inputs change). */
  void KeepOnly(const std::vector<vtkPolyData*>& inputs);

  /** Name of the float texture-coordinate array Prepare adds (vertex attribute mlTCoordMC). */
  static const char* GetReliefTCoordsName();

  /**
   * Name of the 2-component float array of per-vertex quadric coefficients (a, b) Prepare adds
   * to a curved mesh (vertex attribute mlQuadricMC; see SurfaceQuadrics.h in ReliefTextures).
   */
  static const char* GetReliefQuadricsName();

  /** Whether a prepared mesh is curved: it carries the quadrics array. */
  static bool IsCurved(vtkPolyData* prepared);

protected:
  vtkReliefGeometryCache();
  ~vtkReliefGeometryCache() override;

  struct PreparedGeometry
  {
    vtkMTimeType SourceTime = 0;
    vtkSmartPointer<vtkPolyData> Prepared;
  };
  std::map<vtkPolyData*, PreparedGeometry> Prepared;

private:
  vtkReliefGeometryCache(const vtkReliefGeometryCache&) = delete;
  void operator=(const vtkReliefGeometryCache&) = delete;
};

#endif
