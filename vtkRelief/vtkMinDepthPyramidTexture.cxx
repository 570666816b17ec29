// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMinDepthPyramidTexture.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "MinDepthPyramid.h" // Mesolight::ReliefTextures core

#include <algorithm>
#include <cmath>
#include <cstddef>
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
  // (k-1, k), (k, k), clamped to the texture), and a coarser cell the minima of its four children
  // (2i, 2j), (2i+1, 2j), (2i, 2j+1), (2i+1, 2j+1), the leftover odd child folded into the last
  // (a missing child repeats the first). The traversal then reads a level-0 cell once, for its
  // bound and for the exact patch intersection alike, and a coarser cell once for the bounds of
  // the 2 x 2 cells below it (the minimum of the four channels is the cell's own bound).
  std::vector<std::vector<float>> rgba(levels.size());
  for (size_t l = 0; l < levels.size(); ++l)
  {
    const size_t n = levels[l].size();
    rgba[l].resize(4 * n);
    if (l > 0)
    {
      const int lw = sizes[l].first, lh = sizes[l].second;
      const int cw = sizes[l - 1].first, ch = sizes[l - 1].second;
      const std::vector<float>& child = levels[l - 1];
      // Children of cell n along one axis for channel c: [first, last], empty if first > last.
      auto range = [](int node, int c, int nodes, int children, int& first, int& last)
      {
        first = 2 * node + c;
        last = (c == 1 && node == nodes - 1) ? children - 1 : first;
      };
      for (int ny = 0; ny < lh; ++ny)
      {
        for (int nx = 0; nx < lw; ++nx)
        {
          float* c = &rgba[l][4 *
            (static_cast<size_t>(ny) * static_cast<size_t>(lw) + static_cast<size_t>(nx))];
          for (int q = 0; q < 4; ++q)
          {
            int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
            range(nx, q & 1, lw, cw, x0, x1);
            range(ny, q >> 1, lh, ch, y0, y1);
            float m = std::numeric_limits<float>::infinity();
            for (int y = y0; y <= y1 && y < ch; ++y)
            {
              for (int x = x0; x <= x1 && x < cw; ++x)
              {
                m = std::min(m, child[static_cast<size_t>(y) * static_cast<size_t>(cw) +
                                  static_cast<size_t>(x)]);
              }
            }
            c[q] = m;
          }
          for (int q = 1; q < 4; ++q)
          {
            if (std::isinf(c[q]))
            {
              c[q] = c[q & 1] < c[q] ? c[q & 1] : c[0]; // a missing child: a present one's bound
            }
          }
        }
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
