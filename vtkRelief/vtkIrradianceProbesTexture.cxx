// SPDX-License-Identifier: BSD-3-Clause
#include "vtkIrradianceProbesTexture.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
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
  const vtkMTimeType time = std::max(probes->GetMTime(), values ? values->GetMTime() : 0);
  if (probes == this->UploadedImage && values == this->Uploaded && time <= this->UploadTime)
  {
    if (!this->Valid)
    {
      return; // reported when it was first seen
    }
    if (this->TextureObject && this->TextureObject->GetHandle() != 0 &&
      this->TextureObject->GetContext() == renWin)
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
  std::vector<float> texels(static_cast<size_t>(nu) * nv * 7 * 4, 0.0f);
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
        static_cast<unsigned int>(7 * nv), 4, VTK_FLOAT, texels.data()))
  {
    vtkErrorMacro(<< "Could not create the irradiance probes texture (" << nu << " x " << nv
                  << " probes); the relief is drawn without them.");
    return;
  }
  this->GridSize[0] = nu;
  this->GridSize[1] = nv;
  this->Valid = true;
  this->HasProbes = true;
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->TextureObject)
  {
    this->TextureObject->ReleaseGraphicsResources(win);
  }
  this->Uploaded = nullptr;
  this->UploadedImage = nullptr;
  this->Valid = false;
}

//------------------------------------------------------------------------------
void vtkIrradianceProbesTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HasProbes: " << (this->HasProbes ? "yes" : "no") << "\n";
  os << indent << "GridSize: " << this->GridSize[0] << " x " << this->GridSize[1] << "\n";
}
