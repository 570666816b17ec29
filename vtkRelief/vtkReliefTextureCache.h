// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefTextureCache
 * @brief   The relief texture on the GPU: uploaded when its image changes, with what the draw
 *          needs to know about it (size, cone packing, the depth scale its normals were baked
 *          with) and, for the MaximumMipmap method, its min-depth pyramid.
 *
 * The image is a float or unsigned char RGBA image: normal packed in RGB as (n+1)/2, depth in A
 * (vtkReliefTextureFilter), or vtkConeMapFilter's cone map (cone ratios in B, field data
 * "MesolightConeType"). It is uploaded as float RGBA, 8-bit values divided by 255; cone ratios
 * stored as c / (1 + c) in 8-bit maps are decoded. Uploads are keyed by the scalar array
 * and its modification time, since images rebuilt from field data wrap the same array.
 */

#ifndef vtkReliefTextureCache_h
#define vtkReliefTextureCache_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

class vtkDataArray;
class vtkImageData;
class vtkMinDepthPyramidTexture;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class MESOLIGHTRELIEF_EXPORT vtkReliefTextureCache : public vtkObject
{
public:
  static vtkReliefTextureCache* New();
  vtkTypeMacro(vtkReliefTextureCache, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Uploads the image unless it is already on the GPU of this window as asked: with mipmaps
   * (level of detail) or not, and with its min-depth pyramid when needPyramid is set. Returns
   * whether the texture can be drawn; false (with an error, once per change) for an image that
   * is not a relief texture or cannot be uploaded.
   */
  bool Update(vtkOpenGLRenderWindow* renWin, vtkImageData* image, bool mipmaps, bool needPyramid);

  /** The relief texture. */
  vtkTextureObject* GetTextureObject() { return this->TextureObject; }

  /** The min-depth pyramid, built by Update when asked for. */
  vtkMinDepthPyramidTexture* GetPyramid() { return this->Pyramid; }

  /** Texels of the uploaded texture (width, height). */
  vtkGetVector2Macro(Size, int);

  /** The cone map the uploaded texture carries (vtkReliefProperty::ConeMapKind). */
  vtkGetMacro(ConeMap, int);

  /** Whether the uploaded texture carries cone ratios in B. */
  bool GetConePacked() const;

  /**
   * The depth scale the normals were baked with (field data "MesolightDepthScale"); < 0 if
   * unknown, then the normals are taken as consistent with the property's DepthScale.
   */
  vtkGetMacro(BakedDepthScale, double);

  void ReleaseGraphicsResources(vtkWindow* win);

protected:
  vtkReliefTextureCache();
  ~vtkReliefTextureCache() override;

  vtkSmartPointer<vtkTextureObject> TextureObject;
  vtkSmartPointer<vtkMinDepthPyramidTexture> Pyramid;
  vtkDataArray* Uploaded = nullptr; // not referenced: only compared
  vtkMTimeType UploadTime = 0;
  bool UploadedWithMipmaps = false;
  bool Ready = false;
  int Size[2] = { 0, 0 };
  int ConeMap = 0;
  double BakedDepthScale = 0.0;

private:
  vtkReliefTextureCache(const vtkReliefTextureCache&) = delete;
  void operator=(const vtkReliefTextureCache&) = delete;
};

#endif
