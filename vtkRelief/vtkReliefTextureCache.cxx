// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefTextureCache.h"

#include "vtk_glew.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMinDepthPyramidTexture.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkReliefProperty.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVariant.h"

#include "CompactReliefStorage.h" // Mesolight::ReliefTextures core
#include "ConeMaps.h"             // idem

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkReliefTextureCache);

namespace
{
// "relaxed" / "conservative" (or 1 / 2) from the cone map's field data; 0 if not cone packed.
int ConeTypeOf(vtkImageData* image)
{
  vtkAbstractArray* type = image->GetFieldData()->GetAbstractArray("MesolightConeType");
  if (!type || type->GetNumberOfValues() < 1)
  {
    return vtkReliefProperty::NoConeMap;
  }
  std::string text = type->GetVariantValue(0).ToString();
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return (text.find("conserv") != std::string::npos || text == "2")
    ? vtkReliefProperty::ConservativeConeMap
    : vtkReliefProperty::RelaxedConeMap;
}

// Channel c of every texel as a depth-like value in [0, 1] (bytes / 255), NaN kept for the
// caller to refuse.
void ReadChannel(vtkDataArray* scalars, vtkIdType count, int c, bool bytes, float* out)
{
  if (scalars->GetDataType() == VTK_FLOAT)
  {
    const float* v = static_cast<const float*>(scalars->GetVoidPointer(0));
    for (vtkIdType i = 0; i < count; ++i)
    {
      out[i] = v[4 * i + c];
    }
    return;
  }
  if (bytes)
  {
    const unsigned char* v = static_cast<const unsigned char*>(scalars->GetVoidPointer(0));
    for (vtkIdType i = 0; i < count; ++i)
    {
      out[i] = static_cast<float>(v[4 * i + c]) / 255.f;
    }
    return;
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    out[i] = static_cast<float>(scalars->GetComponent(i, c));
  }
}

int MipLevels(int w, int h)
{
  int levels = 1;
  while ((std::max(w, h) >> levels) > 0)
  {
    ++levels;
  }
  return levels;
}

// Makes texture a w x h 2D texture of internalFormat from tightly packed rows of data (format,
// type), with linear filtering and, when asked, a generated mip chain.
bool CreateTexture(vtkTextureObject* texture, vtkOpenGLRenderWindow* renWin, int w, int h,
  int components, int vtkType, unsigned int internalFormat, unsigned int format, unsigned int type,
  const void* data, bool mipmaps)
{
  texture->SetContext(renWin);
  texture->SetInternalFormat(internalFormat);
  texture->SetGenerateMipmap(false);
  texture->SetMinificationFilter(
    mipmaps ? vtkTextureObject::LinearMipmapLinear : vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  // vtkTextureObject's MaxLevel defaults to 0, which clamps every lookup to the base level
  // whatever the filter and textureLod ask for: open it to the whole mip chain.
  texture->SetBaseLevel(0);
  texture->SetMaxLevel(mipmaps ? MipLevels(w, h) - 1 : 0);
  // Allocated here, filled below with byte-aligned rows (8- and 16-bit rows of any width).
  if (!texture->Create2DFromRaw(
        static_cast<unsigned int>(w), static_cast<unsigned int>(h), components, vtkType, nullptr))
  {
    return false;
  }
  texture->Bind();
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, format, type, data);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (mipmaps)
  {
    glGenerateMipmap(GL_TEXTURE_2D);
  }
  texture->Deactivate();
  return glGetError() == GL_NO_ERROR;
}
} // namespace

//------------------------------------------------------------------------------
vtkIdType vtkReliefTextureCache::GetTextureBytes(vtkTextureObject* texture)
{
  if (!texture || texture->GetHandle() == 0)
  {
    return 0;
  }
  texture->Bind();
  vtkIdType bytes = 0;
  for (int level = 0; level < 32; ++level)
  {
    GLint w = 0, h = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &h);
    if (w <= 0 || h <= 0)
    {
      break;
    }
    GLint bits = 0;
    for (GLenum channel :
      { GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE, GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE })
    {
      GLint b = 0;
      glGetTexLevelParameteriv(GL_TEXTURE_2D, level, channel, &b);
      bits += b;
    }
    bytes += static_cast<vtkIdType>(w) * h * ((bits + 7) / 8);
  }
  texture->Deactivate();
  return bytes;
}

//------------------------------------------------------------------------------
vtkReliefTextureCache::vtkReliefTextureCache()
{
  this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  this->NormalTexture = vtkSmartPointer<vtkTextureObject>::New();
  for (auto& t : this->MomentTexture)
  {
    t = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->ConeTexture = vtkSmartPointer<vtkTextureObject>::New();
  this->Pyramid = vtkSmartPointer<vtkMinDepthPyramidTexture>::New();
}

//------------------------------------------------------------------------------
vtkReliefTextureCache::~vtkReliefTextureCache() = default;

//------------------------------------------------------------------------------
bool vtkReliefTextureCache::GetConePacked() const
{
  return this->FloatTextures ? this->ConeMap != vtkReliefProperty::NoConeMap : this->ConesUploaded;
}

//------------------------------------------------------------------------------
bool vtkReliefTextureCache::Update(vtkOpenGLRenderWindow* renWin, vtkImageData* image, bool mipmaps,
  bool needPyramid, bool needCones, bool floatTextures, bool normalMoments)
{
  const bool wantMoments = normalMoments && mipmaps && !floatTextures;
  // With the moments the march and the base normal read level 0 only, and the normal
  // filter reads the moments' mip chain: the depth and normals need no mip chain of their own.
  const bool baseMipmaps = mipmaps && !wantMoments;
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const bool baseCurrent = scalars && scalars == this->Uploaded &&
    scalars->GetMTime() <= this->UploadTime && this->TextureObject->GetHandle() != 0 &&
    this->TextureObject->GetContext() == renWin && this->UploadedWithMipmaps == baseMipmaps &&
    this->FloatTextures == floatTextures;
  const bool wantCones =
    !floatTextures && needCones && ConeTypeOf(image) != vtkReliefProperty::NoConeMap;
  const bool havePyramid = this->Pyramid->GetNumberOfLevels() > 0;
  if (baseCurrent && this->ConesUploaded == wantCones && havePyramid == needPyramid &&
    this->MomentsUploaded == wantMoments)
  {
    return this->Ready;
  }
  this->Ready = false;
  if (!baseCurrent)
  {
    this->Uploaded = scalars;
    this->UploadTime = scalars ? scalars->GetMTime() : 0;
  }

  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] < 1 || dims[1] < 1 || !scalars || scalars->GetNumberOfTuples() < 1)
  {
    vtkErrorMacro(<< "The relief texture is empty.");
    return false;
  }
  if (dims[2] != 1)
  {
    vtkErrorMacro(<< "The relief texture must be a 2D image; it has " << dims[2] << " slices.");
    return false;
  }
  if (scalars->GetNumberOfComponents() != 4)
  {
    vtkErrorMacro(<< "The relief texture needs 4 components (normal RGB, depth A) as made by "
                     "vtkReliefTextureFilter; it has "
                  << scalars->GetNumberOfComponents() << ".");
    return false;
  }
  const bool bytes = scalars->GetDataType() == VTK_UNSIGNED_CHAR;
  this->ConeMap = ConeTypeOf(image);
  const vtkIdType count = static_cast<vtkIdType>(dims[0]) * dims[1];
  const size_t n = static_cast<size_t>(count);

  // Every channel once: refused if not finite, whatever is uploaded of it.
  std::vector<float> channel(n);
  std::vector<float> depth(n);
  std::vector<float> normalXY;
  std::vector<float> normalZ; // empty for cone maps, whose B holds cones: z is rebuilt
  for (int c = 3; c >= 0; --c)
  {
    ReadChannel(scalars, count, c, bytes, channel.data());
    for (size_t i = 0; i < n; ++i)
    {
      if (!std::isfinite(channel[i]))
      {
        vtkErrorMacro(<< "The relief texture has a non-finite value at texel " << i
                      << " (component " << c << "); NaN or Inf cannot be rendered.");
        return false;
      }
    }
    if (c == 3)
    {
      for (size_t i = 0; i < n; ++i)
      {
        depth[i] = vtkMath::ClampValue(channel[i], 0.f, 1.f);
      }
    }
    else if (c < 2)
    {
      normalXY.resize(2 * n);
      for (size_t i = 0; i < n; ++i)
      {
        normalXY[2 * i + c] = 2.f * vtkMath::ClampValue(channel[i], 0.f, 1.f) - 1.f;
      }
    }
    else if (c == 2 && !floatTextures && this->ConeMap == vtkReliefProperty::NoConeMap)
    {
      normalZ.resize(n);
      for (size_t i = 0; i < n; ++i)
      {
        normalZ[i] = 2.f * vtkMath::ClampValue(channel[i], 0.f, 1.f) - 1.f;
      }
    }
  }

  this->BakedDepthScale = -1.0;
  if (vtkDataArray* baked = image->GetFieldData()->GetArray("MesolightDepthScale"))
  {
    if (baked->GetNumberOfTuples() > 0)
    {
      this->BakedDepthScale = baked->GetComponent(0, 0);
    }
  }

  std::vector<std::uint16_t> depth16;
  if (!baseCurrent)
  {
    this->UploadedWithMipmaps = baseMipmaps;
    this->FloatTextures = floatTextures;
    this->NormalTexture->ReleaseGraphicsResources(renWin);
    this->NormalsStored = false;
    this->BaseBytes = 0;
    this->CheckNormalsAgainstDepth(depth, normalXY, dims);
    if (floatTextures)
    {
      if (!this->UploadFloat(renWin, scalars, dims, bytes, baseMipmaps))
      {
        return false;
      }
    }
    else if (!this->UploadCompact(renWin, depth, normalXY, normalZ, dims, baseMipmaps, depth16))
    {
      return false;
    }
  }
  this->Size[0] = dims[0];
  this->Size[1] = dims[1];

  if (this->MomentsUploaded != wantMoments || !baseCurrent)
  {
    for (auto& t : this->MomentTexture)
    {
      t->ReleaseGraphicsResources(renWin);
    }
    this->MomentsUploaded = false;
    this->MomentBytes = 0;
    if (wantMoments && !this->UploadMoments(renWin, depth, normalXY, normalZ, dims))
    {
      return false;
    }
  }

  // Cone ratios, only for the cone methods (compact storage; float storage has them in B).
  if (this->ConesUploaded != wantCones || !baseCurrent)
  {
    this->ConeTexture->ReleaseGraphicsResources(renWin);
    this->ConesUploaded = false;
    this->ConeBytes = 0;
    if (wantCones)
    {
      ReadChannel(scalars, count, 2, bytes, channel.data());
      std::vector<std::uint8_t> cones(n);
      for (size_t i = 0; i < n; ++i)
      {
        // 8-bit maps hold the code already; 255 (an infinite cone) is kept finite for the
        // shader's decoding, a narrower cone.
        const int code = bytes ? static_cast<int>(std::lround(channel[i] * 255.f))
                               : mesolight::EncodeConeRatio8(channel[i]);
        cones[i] = static_cast<std::uint8_t>(std::min(code, 254));
      }
      if (!CreateTexture(this->ConeTexture, renWin, dims[0], dims[1], 1, VTK_UNSIGNED_CHAR, GL_R8,
            GL_RED, GL_UNSIGNED_BYTE, cones.data(), false))
      {
        vtkErrorMacro(<< "Could not create the " << dims[0] << "x" << dims[1]
                      << " cone ratio texture.");
        return false;
      }
      this->ConesUploaded = true;
      this->ConeBytes = GetTextureBytes(this->ConeTexture);
    }
  }

  if (havePyramid != needPyramid || !baseCurrent)
  {
    this->Pyramid->ReleaseGraphicsResources(renWin);
    if (needPyramid)
    {
      if (floatTextures)
      {
        if (!this->Pyramid->Upload(renWin, depth, dims[0], dims[1]))
        {
          return false;
        }
      }
      else
      {
        if (depth16.empty())
        {
          depth16.resize(n);
          for (size_t i = 0; i < n; ++i)
          {
            depth16[i] = mesolight::QuantizeDepth16(depth[i]);
          }
        }
        if (!this->Pyramid->UploadCompact(renWin, depth16, dims[0], dims[1]))
        {
          return false;
        }
      }
    }
  }
  this->UploadedBytes =
    this->BaseBytes + this->ConeBytes + this->MomentBytes + this->Pyramid->GetUploadedBytes();
  this->Ready = true;
  return true;
}

//------------------------------------------------------------------------------
bool vtkReliefTextureCache::UploadFloat(
  vtkOpenGLRenderWindow* renWin, vtkDataArray* scalars, const int dims[3], bool bytes, bool mipmaps)
{
  const bool conePacked = this->ConeMap != vtkReliefProperty::NoConeMap;
  const vtkIdType count = static_cast<vtkIdType>(dims[0]) * dims[1];
  std::vector<float> texels(static_cast<size_t>(count) * 4);
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      double value = scalars->GetComponent(i, c);
      if (bytes)
      {
        value /= 255.0;
      }
      if (c == 2 && conePacked)
      {
        // Cone ratio: raw in float maps, stored as c / (1 + c) in 8-bit ones (never widened).
        value = bytes ? value / (1.0 - std::min(value, 0.999)) : std::max(value, 0.0);
      }
      else
      {
        value = vtkMath::ClampValue(value, 0.0, 1.0);
      }
      texels[static_cast<size_t>(i) * 4 + c] = static_cast<float>(value);
    }
  }
  if (!CreateTexture(this->TextureObject, renWin, dims[0], dims[1], 4, VTK_FLOAT, GL_RGBA32F,
        GL_RGBA, GL_FLOAT, texels.data(), mipmaps))
  {
    vtkErrorMacro(<< "Could not create a " << dims[0] << "x" << dims[1]
                  << " float RGBA texture (too large for this OpenGL implementation?).");
    return false;
  }
  vtkOpenGLCheckErrorMacro("failed uploading the relief texture");
  this->DepthBits = 32;
  this->BaseBytes = GetTextureBytes(this->TextureObject);
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefTextureCache::CheckNormalsAgainstDepth(
  const std::vector<float>& depth, const std::vector<float>& normalXY, const int dims[3])
{
  this->NormalMismatch = -1.0;
  this->NormalsFromDepth = false;
  if (!(this->BakedDepthScale > 0.0) || normalXY.size() != 2 * depth.size())
  {
    return;
  }
  // Against the float depth: 16-bit rounding moves a normal by far less than the tolerance.
  this->NormalMismatch = mesolight::SobelNormalMismatch(
    depth.data(), normalXY.data(), dims[0], dims[1], this->BakedDepthScale);
  this->NormalsFromDepth = this->NormalMismatch <= mesolight::SobelNormalTolerance;
}

//------------------------------------------------------------------------------
bool vtkReliefTextureCache::UploadCompact(vtkOpenGLRenderWindow* renWin,
  const std::vector<float>& depth, const std::vector<float>& normalXY,
  const std::vector<float>& normalZ, const int dims[3], bool mipmaps,
  std::vector<std::uint16_t>& depth16)
{
  // Depth in 16 bits, also for 8-bit maps (exact either way): filtered 8-bit textures come back
  // with 8-bit precision on some implementations (Mesa llvmpipe), which moved the hits.
  const size_t n = depth.size();
  depth16.resize(n);
  for (size_t i = 0; i < n; ++i)
  {
    depth16[i] = mesolight::QuantizeDepth16(depth[i]);
  }
  this->DepthBits = 16;
  if (!CreateTexture(this->TextureObject, renWin, dims[0], dims[1], 1, VTK_UNSIGNED_SHORT, GL_R16,
        GL_RED, GL_UNSIGNED_SHORT, depth16.data(), mipmaps))
  {
    vtkErrorMacro(<< "Could not create a " << dims[0] << "x" << dims[1]
                  << " 16-bit depth texture (too large for this OpenGL implementation?).");
    return false;
  }
  this->BaseBytes = GetTextureBytes(this->TextureObject);

  // Normals that are the depth's own (the Sobel normals vtkReliefTextureFilter bakes; Mendez
  // Fernandez's thesis, section 3.2) are not uploaded: the shader shades the surface it marches
  // from the depth alone (ML_SURFACE_NORMALS). Others (a normal map made apart) are.
  this->NormalsStored = !this->NormalsFromDepth;
  if (this->NormalsStored)
  {
    // Hemispherical octahedral coordinates (Cigolle et al., "A Survey of Efficient
    // Representations for Independent Unit Vectors", JCGT 2014; core/CompactReliefStorage.h).
    std::vector<std::int8_t> xy(2 * n);
    for (size_t i = 0; i < n; ++i)
    {
      const float x = normalXY[2 * i], y = normalXY[2 * i + 1];
      const float z = normalZ.empty() ? std::sqrt(std::max(0.f, 1.f - x * x - y * y)) : normalZ[i];
      mesolight::EncodeOctahedral8(x, y, z, xy[2 * i], xy[2 * i + 1]);
    }
    if (!CreateTexture(this->NormalTexture, renWin, dims[0], dims[1], 2, VTK_SIGNED_CHAR,
          GL_RG8_SNORM, GL_RG, GL_BYTE, xy.data(), mipmaps))
    {
      vtkErrorMacro(<< "Could not create the " << dims[0] << "x" << dims[1] << " normal texture.");
      return false;
    }
    this->BaseBytes += GetTextureBytes(this->NormalTexture);
  }
  vtkOpenGLCheckErrorMacro("failed uploading the relief texture");
  return true;
}

//------------------------------------------------------------------------------
bool vtkReliefTextureCache::UploadMoments(vtkOpenGLRenderWindow* renWin,
  const std::vector<float>& depth, const std::vector<float>& normalXY,
  const std::vector<float>& normalZ, const int dims[3])
{
  // Moments of the unit normal n weighted by w = 1 / nz, the texel's surface area over its base
  // area: a footprint's mean of w (n.v) f(n) is then the light the pixel sees of its facets,
  // each in proportion to its projected area (LEAN mapping, Olano and Baker, "LEAN Mapping",
  // I3D 2010; here the 3D second-moment matrix; core/CompactReliefStorage.h). Averages are
  // linear, so a mip chain holds the moments of every footprint. Its levels 0 and 1 are not
  // uploaded: a texel's moments are those of its own normal (stored, or its surface cell's from
  // the depth), which the shader reads anyway, and level 1 averages four of them
  // (NormalMomentFirstStoredLevel). Levels 2 and
  // up stay half floats: by Olano's error analysis of LEAN mapping, a moment's representation
  // error must stay below 1 / s for a specular exponent s, and 8 bits over these moments' range
  // (up to 16, the weight's clamp) err by 16/512, exponents of 30; half floats err by 1/2048 of
  // the value. At a sixteenth of the texels they cost 1.3 bytes per texel of level 0. Normals
  // that are the depth's own give way to the surface's (NormalsFromDepth): the moments are
  // those of the bilinear surface the shader shades up close, the spread inside each texel
  // included, which the smoothed Sobel normals lack.
  constexpr int k = mesolight::NormalMomentCount;
  this->MomentFirstLevel = mesolight::NormalMomentFirstStoredLevel; // levels 0-1: the shader's
  const int w = mesolight::MipLevelSize(dims[0], this->MomentFirstLevel);
  const int h = mesolight::MipLevelSize(dims[1], this->MomentFirstLevel);
  const std::vector<float> moments = this->NormalsFromDepth
    ? mesolight::SurfaceNormalMomentLevel(
        depth.data(), dims[0], dims[1], this->BakedDepthScale, this->MomentFirstLevel)
    : mesolight::NormalMomentLevel(normalXY.data(), normalZ.empty() ? nullptr : normalZ.data(),
        dims[0], dims[1], this->MomentFirstLevel);
  const size_t stored = static_cast<size_t>(w) * h;
  std::vector<float> m0(4 * stored), m1(4 * stored);
  for (size_t i = 0; i < stored; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      m0[4 * i + c] = moments[k * i + c];
      m1[4 * i + c] = moments[k * i + 4 + c];
    }
  }
  for (int t = 0; t < 2; ++t)
  {
    // Levels above the first stored are glGenerateMipmap's 2 x 2 box filter.
    if (!CreateTexture(this->MomentTexture[t], renWin, w, h, 4, VTK_FLOAT, GL_RGBA16F, GL_RGBA,
          GL_FLOAT, (t == 0 ? m0 : m1).data(), true))
    {
      vtkErrorMacro(<< "Could not create the " << w << "x" << h << " normal moment texture.");
      return false;
    }
    this->MomentBytes += GetTextureBytes(this->MomentTexture[t]);
  }
  this->MomentsUploaded = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefTextureCache::ActivateTextures(int wrap)
{
  this->Repeat = wrap == vtkTextureObject::Repeat;
  for (vtkTextureObject* t :
    { this->TextureObject.Get(), this->NormalTexture.Get(), this->ConeTexture.Get() })
  {
    if (t == this->TextureObject || (t == this->NormalTexture && this->NormalsStored) ||
      (t == this->ConeTexture && this->ConesUploaded))
    {
      t->SetWrapS(wrap);
      t->SetWrapT(wrap);
      t->Activate();
    }
  }
  if (this->MomentsUploaded)
  {
    for (auto& t : this->MomentTexture)
    {
      t->SetWrapS(wrap);
      t->SetWrapT(wrap);
      t->Activate();
    }
  }
}

//------------------------------------------------------------------------------
void vtkReliefTextureCache::DeactivateTextures()
{
  this->TextureObject->Deactivate();
  if (this->NormalsStored)
  {
    this->NormalTexture->Deactivate();
  }
  if (this->ConesUploaded)
  {
    this->ConeTexture->Deactivate();
  }
  if (this->MomentsUploaded)
  {
    for (auto& t : this->MomentTexture)
    {
      t->Deactivate();
    }
  }
}

//------------------------------------------------------------------------------
void vtkReliefTextureCache::SetShaderParameters(vtkShaderProgram* program)
{
  program->SetUniformi("mlReliefTexture", this->TextureObject->GetTextureUnit());
  program->SetUniformi("mlRepeatTexture", this->Repeat ? 1 : 0);
  if (this->NormalsStored && !this->FloatTextures)
  {
    program->SetUniformi("mlNormalTexture", this->NormalTexture->GetTextureUnit());
  }
  if (this->ConesUploaded && !this->FloatTextures)
  {
    program->SetUniformi("mlConeTexture", this->ConeTexture->GetTextureUnit());
  }
  if (this->MomentsUploaded)
  {
    program->SetUniformi("mlMomentTexture0", this->MomentTexture[0]->GetTextureUnit());
    program->SetUniformi("mlMomentTexture1", this->MomentTexture[1]->GetTextureUnit());
    program->SetUniformf("mlMomentFirstLevel", static_cast<float>(this->MomentFirstLevel));
  }
}

//------------------------------------------------------------------------------
void vtkReliefTextureCache::ReleaseGraphicsResources(vtkWindow* win)
{
  this->TextureObject->ReleaseGraphicsResources(win);
  this->NormalTexture->ReleaseGraphicsResources(win);
  this->ConeTexture->ReleaseGraphicsResources(win);
  for (auto& t : this->MomentTexture)
  {
    t->ReleaseGraphicsResources(win);
  }
  this->MomentsUploaded = false;
  this->ConesUploaded = false;
  this->NormalsStored = false;
  this->Pyramid->ReleaseGraphicsResources(win);
  this->Uploaded = nullptr;
}

//------------------------------------------------------------------------------
void vtkReliefTextureCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "ConeMap: " << this->ConeMap << "\n";
  os << indent << "BakedDepthScale: " << this->BakedDepthScale << "\n";
  os << indent << "FloatTextures: " << (this->FloatTextures ? "yes" : "no") << "\n";
  os << indent << "DepthBits: " << this->DepthBits << "\n";
  os << indent << "NormalsStored: " << (this->NormalsStored ? "yes" : "no") << "\n";
  os << indent << "NormalMismatch: " << this->NormalMismatch << "\n";
  os << indent << "NormalsFromDepth: " << (this->NormalsFromDepth ? "yes" : "no") << "\n";
  os << indent << "ConesUploaded: " << (this->ConesUploaded ? "yes" : "no") << "\n";
  os << indent << "MomentsUploaded: " << (this->MomentsUploaded ? "yes" : "no") << "\n";
  os << indent << "MomentFirstLevel: " << this->MomentFirstLevel << "\n";
  os << indent << "UploadedBytes: " << this->UploadedBytes << "\n";
  os << indent << "Ready: " << (this->Ready ? "yes" : "no") << "\n";
}
