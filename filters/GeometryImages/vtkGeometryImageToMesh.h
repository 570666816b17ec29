// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkGeometryImageToMesh
 * @brief   the coarse macro mesh of a geometry image, for relief mapping
 *
 * A geometry image (Gu, Gortler and Hoppe, "Geometry images") is an image whose pixels are 3D
 * positions (e.g. a float EXR or TIFF with RGB = XYZ). This filter samples it into the coarse
 * mesh a relief is drawn on (Méndez Fernández, "Visualizing 3D models with fine-grain surface
 * depth", §6): regularly every Stride-th pixel (two triangles per square, split along the
 * shorter diagonal; the last row and column always included), or adaptively when Tolerance > 0
 * (a quadtree of cells split while the full-resolution surface lies farther than Tolerance, in
 * world units, from the cell's triangles; crack-free).
 *
 * Input 0: vtkImageData, 2D, point scalars with 3 components (the positions). Pixels with a NaN
 * coordinate are empty; no triangle touches them. Input 1 (optional): a normal image of the same
 * size; without it, a 3-component point array "Normals" of input 0 is used, else normals come
 * from the geometry.
 *
 * Output: triangles with point data "Normals" and "TCoords". Pixel (i, j) gets the texture
 * coordinate ((i + 0.5) / W, (j + 0.5) / H), the centre of texel (i, j) of any W x H colour,
 * depth or relief image in the same parameterization: they map texel for texel, as
 * vtkHeightFieldMeshFilter's dense mesh does. Connect the output to vtkReliefMapper.
 */
#ifndef vtkGeometryImageToMesh_h
#define vtkGeometryImageToMesh_h

#include "MesolightGeometryImagesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkImageData;

class MESOLIGHTGEOMETRYIMAGES_EXPORT vtkGeometryImageToMesh : public vtkPolyDataAlgorithm
{
public:
  static vtkGeometryImageToMesh* New();
  vtkTypeMacro(vtkGeometryImageToMesh, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Sample every Stride-th pixel (regular sampling). Default 20 (the thesis' triangle size). */
  vtkSetMacro(Stride, int);
  vtkGetMacro(Stride, int);
  ///@}

  ///@{
  /**
   * Adaptive sampling when > 0: the largest distance (world units) allowed between the
   * full-resolution surface and the mesh. 0 (default) samples regularly with Stride.
   */
  vtkSetClampMacro(Tolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /** Largest adaptive cell, in pixels (a power of two; 0, the default, fits the image). */
  vtkSetClampMacro(MaximumCellSize, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumCellSize, int);
  ///@}

  /** The optional normal image (input port 1). */
  void SetNormalImageConnection(vtkAlgorithmOutput* output);

protected:
  vtkGeometryImageToMesh();
  ~vtkGeometryImageToMesh() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Stride = 20;
  double Tolerance = 0.0;
  int MaximumCellSize = 0;

private:
  vtkGeometryImageToMesh(const vtkGeometryImageToMesh&) = delete;
  void operator=(const vtkGeometryImageToMesh&) = delete;
};

#endif
