// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkHeightFieldMeshFilter
 * @brief   dense displaced reference mesh of a relief texture (one vertex per texel)
 *
 * vtkHeightFieldMeshFilter builds the independent, brute-force geometry that relief
 * mapping approximates, for image comparisons: one vertex per texel of a W x H relief
 * texture (float RGBA, as produced by vtkReliefTextureFilter), placed at the texel centre
 * u = (i + 0.5) / W, v = (j + 0.5) / H, and displaced along -N:
 *
 *   P = Origin + u (Point1 - Origin) + v (Point2 - Origin) - N depth DepthScale |Point1 - Origin|
 *
 * with N = normalize((Point1 - Origin) x (Point2 - Origin)). Each grid quad gives two
 * triangles. Point data: "Normals" (the texture's tangent-space normal n = 2 rgb - 1,
 * rotated into the frame T = normalize(Point1 - Origin), B = normalize(Point2 - Origin), N),
 * "TCoords" (u, v) and a plain "Depth" array (not the active scalars, so that mappers do
 * not colour by it by default).
 *
 * By default (SquareTexels on) the length of Point2 - Origin is set to
 * |Point1 - Origin| * H / W, keeping its direction, so texels are square as the DepthScale
 * convention assumes; the default plane is then the unit-wide rectangle (0,0,0), (1,0,0),
 * (0, H/W, 0) in z = 0. With SquareTexels off Point2 is used as given: texels stretched
 * along v (a georeferenced map on its ground proportions) get normals with their slopes along v
 * scaled to match.
 *
 * The depth scale: when UseInputDepthScale is on (default) and the input field data holds
 * "MesolightDepthScale", that value is used; otherwise DepthScale. When the scale used
 * differs from the one the normals were baked with ("MesolightDepthScale"), the normals'
 * tangential components are rescaled by the ratio before normalising, as the GPU mapper does.
 */
#ifndef vtkHeightFieldMeshFilter_h
#define vtkHeightFieldMeshFilter_h

#include "MesolightReliefTexturesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkHeightFieldMeshFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkHeightFieldMeshFilter* New();
  vtkTypeMacro(vtkHeightFieldMeshFilter, vtkPolyDataAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The textured plane: Origin is texture (0,0), Point1 is (1,0) and Point2 is (0,1).
   * Defaults: (0,0,0), (1,0,0), (0,1,0) (see SquareTexels).
   */
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  vtkSetVector3Macro(Point1, double);
  vtkGetVector3Macro(Point1, double);
  vtkSetVector3Macro(Point2, double);
  vtkGetVector3Macro(Point2, double);
  ///@}

  ///@{
  /**
   * When on (default), only the direction of Point2 - Origin is used and its length is
   * |Point1 - Origin| * H / W, so that texels are square.
   */
  vtkSetMacro(SquareTexels, bool);
  vtkGetMacro(SquareTexels, bool);
  vtkBooleanMacro(SquareTexels, bool);
  ///@}

  ///@{
  /**
   * Depth scale (world depth of depth 1 / world width of the texture), clamped to
   * [0, 100]. Used when UseInputDepthScale is off or the input has no
   * "MesolightDepthScale" field array. Default is 0.05.
   */
  vtkSetClampMacro(DepthScale, double, 0.0, 100.0);
  vtkGetMacro(DepthScale, double);
  ///@}

  ///@{
  /**
   * Use the input's "MesolightDepthScale" field array, when present, as the depth scale.
   * Default is on.
   */
  vtkSetMacro(UseInputDepthScale, bool);
  vtkGetMacro(UseInputDepthScale, bool);
  vtkBooleanMacro(UseInputDepthScale, bool);
  ///@}

protected:
  vtkHeightFieldMeshFilter();
  ~vtkHeightFieldMeshFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Origin[3] = { 0.0, 0.0, 0.0 };
  double Point1[3] = { 1.0, 0.0, 0.0 };
  double Point2[3] = { 0.0, 1.0, 0.0 };
  bool SquareTexels = true;
  double DepthScale = 0.05;
  bool UseInputDepthScale = true;

private:
  vtkHeightFieldMeshFilter(const vtkHeightFieldMeshFilter&) = delete;
  void operator=(const vtkHeightFieldMeshFilter&) = delete;
};

#endif
