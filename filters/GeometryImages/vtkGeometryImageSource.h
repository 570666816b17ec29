// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkGeometryImageSource
 * @brief   analytic surfaces written as geometry images (plane, cylinder, sphere patch, ...)
 *
 * Produces a W x H vtkImageData whose point scalars ("Positions", 3 floats) are the points of an
 * analytic surface at the texel centres ((i + 0.5) / W, (j + 0.5) / H), with its exact normals as
 * a point array "Normals": test data and a demo for vtkGeometryImageToMesh. The surfaces are
 * framed like the relief wall (about [0, 1]^2 in x, y, facing +z, top at z = 0, one world unit
 * across), so a relief texture's DepthScale means the same on them. Surfaces: Plane, Cylinder
 * (120 degrees), SpherePatch (90 x 90 degrees), Wave (two cosine periods along x), Bump (a
 * Gaussian bump on a plane). HolesOn() empties (NaN) a disc of pixels, to test hole handling.
 */
#ifndef vtkGeometryImageSource_h
#define vtkGeometryImageSource_h

#include "MesolightGeometryImagesModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTGEOMETRYIMAGES_EXPORT vtkGeometryImageSource : public vtkImageAlgorithm
{
public:
  static vtkGeometryImageSource* New();
  vtkTypeMacro(vtkGeometryImageSource, vtkImageAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Surfaces
  {
    Plane = 0,
    Cylinder,
    SpherePatch,
    Wave,
    Bump
  };

  ///@{
  /** The surface. Default Cylinder. */
  vtkSetClampMacro(Surface, int, Plane, Bump);
  vtkGetMacro(Surface, int);
  void SetSurfaceToPlane() { this->SetSurface(Plane); }
  void SetSurfaceToCylinder() { this->SetSurface(Cylinder); }
  void SetSurfaceToSpherePatch() { this->SetSurface(SpherePatch); }
  void SetSurfaceToWave() { this->SetSurface(Wave); }
  void SetSurfaceToBump() { this->SetSurface(Bump); }
  /** "plane", "cylinder", "sphere", "wave" or "bump"; false (unchanged) for other names. */
  bool SetSurfaceByName(const char* name);
  ///@}

  ///@{
  /** Pixels across and down, each >= 2. Default 256 x 256. */
  vtkSetVector2Macro(Resolution, int);
  vtkGetVector2Macro(Resolution, int);
  ///@}

  ///@{
  /** Empty (NaN) a disc of radius 0.12 (in u) around (0.3, 0.6). Default off. */
  vtkSetMacro(Holes, bool);
  vtkGetMacro(Holes, bool);
  vtkBooleanMacro(Holes, bool);
  ///@}

protected:
  vtkGeometryImageSource();
  ~vtkGeometryImageSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Surface = Cylinder;
  int Resolution[2] = { 256, 256 };
  bool Holes = false;

private:
  vtkGeometryImageSource(const vtkGeometryImageSource&) = delete;
  void operator=(const vtkGeometryImageSource&) = delete;
};

#endif
