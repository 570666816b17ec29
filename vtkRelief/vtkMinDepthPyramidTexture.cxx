// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMinDepthPyramidTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkReliefTextureCache.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "CompactReliefStorage.h" // Mesolight::ReliefTextures core
#include "MinDepthPyramid.h"      // idem

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

vtkStandardNewMacro(vtkMinDepthPyramidTexture);

//------------------------------------------------------------------------------
vtkMinDepthPyramidTexture::vtkMinDepthPyramidTexture() = default;

//------------------------------------------------------------------------------
vtkMinDepthPyramidTexture::~vtkMinDepthPyramidTexture() = default;

//------------------------------------------------------------------------------
bool vtkMinDepthPyramidTexture::Upload(
  vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth, int width, int height)
{
  // The min-depth pyramid (filters/ReliefTextures/core/MinDepthPyramid.h): level sizes halve
  // rounding down, a complete OpenGL mipmap, so the coarser levels upload as mip levels of one
  // texture.
  const std::vector<std::vector<float>> levels =
    mesolight::ComputeMinDepthPyramid(depth.data(), width, height);
  std::vector<std::pair<int, int>> sizes;
  for (size_t l = 0; l < levels.size(); ++l)
  {
    int lw = 0, lh = 0;
    mesolight::MinDepthPyramidLevelSize(width, height, static_cast<int>(l), lw, lh);
    sizes.emplace_back(lw, lh);
  }
  // RGBA: level 0 holds each cell's four corner depths (the texels (k-1, k-1), (k, k-1),
  // (k-1, k), (k, k), clamped to the texture), so the traversal reads a level-0 cell once, for
  // its bound and for the exact patch intersection alike; coarser cells their children's minima.
  std::vector<std::vector<float>> rgba = mesolight::PackChildMinima(levels, sizes);
  if (!levels.empty())
  {
    const int cw = sizes[0].first;
    const int ch = sizes[0].second;
    rgba[0].resize(4 * static_cast<size_t>(cw) * static_cast<size_t>(ch));
    auto texel = [&](int i, int j)
    {
      i = std::min(std::max(i, 0), width - 1);
      j = std::min(std::max(j, 0), height - 1);
      return depth[static_cast<size_t>(j) * static_cast<size_t>(width) + static_cast<size_t>(i)];
    };
    for (int ky = 0; ky < ch; ++ky)
    {
      for (int kx = 0; kx < cw; ++kx)
      {
        float* c = &rgba[0][4 *
          (static_cast<size_t>(ky) * static_cast<size_t>(cw) + static_cast<size_t>(kx))];
        c[0] = texel(kx - 1, ky - 1);
        c[1] = texel(kx, ky - 1);
        c[2] = texel(kx - 1, ky);
        c[3] = texel(kx, ky);
      }
    }
  }
  std::vector<const void*> data;
  for (const auto& level : rgba)
  {
    data.push_back(level.data());
  }
  if (!this->UploadLevels(renWin, GL_RGBA32F, false, data, sizes))
  {
    return false;
  }
  this->NumberOfLevels = static_cast<int>(levels.size());
  this->MinimumDepth = depth.empty() ? 0.0 : *std::min_element(depth.begin(), depth.end());
  this->LevelSizes.clear();
  for (const auto& size : sizes)
  {
    this->LevelSizes.push_back(size.first);
    this->LevelSizes.push_back(size.second);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkMinDepthPyramidTexture::UploadCompact(
  vtkOpenGLRenderWindow* renWin, const std::vector<std::uint16_t>& depth16, int width, int height)
{
  // Levels 1 and up (core/CompactReliefStorage.h) in 16 bits, the exact minima of the 16-bit
  // depths, each cell holding its four children's (PackChildMinima); level 0's cells' minima
  // (the children of level 1) are taken from their corners.
  std::vector<int> coarseSizes;
  const std::vector<std::vector<std::uint16_t>> coarse =
    mesolight::CompactMinDepthPyramid(depth16.data(), width, height, coarseSizes);
  if (coarse.empty())
  {
    vtkErrorMacro(<< "Could not build the min-depth pyramid of a " << width << "x" << height
                  << " map.");
    return false;
  }
  std::vector<std::pair<int, int>> levelSizes{ { width + 1, height + 1 } };
  std::vector<std::vector<std::uint16_t>> minima(1 + coarse.size());
  minima[0].resize(static_cast<size_t>(width + 1) * static_cast<size_t>(height + 1));
  for (int ky = 0; ky <= height; ++ky)
  {
    for (int kx = 0; kx <= width; ++kx)
    {
      std::uint16_t m = 0xffff;
      for (int j : { ky - 1, ky })
      {
        for (int i : { kx - 1, kx })
        {
          const size_t t =
            static_cast<size_t>(std::min(std::max(j, 0), height - 1)) * static_cast<size_t>(width) +
            static_cast<size_t>(std::min(std::max(i, 0), width - 1));
          m = std::min(m, depth16[t]);
        }
      }
      minima[0][static_cast<size_t>(ky) * static_cast<size_t>(width + 1) +
        static_cast<size_t>(kx)] = m;
    }
  }
  for (size_t l = 0; l < coarse.size(); ++l)
  {
    minima[l + 1] = coarse[l];
    levelSizes.emplace_back(coarseSizes[2 * l], coarseSizes[2 * l + 1]);
  }
  std::vector<std::vector<std::uint16_t>> levels = mesolight::PackChildMinima(minima, levelSizes);
  // Level 0: each cell's four corner depths (the 16-bit texels (k-1, k-1), (k, k-1), (k-1, k),
  // (k, k), clamped), so a level-0 cell is one fetch, as in the float pyramid, instead of four of
  // the depth texture: measured 1.6-2x faster traversal on llvmpipe (docs/relief-methods.md).
  levels[0].resize(4 * minima[0].size());
  for (int ky = 0; ky <= height; ++ky)
  {
    for (int kx = 0; kx <= width; ++kx)
    {
      std::uint16_t* c = &levels[0][4 *
        (static_cast<size_t>(ky) * static_cast<size_t>(width + 1) + static_cast<size_t>(kx))];
      int q = 0;
      for (int j : { ky - 1, ky })
      {
        for (int i : { kx - 1, kx })
        {
          c[q++] = depth16[static_cast<size_t>(std::min(std::max(j, 0), height - 1)) *
              static_cast<size_t>(width) +
            static_cast<size_t>(std::min(std::max(i, 0), width - 1))];
        }
      }
    }
  }
  std::vector<const void*> data;
  for (const auto& level : levels)
  {
    data.push_back(level.data());
  }
  if (!this->UploadLevels(renWin, GL_RGBA16, true, data, levelSizes))
  {
    return false;
  }
  this->NumberOfLevels = static_cast<int>(levels.size());
  this->MinimumDepth = depth16.empty()
    ? 0.0
    : static_cast<float>(*std::min_element(depth16.begin(), depth16.end())) / 65535.0f;
  this->LevelSizes.clear();
  for (const auto& size : levelSizes)
  {
    this->LevelSizes.push_back(size.first);
    this->LevelSizes.push_back(size.second);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkMinDepthPyramidTexture::UploadLevels(vtkOpenGLRenderWindow* renWin,
  unsigned int internalFormat, bool sixteenBit, const std::vector<const void*>& levels,
  const std::vector<std::pair<int, int>>& sizes)
{
  // Mip levels are 16 bits per side at most (a 32768^2 map has 16 levels above its cells).
  if (levels.empty() || levels.size() != sizes.size() || levels.size() > 16)
  {
    vtkErrorMacro(<< (levels.empty() ? "An empty min-depth pyramid."
                                     : "Relief textures above 32768 texels per side are not "
                                       "supported."));
    return false;
  }
  if (!this->TextureObject)
  {
    this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTextureObject* pyramid = this->TextureObject;
  pyramid->SetContext(renWin);
  pyramid->SetInternalFormat(internalFormat);
  pyramid->SetMinificationFilter(vtkTextureObject::NearestMipmapNearest);
  pyramid->SetMagnificationFilter(vtkTextureObject::Nearest);
  pyramid->SetWrapS(vtkTextureObject::ClampToEdge);
  pyramid->SetWrapT(vtkTextureObject::ClampToEdge);
  pyramid->SetBaseLevel(0);
  pyramid->SetMaxLevel(static_cast<int>(levels.size()) - 1);
  if (!pyramid->Create2DFromRaw(static_cast<unsigned int>(sizes[0].first),
        static_cast<unsigned int>(sizes[0].second), 4, sixteenBit ? VTK_UNSIGNED_SHORT : VTK_FLOAT,
        nullptr))
  {
    vtkErrorMacro(<< "Could not create the min-depth pyramid texture.");
    return false;
  }
  // vtkTextureObject allocates one level; the levels are ours (minima, not averages).
  pyramid->Bind();
  // Tightly packed rows (RGBA16 and RGBA32F rows are multiples of 4 bytes), whatever
  // pixel-store state earlier uploads left behind.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (size_t l = 0; l < levels.size(); ++l)
  {
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(l), static_cast<GLint>(internalFormat),
      sizes[l].first, sizes[l].second, 0, GL_RGBA, sixteenBit ? GL_UNSIGNED_SHORT : GL_FLOAT,
      levels[l]);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.size()) - 1);
  pyramid->Deactivate();
  vtkOpenGLCheckErrorMacro("failed uploading the min-depth pyramid");
  this->UploadedBytes = vtkReliefTextureCache::GetTextureBytes(pyramid);
  return true;
}

//------------------------------------------------------------------------------
void vtkMinDepthPyramidTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->TextureObject)
  {
    this->TextureObject->ReleaseGraphicsResources(win);
  }
  this->NumberOfLevels = 0;
  this->UploadedBytes = 0;
  this->MinimumDepth = 0.0;
}

//------------------------------------------------------------------------------
void vtkMinDepthPyramidTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "UploadedBytes: " << this->UploadedBytes << "\n";
  os << indent << "MinimumDepth: " << this->MinimumDepth << "\n";
}
