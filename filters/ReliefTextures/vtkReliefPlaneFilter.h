// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefPlaneFilter
 * @brief   the plane a relief texture is drawn on, in the map's proportions
 *
 * vtkReliefPlaneFilter makes, from an image (a relief texture, or the depth map it was baked
 * from), the flat surface to draw it on: one quad in the z = 0 plane, centred on the origin,
 * Width wide along +x, facing +z, with texture coordinates (0,0) to (1,1) at its corners and
 * point normals. Its height is Width times GetGroundProportions(): the image's rows over its
 * columns, times its pixels' height over their width on the ground when it carries them (field
 * data "MesolightPixelSize", which vtkOIIOImageReader reads from a georeferenced file and
 * vtkReliefTextureFilter passes on), else times its spacing's. A geographic raster's pixels are
 * narrower than tall away from the equator (an SRTM tile at 60 N: 0.49 times as wide as tall), so
 * on a square plane or one of the texels' proportions the terrain would be stretched.
 *
 * A vtkPlaneSource (ParaView's Plane) is square whatever the map; this is its replacement in
 * front of vtkAttachReliefTexture, and vtkReliefMapper draws on any mesh with texture
 * coordinates, this one included.
 *
 * Errors (no output): no input image, or an image without points.
 *
 * In parallel (pieces, MPI ranks) the quad is piece 0's; other pieces are empty. Each asks for
 * the whole image, as piece 0 of 1 (common/vtkWholeExtentRequest.h).
 */
#ifndef vtkReliefPlaneFilter_h
#define vtkReliefPlaneFilter_h

#include "MesolightReliefTexturesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class vtkImageData;

class MESOLIGHTRELIEFTEXTURES_EXPORT vtkReliefPlaneFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkReliefPlaneFilter* New();
  vtkTypeMacro(vtkReliefPlaneFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The plane's width along +x, in world units. Default 1 (ParaView's Plane is 1 wide). A width
   * that is not a positive finite number is an error and keeps the width.
   */
  void SetWidth(double width);
  vtkGetMacro(Width, double);
  ///@}

  /**
   * The map's height over its width on the ground: rows / columns, times the pixels' height
   * over their width where the image carries a valid "MesolightPixelSize" (two positive, finite
   * sizes whose ratio is too), else over the image's spacing along x (VTK's own pixel shape:
   * ParaView's GDAL Raster Reader gives a projected raster's pixel size there). 1 for a null or
   * empty image.
   */
  static double GetGroundProportions(vtkImageData* image);

protected:
  vtkReliefPlaneFilter();
  ~vtkReliefPlaneFilter() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkReliefPlaneFilter(const vtkReliefPlaneFilter&) = delete;
  void operator=(const vtkReliefPlaneFilter&) = delete;

  double Width = 1.0;
};

#endif
