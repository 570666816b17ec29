// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkConeMapFilter
 * @brief   Depth map (or relief texture) -> cone-packed relief texture for cone stepping.
 *
 * Cone maps store, per texel, the widest cone above the surface that a ray may step through
 * safely: conservative cones (Dummer 2006) contain no surface at all; relaxed cones (Policarpo &
 * Oliveira 2007, with the exact definition of Ban et al. 2024) may be entered once but never left,
 * so relaxed cone stepping followed by a binary or interval search finds the first hit. Both are
 * provably valid on the bilinear surface the renderer samples, with ratios read bilinearly (no
 * safety factor). Cone ratios are horizontal radius (in texture widths) over depth. See
 * filters/ReliefTextures/core/ConeMaps.h for the definitions and the bound. Computed with
 * vtkSMPTools.
 *
 * Input: a depth map, read exactly as vtkReliefTextureFilter reads it (the same options: heights,
 * elevations in metres and their no-data value, pixels given as cells by ParaView's GDAL Raster
 * Reader), or a relief texture (4 components and "MesolightDepthScale": depth in A, kept).
 * Output packings:
 *  - Float (default): float RGBA, R,G = normal x, y packed (n+1)/2, B = cone ratio, A = depth;
 *  - Ratio8Bit: the cone ratio c stored as floor(255 c / (1 + c)) in 8 bits (the layout of
 *    Méndez Fernández's thesis; never widened).
 * Field data: "MesolightDepthScale" (as vtkReliefTextureFilter), "MesolightConeType"
 * ("relaxed" or "conservative", which vtkReliefMapper reads to enable cone stepping).
 * Long maps report progress and honour AbortExecute.
 */
#ifndef vtkConeMapFilter_h
#define vtkConeMapFilter_h

#include "MesolightReliefTexturesModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkConeMapFilter : public vtkImageAlgorithm
{
public:
  static vtkConeMapFilter* New();
  vtkTypeMacro(vtkConeMapFilter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ConeTypes
  {
    RELAXED = 0,
    CONSERVATIVE = 1
  };
  vtkSetClampMacro(ConeType, int, RELAXED, CONSERVATIVE);
  vtkGetMacro(ConeType, int);
  void SetConeTypeToRelaxed() { this->SetConeType(RELAXED); }
  void SetConeTypeToConservative() { this->SetConeType(CONSERVATIVE); }

  enum Packings
  {
    FLOAT = 0,
    RATIO_8BIT = 1
  };
  vtkSetClampMacro(Packing, int, FLOAT, RATIO_8BIT);
  vtkGetMacro(Packing, int);
  void SetPackingToFloat() { this->SetPacking(FLOAT); }
  void SetPackingToRatio8Bit() { this->SetPacking(RATIO_8BIT); }

  ///@{
  /** Normals and input handling, as in vtkReliefTextureFilter. */
  vtkSetClampMacro(DepthScale, double, 0.0, 100.0);
  vtkGetMacro(DepthScale, double);
  vtkSetClampMacro(BorderMode, int, 0, 1);
  vtkGetMacro(BorderMode, int);
  void SetBorderModeToClamp() { this->SetBorderMode(0); }
  void SetBorderModeToWrap() { this->SetBorderMode(1); }
  vtkSetMacro(InvertInput, bool);
  vtkGetMacro(InvertInput, bool);
  vtkBooleanMacro(InvertInput, bool);
  vtkSetMacro(NormalizeRange, bool);
  vtkGetMacro(NormalizeRange, bool);
  vtkBooleanMacro(NormalizeRange, bool);
  vtkSetMacro(NoDataValue, double);
  vtkGetMacro(NoDataValue, double);
  vtkSetMacro(UseNoDataValue, bool);
  vtkGetMacro(UseNoDataValue, bool);
  vtkBooleanMacro(UseNoDataValue, bool);
  vtkSetMacro(UseInputNoDataValue, bool);
  vtkGetMacro(UseInputNoDataValue, bool);
  vtkBooleanMacro(UseInputNoDataValue, bool);
  vtkSetMacro(UseTrueDepthScale, bool);
  vtkGetMacro(UseTrueDepthScale, bool);
  vtkBooleanMacro(UseTrueDepthScale, bool);
  vtkSetClampMacro(VerticalExaggeration, double, 0.0, 1000.0);
  vtkGetMacro(VerticalExaggeration, double);
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
  vtkConeMapFilter();
  ~vtkConeMapFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int ConeType = RELAXED;
  int Packing = FLOAT;
  double DepthScale = 0.05;
  int BorderMode = 0;
  bool InvertInput = false;
  bool NormalizeRange = false;
  double NoDataValue = 0.0;
  bool UseNoDataValue = false;
  bool UseInputNoDataValue = true;
  bool UseTrueDepthScale = false;
  double VerticalExaggeration = 1.0;
  vtkTypeInt64 MemoryBudget = 0;

private:
  // RequestData without the std::bad_alloc guard.
  int Execute(vtkInformationVector** inputVector, vtkInformationVector* outputVector);

  vtkConeMapFilter(const vtkConeMapFilter&) = delete;
  void operator=(const vtkConeMapFilter&) = delete;
};

#endif
