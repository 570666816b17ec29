// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOBJSceneReader
 * @brief   reads a Wavefront OBJ + MTL scene into vtkPolyData with material cell arrays
 *
 * The light field's scene reader (Wither 2005 §2.4.2.1: an .obj with an .mtl of surface
 * properties). Reads with the core reader (vtkScene/core/ObjScene.h: n-gons fan-triangulated,
 * negative indices, mtllib/usemtl, Kd/Ks/Ke/Ka/Ns) and outputs triangles with the cell arrays
 * "Diffuse", "Specular" (perfect specular), "Emission" (3 floats each) and "MaterialId", field
 * data "MaterialNames", and point normals / texture coordinates when every face has them (see
 * vtkTriangleSceneConverter).
 *
 * A file that cannot be read (missing, corrupt, "scene.obj:12: face refers to vertex 40 of 31")
 * is a vtkErrorMacro and an empty output; a missing MTL or material (default grey), no emitter,
 * degenerate or non-manifold triangles are vtkWarningMacro messages. GetNonManifoldEdges(),
 * GetDegenerateTriangles() and GetWarnings() give the figures of the last read.
 */
#ifndef vtkOBJSceneReader_h
#define vtkOBJSceneReader_h

#include "MesolightSceneModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For the file name
#include <vector> // For the warnings

class MESOLIGHTSCENE_EXPORT vtkOBJSceneReader : public vtkPolyDataAlgorithm
{
public:
  static vtkOBJSceneReader* New();
  vtkTypeMacro(vtkOBJSceneReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The .obj file; mtllib files are looked up beside it.
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /**
   * A scene without an emitter (no material with Ke > 0) is an error rather than a warning.
   * Default off.
   */
  vtkSetMacro(RequireEmitter, bool);
  vtkGetMacro(RequireEmitter, bool);
  vtkBooleanMacro(RequireEmitter, bool);
  ///@}

  ///@{
  /**
   * Drop zero-area triangles (they are counted either way). Default on.
   */
  vtkSetMacro(RemoveDegenerateTriangles, bool);
  vtkGetMacro(RemoveDegenerateTriangles, bool);
  vtkBooleanMacro(RemoveDegenerateTriangles, bool);
  ///@}

  ///@{
  /**
   * What the last read found.
   */
  vtkGetMacro(NonManifoldEdges, vtkIdType);
  vtkGetMacro(DegenerateTriangles, vtkIdType);
  const std::vector<std::string>& GetWarnings() const { return this->Warnings; }
  ///@}

protected:
  vtkOBJSceneReader();
  ~vtkOBJSceneReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkOBJSceneReader(const vtkOBJSceneReader&) = delete;
  void operator=(const vtkOBJSceneReader&) = delete;

  std::string FileName;
  bool RequireEmitter = false;
  bool RemoveDegenerateTriangles = true;
  vtkIdType NonManifoldEdges = 0;
  vtkIdType DegenerateTriangles = 0;
  std::vector<std::string> Warnings;
};

#endif
