// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightSetTexture.h"

#include "Luminance.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkLightSetTexture);

//------------------------------------------------------------------------------
vtkLightSetTexture::vtkLightSetTexture() = default;

//------------------------------------------------------------------------------
vtkLightSetTexture::~vtkLightSetTexture() = default;

//------------------------------------------------------------------------------
bool vtkLightSetTexture::Update(vtkOpenGLRenderWindow* renWin, vtkImageData* lights)
{
  this->HasLightSet = lights != nullptr && this->Upload(renWin, lights);
  return lights == nullptr || this->HasLightSet;
}

//------------------------------------------------------------------------------
bool vtkLightSetTexture::Upload(vtkOpenGLRenderWindow* renWin, vtkImageData* lights)
{
  vtkDataArray* values = lights->GetPointData()->GetScalars();
  if (values && values == this->Uploaded && values->GetMTime() <= this->UploadTime &&
    this->TextureObject && this->TextureObject->GetHandle() != 0 &&
    this->TextureObject->GetContext() == renWin)
  {
    return this->NumberOfLights > 0;
  }
  this->Uploaded = values;
  this->UploadTime = values ? values->GetMTime() : 0;
  this->NumberOfLights = 0;
  int dims[3];
  lights->GetDimensions(dims);
  if (!values || lights->GetNumberOfPoints() == 0)
  {
    // An empty image is what a light-set source leaves after it reported its own error.
    vtkErrorMacro(<< "The light set is empty: its source made no lights (see its error "
                     "above).");
    return false;
  }
  if (dims[1] != 2 || dims[0] < 1 || values->GetNumberOfComponents() < 3)
  {
    vtkErrorMacro(<< "The light set must be an N x 2 image with 3 or 4 components (row 0 "
                     "directions, row 1 irradiance). In ParaView: connect Mesolight Median Cut "
                     "Lights' second output (LightTexture) as Attach Relief Texture's Light Set. "
                     "In VTK: vtkMedianCutLights' output port 1.");
    return false;
  }
  // Sorted by luminance, strongest first, so the shader can stop at the first negligible light.
  struct Light
  {
    float Direction[3];
    float Irradiance[3];
    float Luminance;
  };
  std::vector<Light> sorted(static_cast<size_t>(dims[0]));
  for (int i = 0; i < dims[0]; ++i)
  {
    Light& light = sorted[static_cast<size_t>(i)];
    double direction[3];
    for (int c = 0; c < 3; ++c)
    {
      direction[c] = values->GetComponent(i, c);
      light.Irradiance[c] = static_cast<float>(values->GetComponent(dims[0] + i, c));
      if (!std::isfinite(direction[c]) || !std::isfinite(light.Irradiance[c]) ||
        light.Irradiance[c] < 0.0f)
      {
        vtkErrorMacro(<< "Light " << i
                      << " of the light set has a non-finite direction or a "
                         "negative or non-finite irradiance.");
        return false;
      }
    }
    if (vtkMath::Normalize(direction) <= 0.0)
    {
      vtkErrorMacro(<< "Light " << i << " of the light set has a zero direction.");
      return false;
    }
    for (int c = 0; c < 3; ++c)
    {
      light.Direction[c] = static_cast<float>(direction[c]);
    }
    light.Luminance = mesolight::Luminance(light.Irradiance);
  }
  // One texel per light along a row: a GPU takes as many lights as its widest texture.
  const int widest = vtkTextureObject::GetMaximumTextureSize(renWin);
  if (widest > 0 && dims[0] > widest)
  {
    vtkErrorMacro(<< "The light set has " << dims[0] << " lights; this GPU's textures hold at most "
                  << widest << ". Use fewer lights (vtkMedianCutLights::SetNumberOfLights).");
    return false;
  }
  std::sort(sorted.begin(), sorted.end(),
    [](const Light& a, const Light& b) { return a.Luminance > b.Luminance; });
  std::vector<float> texels(static_cast<size_t>(dims[0]) * 8);
  for (int i = 0; i < dims[0]; ++i)
  {
    const Light& light = sorted[static_cast<size_t>(i)];
    float* d = &texels[static_cast<size_t>(i) * 4];
    float* e = &texels[(static_cast<size_t>(dims[0]) + i) * 4];
    for (int c = 0; c < 3; ++c)
    {
      d[c] = light.Direction[c];
      e[c] = light.Irradiance[c];
    }
    d[3] = light.Luminance;
    e[3] = light.Luminance;
  }
  if (!this->TextureObject)
  {
    this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->TextureObject->SetContext(renWin);
  this->TextureObject->SetMinificationFilter(vtkTextureObject::Nearest);
  this->TextureObject->SetMagnificationFilter(vtkTextureObject::Nearest);
  if (!this->TextureObject->Create2DFromRaw(
        static_cast<unsigned int>(dims[0]), 2, 4, VTK_FLOAT, texels.data()))
  {
    vtkErrorMacro(<< "Could not create the light-set texture (" << dims[0] << " lights).");
    return false;
  }
  this->NumberOfLights = dims[0];
  this->MaximumLuminance = sorted.empty() ? 0.0f : sorted.front().Luminance;
  return true;
}

//------------------------------------------------------------------------------
void vtkLightSetTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->TextureObject)
  {
    this->TextureObject->ReleaseGraphicsResources(win);
  }
  this->Uploaded = nullptr;
}

//------------------------------------------------------------------------------
void vtkLightSetTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HasLightSet: " << (this->HasLightSet ? "yes" : "no") << "\n";
  os << indent << "NumberOfLights: " << this->NumberOfLights << "\n";
  os << indent << "MaximumLuminance: " << this->MaximumLuminance << "\n";
}
