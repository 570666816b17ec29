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
#include <cstddef>
#include <cstdint>
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
  // (k-1, k), (k, k), clamped to the texture) and the coarser levels their minimum in every
  // channel. The traversal then reads a level-0 cell once, for its bound and for the exact patch
  // intersection alike, instead of one pyramid fetch and four relief-texture fetches.
  std::vector<std::vector<float>> rgba(levels.size());
  for (size_t l = 0; l < levels.size(); ++l)
  {
    const size_t n = levels[l].size();
    rgba[l].resize(4 * n);
    if (l > 0)
    {
      for (size_t i = 0; i < n; ++i)
      {
        std::fill_n(rgba[l].begin() + static_cast<std::ptrdiff_t>(4 * i), 4, levels[l][i]);
      }
      continue;
    }
    const int cw = sizes[0].first;
    const int ch = sizes[0].second;
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
  if (!this->TextureObject)
  {
    this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTextureObject* pyramid = this->TextureObject;
  pyramid->SetContext(renWin);
  pyramid->SetMinificationFilter(vtkTextureObject::NearestMipmapNearest);
  pyramid->SetMagnificationFilter(vtkTextureObject::Nearest);
  pyramid->SetWrapS(vtkTextureObject::ClampToEdge);
  pyramid->SetWrapT(vtkTextureObject::ClampToEdge);
  pyramid->SetBaseLevel(0);
  pyramid->SetMaxLevel(static_cast<int>(levels.size()) - 1);
  if (!pyramid->Create2DFromRaw(static_cast<unsigned int>(sizes[0].first),
        static_cast<unsigned int>(sizes[0].second), 4, VTK_FLOAT, rgba[0].data()))
  {
    vtkErrorMacro(<< "Could not create the min-depth pyramid texture.");
    return false;
  }
  // vtkTextureObject uploads one level; the coarser ones are ours (minima, not averages).
  pyramid->Bind();
  // Tightly packed rows, whatever pixel-store state earlier uploads left behind.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (size_t l = 1; l < levels.size(); ++l)
  {
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(l), GL_RGBA32F, sizes[l].first, sizes[l].second,
      0, GL_RGBA, GL_FLOAT, rgba[l].data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.size()) - 1);
  if (levels.size() > 16)
  {
    vtkErrorMacro(<< "Relief textures above 32768 texels per side are not supported.");
    return false;
  }
  vtkOpenGLCheckErrorMacro("failed uploading the min-depth pyramid");
  this->UploadedBytes = vtkReliefTextureCache::GetTextureBytes(pyramid);
  this->NumberOfLevels = static_cast<int>(levels.size());
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
  // depths; level 0's corners are the depth texture's texels.
  std::vector<int> sizes;
  const std::vector<std::vector<std::uint16_t>> levels =
    mesolight::CompactMinDepthPyramid(depth16.data(), width, height, sizes);
  if (levels.empty())
  {
    vtkErrorMacro(<< "Could not build the min-depth pyramid of a " << width << "x" << height
                  << " map.");
    return false;
  }
  if (levels.size() > 15)
  {
    vtkErrorMacro(<< "Relief textures above 32768 texels per side are not supported.");
    return false;
  }
  if (!this->TextureObject)
  {
    this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  vtkTextureObject* pyramid = this->TextureObject;
  pyramid->SetContext(renWin);
  pyramid->SetInternalFormat(GL_R16);
  pyramid->SetMinificationFilter(vtkTextureObject::NearestMipmapNearest);
  pyramid->SetMagnificationFilter(vtkTextureObject::Nearest);
  pyramid->SetWrapS(vtkTextureObject::ClampToEdge);
  pyramid->SetWrapT(vtkTextureObject::ClampToEdge);
  pyramid->SetBaseLevel(0);
  pyramid->SetMaxLevel(static_cast<int>(levels.size()) - 1);
  if (!pyramid->Create2DFromRaw(static_cast<unsigned int>(sizes[0]),
        static_cast<unsigned int>(sizes[1]), 1, VTK_UNSIGNED_SHORT, nullptr))
  {
    vtkErrorMacro(<< "Could not create the min-depth pyramid texture.");
    return false;
  }
  pyramid->Bind();
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
  for (size_t l = 0; l < levels.size(); ++l)
  {
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(l), GL_R16, sizes[2 * l], sizes[2 * l + 1], 0,
      GL_RED, GL_UNSIGNED_SHORT, levels[l].data());
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.size()) - 1);
  pyramid->Deactivate();
  vtkOpenGLCheckErrorMacro("failed uploading the min-depth pyramid");
  this->UploadedBytes = vtkReliefTextureCache::GetTextureBytes(pyramid);
  this->NumberOfLevels = static_cast<int>(levels.size()) + 1;
  this->LevelSizes = { width + 1, height + 1 };
  this->LevelSizes.insert(this->LevelSizes.end(), sizes.begin(), sizes.end());
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
}

//------------------------------------------------------------------------------
void vtkMinDepthPyramidTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
  os << indent << "UploadedBytes: " << this->UploadedBytes << "\n";
}
