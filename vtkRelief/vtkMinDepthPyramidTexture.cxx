// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMinDepthPyramidTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "MinDepthPyramid.h" // Mesolight::ReliefTextures core

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
        static_cast<unsigned int>(sizes[0].second), 1, VTK_FLOAT,
        const_cast<float*>(levels[0].data())))
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
    glTexImage2D(GL_TEXTURE_2D, static_cast<GLint>(l), GL_R32F, sizes[l].first, sizes[l].second, 0,
      GL_RED, GL_FLOAT, levels[l].data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, static_cast<GLint>(levels.size()) - 1);
  if (levels.size() > 16)
  {
    vtkErrorMacro(<< "Relief textures above 32768 texels per side are not supported.");
    return false;
  }
  vtkOpenGLCheckErrorMacro("failed uploading the min-depth pyramid");
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
void vtkMinDepthPyramidTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->TextureObject)
  {
    this->TextureObject->ReleaseGraphicsResources(win);
  }
  this->NumberOfLevels = 0;
}

//------------------------------------------------------------------------------
void vtkMinDepthPyramidTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLevels: " << this->NumberOfLevels << "\n";
}
