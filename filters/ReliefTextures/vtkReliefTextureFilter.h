// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefTextureFilter
 * @brief   depth map -> relief texture (Sobel normals in RGB, depth in A)
 *
 * vtkReliefTextureFilter turns a 2D image into the relief texture used by Mesolight's
 * relief mapper (as in Méndez Fernández's thesis §3.2, "Sobel operator", eq. 2):
 * a float RGBA image, point scalars named "Relief", where RGB is the tangent-space normal
 * packed to [0,1] as (n + 1) / 2 and A is the depth in [0,1] (0 = top, 1 = deepest).
 * The normal is that of the surface z = -DepthScale * d(x, y), x = u in [0,1], computed
 * from Sobel derivatives (see core/SobelNormals.h). The DepthScale used is stored in the
 * output field data as a 1-tuple float array "MesolightDepthScale".
 *
 * Input: any scalar type. Unsigned integers are divided by the type maximum (uchar / 255,
 * ushort / 65535); float and double are used as they are. The values must lie in [0,1] unless
 * NormalizeRange is on, which rescales the stored values themselves (elevations in metres,
 * below sea level too). Signed integers (int16 DEMs) hold measurements and need NormalizeRange.
 * Elevation maps mark missing samples with a no-data value (GDAL's, e.g. -32768 in int16 DEMs):
 * with UseNoDataValue those texels are left out of the range and get the deepest depth of the
 * others, as the lowest ground. An input that names its own no-data value (field data
 * "MesolightNoDataValue", which vtkOIIOImageReader sets from a GeoTIFF's GDAL_NODATA tag) gets the
 * same by default (UseInputNoDataValue). Images with 3 or 4 components are converted to luminance
 * 0.2126 R + 0.7152 G + 0.0722 B (Rec. 709, common/Luminance.h); with 2 components the first one is
 * used. The input array is selected with SetInputArrayToProcess() and defaults to the point
 * scalars, else the cell scalars. Pixels given as cells (GDAL Raster Reader's output: a grid one
 * point larger than the raster) are read at the cells' corners: each texel is the mean of the cells
 * around it that have data (hidden cells, GDAL's no-data ones, have none under
 * UseInputNoDataValue), as Cell Data to Point Data averages them but without the holes; the output
 * keeps the input's points. A plain image's rows, which GDAL Raster Reader gives top row first,
 * are turned around (common/vtkRasterRowOrder.h), so texel row 0 is the picture's bottom row as
 * from every other reader.
 *
 * Errors (no output is produced): no input, an empty or non-2D image, NaN or infinite
 * values (other than no data), depths outside [0,1] or signed integers without NormalizeRange, no
 * texel with data. An image one texel wide or high gets a warning: slopes cannot be estimated
 * across it and that normal component is 0.
 */
#ifndef vtkReliefTextureFilter_h
#define vtkReliefTextureFilter_h

#include "MesolightReliefTexturesModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkReliefTextureFilter : public vtkImageAlgorithm
{
public:
  static vtkReliefTextureFilter* New();
  vtkTypeMacro(vtkReliefTextureFilter, vtkImageAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BorderModes
  {
    CLAMP = 0,
    WRAP = 1
  };

  ///@{
  /**
   * World depth of depth = 1 divided by the world width of the texture (dimensionless).
   * Clamped to [0, 10] (mesolight::MaximumDepthScale), with a warning (a negative scale is 0:
   * invert the input instead); NaN is an error and keeps the value. Default is 0.05.
   */
  void SetDepthScale(double depthScale);
  vtkGetMacro(DepthScale, double);
  ///@}

  ///@{
  /**
   * The true vertical scale of an elevation map: with UseTrueDepthScale on, the depth scale is
   * not DepthScale but TrueDepthScale times VerticalExaggeration, where TrueDepthScale is the
   * elevations' range over the map's width on the ground, (max - min) / (W * pixel width), both
   * in metres: the relief is then as deep, relative to its width, as the terrain is (times the
   * exaggeration). It needs NormalizeRange (the range is the stored values', in metres, or in
   * the unit the field data array "MesolightElevationUnit" gives in metres: vtkOIIOImageReader's
   * for a GeoTIFF that names its vertical unit, e.g. feet) and an image that carries a pixel's
   * size on the ground (the field data array "MesolightPixelSize", metres along rows and
   * columns, which vtkOIIOImageReader gives for a GeoTIFF and an SRTM tile); without them the
   * filter fails with an error. Defaults: off, 1.
   */
  vtkSetMacro(UseTrueDepthScale, bool);
  vtkGetMacro(UseTrueDepthScale, bool);
  vtkBooleanMacro(UseTrueDepthScale, bool);
  vtkSetClampMacro(VerticalExaggeration, double, 0.0, 1000.0);
  vtkGetMacro(VerticalExaggeration, double);
  ///@}

  ///@{
  /**
   * After Update(): the true vertical scale's depth scale of the last input, when it was
   * georeferenced and NormalizeRange was on (else 0; the output carries it as the field data
   * array "MesolightTrueDepthScale" then), and the depth scale the output carries
   * ("MesolightDepthScale").
   */
  vtkGetMacro(TrueDepthScale, double);
  vtkGetMacro(AppliedDepthScale, double);
  ///@}

  ///@{
  /**
   * How the Sobel stencil addresses texels outside the image: CLAMP (one-sided differences
   * at the borders, the default) or WRAP (periodic, for tileable textures).
   */
  vtkSetClampMacro(BorderMode, int, CLAMP, WRAP);
  vtkGetMacro(BorderMode, int);
  void SetBorderModeToClamp() { this->SetBorderMode(CLAMP); }
  void SetBorderModeToWrap() { this->SetBorderMode(WRAP); }
  ///@}

  ///@{
  /**
   * When on, the input is a HEIGHT map (white = high) and depth = 1 - value.
   * Applied after NormalizeRange. Default is off.
   */
  vtkSetMacro(InvertInput, bool);
  vtkGetMacro(InvertInput, bool);
  vtkBooleanMacro(InvertInput, bool);
  ///@}

  ///@{
  /**
   * When on, the input range [min, max] is rescaled to [0, 1] (a constant image becomes
   * depth 0). Default is off.
   */
  vtkSetMacro(NormalizeRange, bool);
  vtkGetMacro(NormalizeRange, bool);
  vtkBooleanMacro(NormalizeRange, bool);
  ///@}

  ///@{
  /**
   * When UseNoDataValue is on, texels whose first component equals NoDataValue (in the input
   * array's own values, before any conversion; NaN: texels that are NaN) hold no data: they are
   * left out of the range check and of NormalizeRange, and get the deepest depth of the other
   * texels. It is an error when every texel holds no data. Defaults: off, 0.
   */
  vtkSetMacro(NoDataValue, double);
  vtkGetMacro(NoDataValue, double);
  vtkSetMacro(UseNoDataValue, bool);
  vtkGetMacro(UseNoDataValue, bool);
  vtkBooleanMacro(UseNoDataValue, bool);
  ///@}

  ///@{
  /**
   * When UseNoDataValue is off and the input image names a no-data value (a one-value field data
   * array "MesolightNoDataValue", as vtkOIIOImageReader gives a GeoTIFF's GDAL_NODATA tag), use
   * that one: a DEM's holes are not drawn as terrain unless this is turned off. Default: on.
   * GetAppliedNoDataValue() tells, after Update(), which value was applied, if any.
   */
  vtkSetMacro(UseInputNoDataValue, bool);
  vtkGetMacro(UseInputNoDataValue, bool);
  vtkBooleanMacro(UseInputNoDataValue, bool);
  ///@}

  ///@{
  /**
   * After Update(): whether texels were taken as holding no data (UseNoDataValue, or the
   * input's own value under UseInputNoDataValue), which value, and how many texels held it.
   */
  vtkGetMacro(AppliedNoData, bool);
  vtkGetMacro(AppliedNoDataValue, double);
  vtkGetMacro(NumberOfNoDataTexels, vtkIdType);
  ///@}

  ///@{
  /**
   * Memory budget in bytes. The filter estimates its working memory before allocating it and
   * fails with an error giving the size it needs when that is more than the budget (a
   * std::bad_alloc that still happens becomes an error too, never an abort). 0 (default): the
   * memory the process can get (its cgroup limit, else the physical memory).
   */
  vtkSetClampMacro(MemoryBudget, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(MemoryBudget, vtkTypeInt64);
  ///@}

protected:
  vtkReliefTextureFilter();
  ~vtkReliefTextureFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double DepthScale = 0.05;
  bool UseTrueDepthScale = false;
  double VerticalExaggeration = 1.0;
  double TrueDepthScale = 0.0;
  double AppliedDepthScale = 0.0;
  int BorderMode = CLAMP;
  bool InvertInput = false;
  bool NormalizeRange = false;
  double NoDataValue = 0.0;
  bool UseNoDataValue = false;
  bool UseInputNoDataValue = true;
  bool AppliedNoData = false;
  double AppliedNoDataValue = 0.0;
  vtkIdType NumberOfNoDataTexels = 0;
  vtkTypeInt64 MemoryBudget = 0;

private:
  // RequestData without the std::bad_alloc guard.
  int Execute(vtkInformationVector** inputVector, vtkInformationVector* outputVector);

  vtkReliefTextureFilter(const vtkReliefTextureFilter&) = delete;
  void operator=(const vtkReliefTextureFilter&) = delete;
};

#endif
