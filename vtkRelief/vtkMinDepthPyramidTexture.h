// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMinDepthPyramidTexture
 * @brief   The min-depth (maximum-mipmap) pyramid of a relief texture on the GPU, which the
 *          MaximumMipmap method traverses.
 *
 * The traversal reads a cell of level 0 (one per cell between the relief texture's texel
 * centres) as its four corner depths straight from the depth texture, with one gather, and
 * stores no bound for levels 1 to FirstLevel - 1; from FirstLevel up a cell holds the minimum
 * depths (the highest surface) of its 2 x 2 children, one per channel, so one fetch bounds the
 * four cells a traversal may descend into (mesolight::ChildMinimaFromLevel,
 * filters/ReliefTextures/core/MinDepthPyramid.h). Level sizes halve rounding down, a complete
 * OpenGL mipmap, so these levels are the mip levels of one RGBA texture (uploaded by hand:
 * OpenGL would average, not take minima); its mip level m is pyramid level FirstLevel + m.
 *
 * Upload (float storage) keeps float minima (GL_RGBA32F); UploadCompact (the relief texture
 * cache's compact storage, the default) rounds them down to 8 bits (GL_RGBA8), which still
 * bound the surface from above, so the traversal stays exact: 1/3 byte per texel at
 * FirstLevel 2, 87 KB for a 512^2 map. (Level 2 was left out, 1/12 byte per texel, while the
 * normals were uploaded too; stored, it saves 3-11% of the grazing rays' lock-step fetches on
 * rough real maps: docs/relief-methods.md. Before: level 0's corners and every level in RGBA16,
 * 10.67 bytes per texel, 2.8 MB; the corners from the depth texture with four fetches had made
 * the traversal 1.6-2x slower: docs/relief-methods.md.)
 */

#ifndef vtkMinDepthPyramidTexture_h
#define vtkMinDepthPyramidTexture_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for TextureObject

#include <cstdint> // for std::uint16_t
#include <vector>  // for LevelSizes

class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class MESOLIGHTRELIEF_EXPORT vtkMinDepthPyramidTexture : public vtkObject
{
public:
  static vtkMinDepthPyramidTexture* New();
  vtkTypeMacro(vtkMinDepthPyramidTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Builds and uploads the pyramid of a width x height depth image (row by row, depth in
   * [0, 1]). False (with an error) if the texture cannot be made.
   */
  bool Upload(
    vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth, int width, int height);

  /**
   * Builds and uploads the compact pyramid of a width x height map of 16-bit depths as the
   * depth texture holds them. False (with an error) if the texture cannot be made.
   */
  bool UploadCompact(vtkOpenGLRenderWindow* renWin, const std::vector<std::uint16_t>& depth16,
    int width, int height);

  /** Bytes the uploaded pyramid occupies on the GPU (all levels); 0 when not built. */
  vtkGetMacro(UploadedBytes, vtkIdType);

  /** Marks the pyramid as not built (its relief texture changed). */
  void Reset() { this->NumberOfLevels = 0; }

  /** Pyramid levels (FirstLevel plus those uploaded); 0 until Upload succeeds. */
  vtkGetMacro(NumberOfLevels, int);

  /**
   * The smallest depth of the whole map (the pyramid's apex) as the texture holds it; 0 until
   * Upload succeeds. A ray above it meets nothing, so the traversal starts where it reaches it.
   */
  vtkGetMacro(MinimumDepth, double);

  /**
   * The first level stored: levels 1 to FirstLevel - 1 hold no bounds (the traversal walks
   * their level-0 cells, at most 2 x 2 in a blocked level-2 cell), level 0 is the depth
   * texture's texels.
   */
  static constexpr int FirstLevel = 2;

  /** Cells per stored level, (width, height) pairs from FirstLevel on. */
  const std::vector<int>& GetLevelSizes() const { return this->LevelSizes; }

  /** The texture; null before the first Upload. */
  vtkTextureObject* GetTextureObject();

  void ReleaseGraphicsResources(vtkWindow* win);

protected:
  vtkMinDepthPyramidTexture();
  ~vtkMinDepthPyramidTexture() override;

  /**
   * Creates the texture (internalFormat GL_RGBA32F with type GL_FLOAT, or GL_RGBA8 with
   * GL_UNSIGNED_BYTE) and uploads levels[l] (RGBA, sizes[2l] x sizes[2l + 1] cells) as its mip
   * level l. False (with an error) if it cannot.
   */
  bool UploadLevels(vtkOpenGLRenderWindow* renWin, unsigned int internalFormat, unsigned int type,
    const std::vector<const void*>& levels, const std::vector<int>& sizes);

  vtkSmartPointer<vtkTextureObject> TextureObject;
  int NumberOfLevels = 0;
  vtkIdType UploadedBytes = 0;
  double MinimumDepth = 0.0;
  std::vector<int> LevelSizes;

private:
  vtkMinDepthPyramidTexture(const vtkMinDepthPyramidTexture&) = delete;
  void operator=(const vtkMinDepthPyramidTexture&) = delete;
};

#endif
