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
#include "vtkTextureObject.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cctype>
#include <cmath>
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
} // namespace

//------------------------------------------------------------------------------
vtkReliefTextureCache::vtkReliefTextureCache()
{
  this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  this->Pyramid = vtkSmartPointer<vtkMinDepthPyramidTexture>::New();
}

//------------------------------------------------------------------------------
vtkReliefTextureCache::~vtkReliefTextureCache() = default;

//------------------------------------------------------------------------------
bool vtkReliefTextureCache::GetConePacked() const
{
  return this->ConeMap != vtkReliefProperty::NoConeMap;
}

//------------------------------------------------------------------------------
bool vtkReliefTextureCache::Update(
  vtkOpenGLRenderWindow* renWin, vtkImageData* image, bool mipmaps, bool needPyramid)
{
  // Upload again when the image changed, or when mipmaps or the pyramid are newly needed.
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (scalars && scalars == this->Uploaded && scalars->GetMTime() <= this->UploadTime &&
    this->TextureObject->GetHandle() != 0 && this->TextureObject->GetContext() == renWin &&
    this->UploadedWithMipmaps == mipmaps &&
    (!needPyramid || this->Pyramid->GetNumberOfLevels() > 0))
  {
    return this->Ready;
  }
  this->Uploaded = scalars;
  this->UploadTime = scalars ? scalars->GetMTime() : 0;
  this->Ready = false;

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
  const bool conePacked = this->GetConePacked();
  const vtkIdType count = static_cast<vtkIdType>(dims[0]) * dims[1];
  std::vector<float> texels(static_cast<size_t>(count) * 4);
  std::vector<float> depth(needPyramid ? static_cast<size_t>(count) : 0);
  for (vtkIdType i = 0; i < count; ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      double value = scalars->GetComponent(i, c);
      if (bytes)
      {
        value /= 255.0;
      }
      if (!std::isfinite(value))
      {
        vtkErrorMacro(<< "The relief texture has a non-finite value at texel " << i
                      << " (component " << c << "); NaN or Inf cannot be rendered.");
        return false;
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
    if (needPyramid)
    {
      depth[static_cast<size_t>(i)] = texels[static_cast<size_t>(i) * 4 + 3];
    }
  }

  this->TextureObject->SetContext(renWin);
  this->TextureObject->SetGenerateMipmap(mipmaps);
  this->TextureObject->SetMinificationFilter(
    mipmaps ? vtkTextureObject::LinearMipmapLinear : vtkTextureObject::Linear);
  this->TextureObject->SetMagnificationFilter(vtkTextureObject::Linear);
  // vtkTextureObject's MaxLevel defaults to 0, which clamps every lookup to the base level
  // whatever the filter and textureLod ask for: open it to the whole mip chain.
  int levels = 1;
  while ((std::max(dims[0], dims[1]) >> levels) > 0)
  {
    ++levels;
  }
  this->TextureObject->SetBaseLevel(0);
  this->TextureObject->SetMaxLevel(mipmaps ? levels - 1 : 0);
  this->UploadedWithMipmaps = mipmaps;
  if (!this->TextureObject->Create2DFromRaw(static_cast<unsigned int>(dims[0]),
        static_cast<unsigned int>(dims[1]), 4, VTK_FLOAT, texels.data()))
  {
    vtkErrorMacro(<< "Could not create a " << dims[0] << "x" << dims[1]
                  << " float RGBA texture (too large for this OpenGL implementation?).");
    return false;
  }
  if (mipmaps)
  {
    // Create2DFromRaw uploads level 0 only (VTK 9.1 and 9.2 generate mipmaps for cube maps
    // alone, whatever SetGenerateMipmap says); the coarser levels are made here.
    this->TextureObject->Activate();
    glGenerateMipmap(GL_TEXTURE_2D);
    this->TextureObject->Deactivate();
    vtkOpenGLCheckErrorMacro("failed generating the relief texture's mipmaps");
  }
  this->Size[0] = dims[0];
  this->Size[1] = dims[1];
  this->BakedDepthScale = -1.0;
  if (vtkDataArray* baked = image->GetFieldData()->GetArray("MesolightDepthScale"))
  {
    if (baked->GetNumberOfTuples() > 0)
    {
      this->BakedDepthScale = baked->GetComponent(0, 0);
    }
  }
  this->Pyramid->Reset();
  if (needPyramid && !this->Pyramid->Upload(renWin, depth, dims[0], dims[1]))
  {
    return false;
  }
  this->Ready = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefTextureCache::ReleaseGraphicsResources(vtkWindow* win)
{
  this->TextureObject->ReleaseGraphicsResources(win);
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
  os << indent << "Ready: " << (this->Ready ? "yes" : "no") << "\n";
}
