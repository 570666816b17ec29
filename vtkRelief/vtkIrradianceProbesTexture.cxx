// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIrradianceProbesTexture.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkIrradianceProbesTexture);

//------------------------------------------------------------------------------
vtkIrradianceProbesTexture::vtkIrradianceProbesTexture() = default;

//------------------------------------------------------------------------------
vtkIrradianceProbesTexture::~vtkIrradianceProbesTexture() = default;

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::Update(vtkOpenGLRenderWindow* renWin, vtkImageData* probes)
{
  this->HasProbes = false;
  if (!probes)
  {
    return;
  }
  vtkDataArray* values = probes->GetPointData()->GetScalars();
  vtkDataArray* share = probes->GetFieldData()->GetArray(GetVisibleShareName());
  vtkDataArray* shareSize = probes->GetFieldData()->GetArray(GetVisibleShareSizeName());
  vtkDataArray* walls = probes->GetFieldData()->GetArray(GetWallShareName());
  const vtkMTimeType time =
    std::max({ probes->GetMTime(), values ? values->GetMTime() : 0, share ? share->GetMTime() : 0,
      shareSize ? shareSize->GetMTime() : 0, walls ? walls->GetMTime() : 0 });
  if (probes == this->UploadedImage && values == this->Uploaded && time <= this->UploadTime)
  {
    if (!this->Valid)
    {
      return; // reported when it was first seen
    }
    if (this->TextureObject && this->TextureObject->GetHandle() != 0 &&
      this->TextureObject->GetContext() == renWin && this->ShareTexture &&
      this->ShareTexture->GetHandle() != 0 && this->ShareTexture->GetContext() == renWin)
    {
      this->HasProbes = true;
      return;
    }
  }
  this->UploadedImage = probes;
  this->Uploaded = values;
  this->UploadTime = time;
  this->Valid = false;
  int dims[3];
  probes->GetDimensions(dims);
  const char* const layout = " The irradiance probes must be a (9 x Nu) x Nv image of RGB float "
                             "SH9 coefficients (coefficient k of probe (i, j) at pixel (9 i + k, "
                             "j)); the relief is drawn without them.";
  if (!values || dims[0] < 1 || dims[1] < 1 || values->GetNumberOfTuples() == 0)
  {
    vtkErrorMacro(<< "The irradiance probes image is empty." << layout);
    return;
  }
  if (dims[0] % 9 != 0)
  {
    vtkErrorMacro(<< "The irradiance probes image is " << dims[0]
                  << " pixels wide, not a multiple of 9." << layout);
    return;
  }
  if (dims[2] != 1 || values->GetNumberOfComponents() < 3 ||
    values->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    vtkErrorMacro(<< "The irradiance probes image has " << values->GetNumberOfComponents()
                  << " components and " << dims[2] << " slices (3 components and 1 slice "
                  << "expected)." << layout);
    return;
  }
  const int nu = dims[0] / 9;
  const int nv = dims[1];
  // Seven RGBA blocks of Nu x Nv texels, each channel one coefficient of one colour channel:
  // blocks 0-1 red's L_0..L_7, 2-3 green's, 4-5 blue's, 6 (red, green, blue) L_8. The shader then
  // evaluates each colour channel as two four-wide dot products (seven fetches, not nine).
  // Blocks 7-8: the scene's visibility of lights 0-3 and 4-7 from the probe (a fourth
  // component), 1 without it.
  std::vector<float> texels(static_cast<size_t>(nu) * nv * Blocks * 4, 0.0f);
  std::fill(texels.begin() + static_cast<std::ptrdiff_t>(nu) * nv * 7 * 4, texels.end(), 1.0f);
  const bool visibility = values->GetNumberOfComponents() >= 4;
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      for (int k = 0; k < 9; ++k)
      {
        const vtkIdType pixel = static_cast<vtkIdType>(j) * dims[0] + 9 * i + k;
        for (int c = 0; c < 3; ++c)
        {
          const double value = values->GetComponent(pixel, c);
          if (!std::isfinite(value))
          {
            vtkErrorMacro(<< "Coefficient " << k << " of irradiance probe (" << i << ", " << j
                          << ") is not finite (component " << c << ")." << layout);
            return;
          }
          const int block = k < 8 ? 2 * c + k / 4 : 6;
          const int channel = k < 8 ? k % 4 : c;
          texels[((static_cast<size_t>(block) * nv + j) * nu + i) * 4 + channel] =
            static_cast<float>(value);
        }
        if (visibility && k < 8)
        {
          const double value = values->GetComponent(pixel, 3);
          if (!(value >= 0.0 && value <= MaxLightFactor))
          {
            vtkErrorMacro(<< "The factor of light " << k << " at irradiance probe (" << i << ", "
                          << j << ") is " << value << ", not in [0, " << MaxLightFactor << "]."
                          << layout);
            return;
          }
          texels[((static_cast<size_t>(7 + k / 4) * nv + j) * nu + i) * 4 + k % 4] =
            static_cast<float>(value);
        }
      }
    }
  }
  if (!this->TextureObject)
  {
    this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->TextureObject->SetContext(renWin);
  this->TextureObject->SetMinificationFilter(vtkTextureObject::Linear);
  this->TextureObject->SetMagnificationFilter(vtkTextureObject::Linear);
  this->TextureObject->SetWrapS(vtkTextureObject::ClampToEdge);
  this->TextureObject->SetWrapT(vtkTextureObject::ClampToEdge);
  if (!this->TextureObject->Create2DFromRaw(static_cast<unsigned int>(nu),
        static_cast<unsigned int>(Blocks * nv), 4, VTK_FLOAT, texels.data()))
  {
    vtkErrorMacro(<< "Could not create the irradiance probes texture (" << nu << " x " << nv
                  << " probes); the relief is drawn without them.");
    return;
  }
  if (!this->UploadVisibleShare(renWin, share, shareSize, walls))
  {
    return;
  }
  this->GridSize[0] = nu;
  this->GridSize[1] = nv;
  this->Valid = true;
  this->HasProbes = true;
}

//------------------------------------------------------------------------------
bool vtkIrradianceProbesTexture::UploadVisibleShare(
  vtkOpenGLRenderWindow* renWin, vtkDataArray* share, vtkDataArray* shareSize, vtkDataArray* walls)
{
  // Without a map: one texel of (1, 1, 1, 1), the relief unoccluded (the shader reads it all the
  // same). A map of pairs (V, S) gets the seen share Vs = V: the series at the point's own share.
  // The fourth value, light 0's share past the relief's shadow, is 1 unless given.
  std::vector<float> texels(4, 1.0f);
  int size[2] = { 1, 1 };
  this->HasVisibleShare = false;
  this->HasLightShadow = false;
  this->WallLevels = 0;
  this->ShareRows = 1;
  if (share || shareSize)
  {
    const char* const layout =
      " The relief's visible share must be a field-data array of W x H "
      "pairs, triples or quadruples in [0, 1] (row-major, row 0 at v ~ 0) with a "
      "2-value array (W, H); the relief is drawn without the probes.";
    const int components = share ? share->GetNumberOfComponents() : 0;
    if (!share || !shareSize || shareSize->GetNumberOfValues() != 2 || components < 2 ||
      components > 4)
    {
      vtkErrorMacro(<< "The relief's visible share is incomplete." << layout);
      return false;
    }
    const double w = shareSize->GetComponent(0, 0), h = shareSize->GetComponent(1, 0);
    if (!(w >= 1.0 && h >= 1.0 && w <= 16384.0 && h <= 16384.0) ||
      static_cast<double>(share->GetNumberOfTuples()) != w * h)
    {
      vtkErrorMacro(<< "The relief's visible share holds " << share->GetNumberOfTuples()
                    << " values for a " << w << " x " << h << " grid." << layout);
      return false;
    }
    size[0] = static_cast<int>(w);
    size[1] = static_cast<int>(h);
    // The side walls' rows below the map's (4 walls x levels rows of W cells), when given whole.
    int levels = 0;
    if (walls)
    {
      const vtkIdType wallRow = 4 * static_cast<vtkIdType>(size[0]);
      if (walls->GetNumberOfComponents() != components || walls->GetNumberOfTuples() == 0 ||
        walls->GetNumberOfTuples() % wallRow != 0 || walls->GetNumberOfTuples() / wallRow > 64)
      {
        vtkErrorMacro(<< "The relief's side-wall share holds " << walls->GetNumberOfTuples()
                      << " tuples of " << walls->GetNumberOfComponents() << " values, not 4 x D x "
                      << size[0] << " (D <= 64) of " << components << "." << layout);
        return false;
      }
      levels = static_cast<int>(walls->GetNumberOfTuples() / wallRow);
    }
    const vtkIdType cells = share->GetNumberOfTuples();
    texels.assign(4 * static_cast<size_t>(size[0]) * (size[1] + 4 * levels), 1.0f);
    for (vtkIdType t = 0; t < cells + (levels > 0 ? walls->GetNumberOfTuples() : 0); ++t)
    {
      vtkDataArray* from = t < cells ? share : walls;
      const vtkIdType tuple = t < cells ? t : t - cells;
      for (int c = 0; c < std::max(components, 3); ++c)
      {
        const double value = from->GetComponent(tuple, c < components ? c : 0);
        if (!(value >= 0.0 && value <= 1.0))
        {
          vtkErrorMacro(<< "The relief's visible share " << value << " at " << t
                        << " is not in [0, 1]." << layout);
          return false;
        }
        texels[4 * static_cast<size_t>(t) + c] = static_cast<float>(value);
      }
    }
    this->HasVisibleShare = true;
    this->HasLightShadow = components == 4;
    this->WallLevels = levels;
    this->ShareRows = size[1];
    size[1] += 4 * levels;
  }
  if (!this->ShareTexture)
  {
    this->ShareTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->ShareTexture->SetContext(renWin);
  this->ShareTexture->SetMinificationFilter(vtkTextureObject::Linear);
  this->ShareTexture->SetMagnificationFilter(vtkTextureObject::Linear);
  this->ShareTexture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->ShareTexture->SetWrapT(vtkTextureObject::ClampToEdge);
  if (!this->ShareTexture->Create2DFromRaw(static_cast<unsigned int>(size[0]),
        static_cast<unsigned int>(size[1]), 4, VTK_FLOAT, texels.data()))
  {
    vtkErrorMacro(<< "Could not create the relief's visible-share texture (" << size[0] << " x "
                  << size[1] << "); the relief is drawn without the probes.");
    this->HasVisibleShare = false;
    this->HasLightShadow = false;
    this->WallLevels = 0;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::Activate()
{
  this->TextureObject->Activate();
  this->ShareTexture->Activate();
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::Deactivate()
{
  this->TextureObject->Deactivate();
  this->ShareTexture->Deactivate();
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::SetUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("mlIrradianceProbes", this->TextureObject->GetTextureUnit());
  program->SetUniformi("mlReliefVisibleShare", this->ShareTexture->GetTextureUnit());
  program->SetUniformi("mlReliefLightShadow", this->HasLightShadow ? 1 : 0);
  program->SetUniformi("mlReliefWallLevels", this->WallLevels);
  program->SetUniformf("mlReliefShareRows", static_cast<float>(this->ShareRows));
  const float probeGrid[2] = { static_cast<float>(this->GridSize[0]),
    static_cast<float>(this->GridSize[1]) };
  program->SetUniform2f("mlProbeGrid", probeGrid);
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->TextureObject)
  {
    this->TextureObject->ReleaseGraphicsResources(win);
  }
  if (this->ShareTexture)
  {
    this->ShareTexture->ReleaseGraphicsResources(win);
  }
  this->Uploaded = nullptr;
  this->UploadedImage = nullptr;
  this->Valid = false;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkIrradianceProbesTexture::GetTextureObject()
{
  return this->TextureObject;
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::AttachVisibleShare(
  vtkDataObject* probes, vtkDataArray* share, int w, int h)
{
  if (!probes || !share)
  {
    vtkGenericWarningMacro(
      "AttachVisibleShare: no " << (probes ? "share map" : "probes") << " given; nothing attached");
    return;
  }
  share->SetName(GetVisibleShareName());
  vtkNew<vtkIntArray> size;
  size->SetName(GetVisibleShareSizeName());
  size->InsertNextValue(w);
  size->InsertNextValue(h);
  probes->GetFieldData()->AddArray(share);
  probes->GetFieldData()->AddArray(size);
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HasProbes: " << (this->HasProbes ? "yes" : "no") << "\n";
  os << indent << "GridSize: " << this->GridSize[0] << " x " << this->GridSize[1] << "\n";
  os << indent << "HasVisibleShare: " << (this->HasVisibleShare ? "yes" : "no") << "\n";
  os << indent << "HasLightShadow: " << (this->HasLightShadow ? "yes" : "no") << "\n";
  os << indent << "WallLevels: " << this->WallLevels << "\n";
}
