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

vtkStandardNewMacro(vtkMinDepthPyramidTexture);

//------------------------------------------------------------------------------
vtkTextureObject* vtkMinDepthPyramidTexture::GetTextureObject()
{
  return this->TextureObject;
}

//------------------------------------------------------------------------------
vtkMinDepthPyramidTexture::vtkMinDepthPyramidTexture() = default;

//------------------------------------------------------------------------------
vtkMinDepthPyramidTexture::~vtkMinDepthPyramidTexture() = default;

//------------------------------------------------------------------------------
bool vtkMinDepthPyramidTexture::Upload(
  vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth, int width, int height)
{
  // Levels FirstLevel and up (filters/ReliefTextures/core/MinDepthPyramid.h), each cell its
  // 2 x 2 children's minima; sizes halve rounding down, a complete OpenGL mipmap from
  // FirstLevel on, so they upload as mip levels of one texture.
  std::vector<int> sizes;
  const std::vector<std::vector<float>> levels = mesolight::ChildMinimaFromLevel(
    depth.data(), width, height, vtkMinDepthPyramidTexture::FirstLevel, sizes);
  std::vector<const void*> data;
  for (const auto& level : levels)
  {
    data.push_back(level.data());
  }
  if (!this->UploadLevels(renWin, GL_RGBA32F, GL_FLOAT, data, sizes))
  {
    return false;
  }
  this->NumberOfLevels = vtkMinDepthPyramidTexture::FirstLevel + static_cast<int>(levels.size());
  this->MinimumDepth = depth.empty() ? 0.0 : *std::min_element(depth.begin(), depth.end());
  this->LevelSizes = sizes;
  return true;
}

//------------------------------------------------------------------------------
bool vtkMinDepthPyramidTexture::UploadCompact(
  vtkOpenGLRenderWindow* renWin, const std::vector<std::uint16_t>& depth16, int width, int height)
{
  // The same levels with each minimum rounded down to 8 bits (core/CompactReliefStorage.h):
  // bounds never below the surface, 1/3 byte per texel from level 2, so the default's upload
  // stays far under a tenth of the dense mesh's (docs/relief-benchmark.md, "GPU memory").
  std::vector<int> sizes;
  const std::vector<std::vector<std::uint8_t>> levels = mesolight::CompactChildMinima8(
    depth16.data(), width, height, vtkMinDepthPyramidTexture::FirstLevel, sizes);
  if (levels.empty())
  {
    vtkErrorMacro(<< "Could not build the min-depth pyramid of a " << width << "x" << height
                  << " map.");
    return false;
  }
  std::vector<const void*> data;
  for (const auto& level : levels)
  {
    data.push_back(level.data());
  }
  if (!this->UploadLevels(renWin, GL_RGBA8, GL_UNSIGNED_BYTE, data, sizes))
  {
    return false;
  }
  this->NumberOfLevels = vtkMinDepthPyramidTexture::FirstLevel + static_cast<int>(levels.size());
  this->MinimumDepth = depth16.empty()
    ? 0.0
    : static_cast<float>(*std::min_element(depth16.begin(), depth16.end())) / 65535.0f;
  this->LevelSizes = sizes;
  return true;
}

//------------------------------------------------------------------------------
bool vtkMinDepthPyramidTexture::UploadLevels(vtkOpenGLRenderWindow* renWin,
  unsigned int internalFormat, unsigned int type, const std::vector<const void*>& levels,
  const std::vector<int>& sizes)
{
  // Mip levels are 16 bits per side at most (a 32768^2 map has 16 levels above its cells).
  if (levels.empty() || 2 * levels.size() != sizes.size() || levels.size() > 16)
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
  if (!pyramid->Create2DFromRaw(static_cast<unsigned int>(sizes[0]),
        static_cast<unsigned int>(sizes[1]), 4, type == GL_FLOAT ? VTK_FLOAT : VTK_UNSIGNED_CHAR,
        nullptr))
  {
    vtkErrorMacro(<< "Could not create the min-depth pyramid texture.");
    return false;
  }
  // vtkTextureObject allocates one level; the levels are ours (minima, not averages).
  pyramid->Bind();
  // Tightly packed rows (RGBA8 and RGBA32F rows are multiples of 4 bytes), whatever
  // pixel-store state earlier uploads left behind.
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  for (size_t l = 0; l < levels.size(); ++l)
  {
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(l), static_cast<GLint>(internalFormat),
      sizes[2 * l], sizes[2 * l + 1], 0, GL_RGBA, type, levels[l]);
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
