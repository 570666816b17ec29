// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMinDepthPyramidTexture
 * @brief   The min-depth (maximum-mipmap) pyramid of a relief texture on the GPU, which the
 *          MaximumMipmap method traverses.
 *
 * Level 0 has one texel per cell between the relief texture's texel centres holding the cell's
 * four corner depths (RGBA), so one fetch gives the traversal both the cell's bound and its
 * bilinear patch; a cell of a coarser level holds the minimum depths (the highest surface) of
 * its 2 x 2 children, one per channel, so one fetch bounds the four cells a traversal may
 * descend into (mesolight::ComputeMinDepthPyramid,
 * filters/ReliefTextures/core/MinDepthPyramid.h). Level sizes halve rounding down, a complete
 * OpenGL mipmap, so all levels are mip levels of one RGBA float texture (uploaded by hand:
 * OpenGL would average, not take minima). 16 bytes per cell: 5.6 MB for a 512^2 map.
 *
 * UploadCompact (the relief texture cache's compact storage) stores the same levels in 16 bits
 * (GL_RGBA16): level 0 the 16-bit depth texels at the cells' corners, coarser levels the minima
 * of each cell's 2 x 2 children as the depth texture holds them (exact): 2.8 MB for a 512^2 map.
 * (Reading level 0's corners from the depth texture instead, 0.7 MB, took four fetches per
 * level-0 cell and made the traversal 1.6-2x slower on llvmpipe: docs/relief-methods.md.)
 */

#ifndef vtkMinDepthPyramidTexture_h
#define vtkMinDepthPyramidTexture_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for TextureObject

#include <cstdint> // for std::uint16_t
#include <utility> // for std::pair
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

  /** Number of levels uploaded; 0 until Upload succeeds. */
  vtkGetMacro(NumberOfLevels, int);

  /**
   * The smallest depth of the whole map (the pyramid's apex) as the texture holds it; 0 until
   * Upload succeeds. A ray above it meets nothing, so the traversal starts where it reaches it.
   */
  vtkGetMacro(MinimumDepth, double);

  /** Cells per level, (width, height) pairs from level 0 on. */
  const std::vector<int>& GetLevelSizes() const { return this->LevelSizes; }

  /** The texture; null before the first Upload. */
  vtkTextureObject* GetTextureObject() { return this->TextureObject; }

  void ReleaseGraphicsResources(vtkWindow* win);

protected:
  vtkMinDepthPyramidTexture();
  ~vtkMinDepthPyramidTexture() override;

  /**
   * Creates the texture (internalFormat: GL_RGBA32F with float data, GL_RGBA16 with 16-bit
   * data) and uploads levels[l] (RGBA, sizes[l] cells) as its mip level l. False (with an
   * error) if it cannot.
   */
  bool UploadLevels(vtkOpenGLRenderWindow* renWin, unsigned int internalFormat, bool sixteenBit,
    const std::vector<const void*>& levels, const std::vector<std::pair<int, int>>& sizes);

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
