// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefTextureCache
 * @brief   The relief texture on the GPU: uploaded when its image changes, with what the draw
 *          needs to know about it (size, cone packing, the depth scale its normals were baked
 *          with) and, for the MaximumMipmap method, its min-depth pyramid.
 *
 * The image is a float or unsigned char RGBA image: normal packed in RGB as (n+1)/2, depth in A
 * (vtkReliefTextureFilter), or vtkConeMapFilter's cone map (cone ratios in B, field data
 * "MesolightConeType"); 8-bit cone ratios are stored as c / (1 + c). Uploads are keyed by the
 * scalar array and its modification time, since images rebuilt from field data wrap the same
 * array.
 *
 * Compact storage (the default) uploads only what the method reads, in as few bits as keep the
 * hits exact (core/CompactReliefStorage.h):
 *  - depth in 16 bits (GL_R16; 8-bit maps too: some implementations filter 8-bit textures to
 *    8-bit results, which moves the hits);
 *  - the normal in GL_RG8_SNORM, hemispherical octahedral coordinates; with deriveNormals,
 *    none when they are the depth's Sobel normals (vtkReliefTextureFilter's bake; checked here,
 *    NormalMismatch): the shader derives them from 16 depth texels, the float texture's shading
 *    for half the bytes and more fetches;
 *  - cone ratios only for cone methods, 8 bits rounded to narrower cones (GL_R8);
 *  - for MaximumMipmap the pyramid's levels 1 and up in 16 bits, each cell its four children's
 *    exact minima (RGBA16)
 *    (vtkMinDepthPyramidTexture); its level 0, the cells' corners, is the depth texture itself.
 * 4 bytes per texel for relief (14x less than the dense displaced mesh's 56), 6.7 for
 * MaximumMipmap, 5 for cone methods, against 16 to 37 as float. Level of detail's visible
 * normal filter (the default) adds the normal's moments from mip level 2 up, 1.3 bytes per
 * texel: 5.3 for relief (10.5x less than the dense mesh). Float storage (floatTextures)
 * uploads the float RGBA texture and float pyramid instead: kept to measure what compact storage
 * costs (bench relief --texture-storage).
 */

#ifndef vtkReliefTextureCache_h
#define vtkReliefTextureCache_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

#include <cstdint> // for std::uint16_t
#include <vector>  // for the upload buffers

class vtkDataArray;
class vtkImageData;
class vtkMinDepthPyramidTexture;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
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
  bool Update(vtkOpenGLRenderWindow* renWin, vtkImageData* image, bool mipmaps, bool needPyramid,
    bool needCones = true, bool floatTextures = false, bool normalMoments = false);

  /**
   * The relief texture: the depth (compact storage) or the float RGBA texture (float storage).
   */
  vtkTextureObject* GetTextureObject() { return this->TextureObject; }

  /** Activates the textures the draw reads (wrap: vtkTextureObject's wrap mode), and after it. */
  void ActivateTextures(int wrap);
  void DeactivateTextures();

  /** Sets the samplers' uniforms (mlReliefTexture, mlNormalTexture, mlConeTexture). */
  void SetShaderParameters(vtkShaderProgram* program);

  /** Whether the float RGBA layout is uploaded (float storage). */
  vtkGetMacro(FloatTextures, bool);

  /**
   * Compact storage: whether normals are uploaded. Not when they are the depth's own
   * (NormalsFromDepth): the shader then takes every normal it reads from the depth (the
   * surface's gradient, its cells' facets, the moments of its levels), 2 bytes per texel less.
   */
  vtkGetMacro(NormalsStored, bool);

  /**
   * Whether the normal's mip-mapped moments are uploaded (compact storage with mipmaps, asked
   * for by level of detail, whose normal filters read them): mlMomentTexture0 holds E[w nx^2],
   * E[w ny^2], E[w nx ny], E[w nz^2] and mlMomentTexture1 E[w nx nz], E[w ny nz], E[w nx],
   * E[w ny] in RGBA16F, w = 1 / nz the texel's surface area over its base area (LEAN mapping,
   * Olano and Baker 2010, with the 3D second-moment matrix). The depth and normals then have
   * no mip chain (the filter reads their level 0 only).
   */
  vtkGetMacro(MomentsUploaded, bool);

  /**
   * The relief's mip level that the moment textures' level 0 holds: 2
   * (mesolight::NormalMomentFirstStoredLevel; the shader computes levels 0 and 1 from the stored
   * normals, or from the depth's surface cells when the normals are the depth's own).
   * Uniform mlMomentFirstLevel.
   */
  vtkGetMacro(MomentFirstLevel, int);

  /** Bits per depth texel: 16 (compact storage) or 32 (float storage). */
  vtkGetMacro(DepthBits, int);

  /**
   * The largest normal component difference between the stored normals and the Sobel normals
   * of the depth (interior texels); negative when the texture records no depth scale
   * (MesolightDepthScale) to compare them at.
   */
  vtkGetMacro(NormalMismatch, double);

  /**
   * Whether the texture's normals are its depth's own, the Sobel normals vtkReliefTextureFilter
   * bakes at the depth scale it records (NormalMismatch within about a degree): the shader then
   * shades the surface it marches (the bilinear depth's gradient near, its facets' moments far:
   * ML_SURFACE_NORMALS), as the exact intersector and the path tracer's dense mesh do. Other
   * normals (a normal map made apart) are shaded as given.
   */
  vtkGetMacro(NormalsFromDepth, bool);

  /**
   * Bytes the textures of the last Update occupy on the GPU, all mip levels, from the sizes
   * and formats OpenGL reports for them (relief texture, normals, cones, pyramid).
   */
  vtkGetMacro(UploadedBytes, vtkIdType);

  /** The min-depth pyramid, built by Update when asked for. */
  vtkMinDepthPyramidTexture* GetPyramid() { return this->Pyramid; }

  /** Texels of the uploaded texture (width, height). */
  vtkGetVector2Macro(Size, int);

  /** The cone map the uploaded texture carries (vtkReliefProperty::ConeMapKind). */
  vtkGetMacro(ConeMap, int);

  /**
   * Whether the shader reads cone ratios: uploaded (compact storage, a cone method) or in the
   * float texture's B (float storage, a cone map).
   */
  bool GetConePacked() const;

  /**
   * The depth scale the normals were baked with (field data "MesolightDepthScale"); < 0 if
   * unknown, then the normals are taken as consistent with the property's DepthScale.
   */
  vtkGetMacro(BakedDepthScale, double);

  /** Bytes a texture occupies, all its levels, as OpenGL reports its sizes and format. */
  static vtkIdType GetTextureBytes(vtkTextureObject* texture);

  void ReleaseGraphicsResources(vtkWindow* win);

protected:
  vtkReliefTextureCache();
  ~vtkReliefTextureCache() override;

  bool UploadFloat(vtkOpenGLRenderWindow* renWin, vtkDataArray* scalars, const int dims[3],
    bool bytes, bool mipmaps);
  bool UploadCompact(vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth,
    const std::vector<float>& normalXY, const std::vector<float>& normalZ, const int dims[3],
    bool mipmaps, std::vector<std::uint16_t>& depth16);
  void CheckNormalsAgainstDepth(
    const std::vector<float>& depth, const std::vector<float>& normalXY, const int dims[3]);
  bool UploadMoments(vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth,
    const std::vector<float>& normalXY, const std::vector<float>& normalZ, const int dims[3]);

  vtkSmartPointer<vtkTextureObject> TextureObject;
  vtkSmartPointer<vtkTextureObject> NormalTexture;
  vtkSmartPointer<vtkTextureObject> ConeTexture;
  vtkSmartPointer<vtkTextureObject> MomentTexture[2];
  vtkSmartPointer<vtkMinDepthPyramidTexture> Pyramid;
  vtkDataArray* Uploaded = nullptr; // not referenced: only compared
  vtkMTimeType UploadTime = 0;
  bool UploadedWithMipmaps = false;
  bool FloatTextures = false;
  bool NormalsStored = false;
  bool ConesUploaded = false;
  bool MomentsUploaded = false;
  vtkIdType MomentBytes = 0;
  int MomentFirstLevel = 0;
  bool Repeat = false; // the wrap mode of the current draw
  int DepthBits = 0;
  double NormalMismatch = -1.0;
  bool NormalsFromDepth = false;
  vtkIdType BaseBytes = 0; // relief texture and normals
  vtkIdType ConeBytes = 0;
  vtkIdType UploadedBytes = 0;
  bool Ready = false;
  int Size[2] = { 0, 0 };
  int ConeMap = 0;
  double BakedDepthScale = 0.0;

private:
  vtkReliefTextureCache(const vtkReliefTextureCache&) = delete;
  void operator=(const vtkReliefTextureCache&) = delete;
};

#endif
