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
 * Input: a depth map, baked exactly as vtkReliefTextureFilter bakes it: a cone map is a relief
 * texture with cone ratios, so this filter is one and has all of its options (heights, elevations
 * in metres and their no-data value, pixels given as cells by ParaView's GDAL Raster Reader, the
 * depth scale, the memory budget) and its results (GetAppliedNoData() and the rest). Or a relief
 * texture (4 components and "MesolightDepthScale": depth in A, kept).
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
#include "vtkReliefTextureFilter.h"

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkConeMapFilter : public vtkReliefTextureFilter
{
public:
  static vtkConeMapFilter* New();
  vtkTypeMacro(vtkConeMapFilter, vtkReliefTextureFilter);
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

protected:
  vtkConeMapFilter();
  ~vtkConeMapFilter() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int ConeType = RELAXED;
  int Packing = FLOAT;

private:
  // RequestData without the std::bad_alloc guard.
  int Execute(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector);

  vtkConeMapFilter(const vtkConeMapFilter&) = delete;
  void operator=(const vtkConeMapFilter&) = delete;
};

#endif
