// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCompositeLightFieldMapper.h"

#include "vtkLightFieldMapper.h"
#include "vtkVirtualLightField.h"

#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectLeaves.h"
#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h" // before vtkCompositeMapperHelper2.h: VTK 9.1's uses GLenum undeclared

#include "vtkCompositeMapperHelper2.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

//==============================================================================
// The helper that draws the blocks: vtkLightFieldMapper's shader edits, with the parent's atlas.
class vtkCompositeLightFieldMapperHelper : public vtkCompositeMapperHelper2
{
public:
  static vtkCompositeLightFieldMapperHelper* New();
  vtkTypeMacro(vtkCompositeLightFieldMapperHelper, vtkCompositeMapperHelper2);

protected:
  vtkCompositeLightFieldMapperHelper() = default;
  ~vtkCompositeLightFieldMapperHelper() override = default;

  vtkCompositeLightFieldMapper* Owner() const
  {
    return static_cast<vtkCompositeLightFieldMapper*>(this->Parent);
  }

  void RenderPieceStart(vtkRenderer* ren, vtkActor* actor) override
  {
    this->Radiance = this->Owner()->PrepareAtlas(ren);
    if (this->Radiance)
    {
      this->Owner()->AtlasTexture->Activate();
    }
    this->Superclass::RenderPieceStart(ren, actor);
  }

  void RenderPieceFinish(vtkRenderer* ren, vtkActor* actor) override
  {
    this->Superclass::RenderPieceFinish(ren, actor);
    if (this->Radiance)
    {
      this->Owner()->AtlasTexture->Deactivate();
    }
  }

  // The atlas coordinates are our own attribute: the helper uploads "tcoord" only when the
  // actor has a texture.
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* actor, vtkCompositeMapperHelperData* hdata,
    vtkIdType& voffset, std::vector<unsigned char>& colors, std::vector<float>& norms) override
  {
    this->Superclass::AppendOneBufferObject(ren, actor, hdata, voffset, colors, norms);
    vtkDataArray* tcoords =
      hdata->Data->GetPointData()->GetArray(vtkVirtualLightField::GetAtlasCoordinatesName());
    if (!tcoords || tcoords->GetNumberOfComponents() != 2)
    {
      return;
    }
    vtkIdType offset = 0;
    vtkIdType total = 0;
    // Reused blocks (the superclass found their vertices already uploaded) keep ours too.
    if (!this->VBOs->ArrayExists("mlAtlasTC", tcoords, offset, total) || offset != voffset)
    {
      this->VBOs->AppendDataArray("mlAtlasTC", tcoords, VTK_FLOAT);
    }
  }

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override
  {
    const auto built = this->BuiltRadiance.find(&cellBO);
    const bool changed = built == this->BuiltRadiance.end() || built->second != this->Radiance;
    return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor) || changed;
  }

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override
  {
    this->BuiltRadiance[this->LastBoundBO] = this->Radiance;
    if (!this->Radiance)
    {
      this->Superclass::ReplaceShaderValues(shaders, ren, actor);
      return;
    }
    vtkLightFieldMapper::ReplaceRadianceShaderValues(
      shaders, [&]() { this->Superclass::ReplaceShaderValues(shaders, ren, actor); });
  }

  void SetMapperShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override
  {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
    if (!this->Radiance || !cellBO.Program)
    {
      return;
    }
    vtkLightFieldMapper::RadianceUniforms uniforms;
    uniforms.AtlasUnit = this->Owner()->AtlasTexture->GetTextureUnit();
    uniforms.ScreenUnit = uniforms.AtlasUnit; // no screen-space pass: never read (size 0)
    uniforms.Exposure = static_cast<float>(this->Owner()->GetEffectiveExposure());
    uniforms.ToneMap = this->Owner()->GetToneMap();
    vtkLightFieldMapper::SetRadianceUniforms(cellBO.Program, uniforms);
  }

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->BuiltRadiance.clear();
    this->Superclass::ReleaseGraphicsResources(window);
  }

  bool Radiance = false;                     // this draw replaces VTK's lighting
  std::map<const void*, bool> BuiltRadiance; // per cellBO: the variant its shader was built for

private:
  vtkCompositeLightFieldMapperHelper(const vtkCompositeLightFieldMapperHelper&) = delete;
  void operator=(const vtkCompositeLightFieldMapperHelper&) = delete;
};

vtkStandardNewMacro(vtkCompositeLightFieldMapperHelper);

//==============================================================================
vtkStandardNewMacro(vtkCompositeLightFieldMapper);

//------------------------------------------------------------------------------
vtkCompositeLightFieldMapper::vtkCompositeLightFieldMapper() = default;
vtkCompositeLightFieldMapper::~vtkCompositeLightFieldMapper() = default;

//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkCompositeLightFieldMapper::CreateHelper()
{
  return vtkCompositeLightFieldMapperHelper::New();
}

//------------------------------------------------------------------------------
void vtkCompositeLightFieldMapper::Render(vtkRenderer* ren, vtkActor* actor)
{
  this->CurrentAtlas = nullptr;
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  const std::vector<vtkDataObject*> blocks = mesolight::DataObjectLeaves(input);
  for (vtkDataObject* block : blocks)
  {
    if (!this->CurrentAtlas)
    {
      this->CurrentAtlas = vtkVirtualLightField::GetAttachedAtlas(block, this->CurrentAtlasSize);
    }
  }
  // An empty piece (an MPI rank without cells) has nothing to warn about.
  bool anyCells = false;
  for (vtkDataObject* block : blocks)
  {
    auto* poly = vtkPolyData::SafeDownCast(block);
    anyCells = anyCells || (poly && poly->GetNumberOfCells() > 0);
  }
  this->EffectiveExposure = this->Exposure;
  if (this->CurrentAtlas && this->AutoExposure)
  {
    if (this->KeyAtlas != this->CurrentAtlas || this->KeyTime != this->CurrentAtlas->GetMTime())
    {
      this->AtlasLogAverage = LogAverageLuminance(
        this->CurrentAtlas->GetPointer(0), this->CurrentAtlas->GetNumberOfTuples());
      this->KeyAtlas = this->CurrentAtlas;
      this->KeyTime = this->CurrentAtlas->GetMTime();
    }
    if (this->AtlasLogAverage > 0.0)
    {
      this->EffectiveExposure = this->Exposure * 0.18 / this->AtlasLogAverage;
    }
  }
  if (!this->CurrentAtlas && anyCells && !this->WarnedNoAtlas)
  {
    vtkWarningMacro("The input carries no light field atlas (field data '"
      << vtkVirtualLightField::GetAtlasName() << "' of Virtual Light Field's output): drawn "
      << "the ordinary way.");
    this->WarnedNoAtlas = true;
  }
  this->Superclass::Render(ren, actor);
}

//------------------------------------------------------------------------------
double vtkCompositeLightFieldMapper::LogAverageLuminance(const float* rgba, vtkIdType texels)
{
  double sum = 0.0;
  vtkIdType count = 0;
  for (vtkIdType i = 0; i < texels; ++i)
  {
    const float* p = rgba + 4 * i;
    const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    if (y > 0.0 && std::isfinite(y))
    {
      sum += std::log(y);
      ++count;
    }
  }
  return count > 0 ? std::exp(sum / static_cast<double>(count)) : 0.0;
}

//------------------------------------------------------------------------------
bool vtkCompositeLightFieldMapper::PrepareAtlas(vtkRenderer* ren)
{
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!this->CurrentAtlas || !window)
  {
    return false;
  }
  if (this->AtlasTexture && this->AtlasTexture->GetHandle() != 0 &&
    this->AtlasTexture->GetContext() == window && this->UploadedAtlas == this->CurrentAtlas &&
    this->UploadedTime == this->CurrentAtlas->GetMTime())
  {
    return true; // uploaded once per field
  }
  if (!vtkLightFieldMapper::UploadAtlasTexture(this->AtlasTexture, window,
        this->CurrentAtlasSize[0], this->CurrentAtlasSize[1], this->CurrentAtlas->GetPointer(0)))
  {
    vtkErrorMacro(<< "could not upload the light field's " << this->CurrentAtlasSize[0] << "x"
                  << this->CurrentAtlasSize[1] << " texture atlas");
    this->UploadedAtlas = nullptr;
    return false;
  }
  this->UploadedAtlas = this->CurrentAtlas;
  this->UploadedTime = this->CurrentAtlas->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
void vtkCompositeLightFieldMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  if (this->AtlasTexture)
  {
    this->AtlasTexture->ReleaseGraphicsResources(win);
  }
  this->UploadedAtlas = nullptr;
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkCompositeLightFieldMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "AutoExposure: " << this->AutoExposure << "\n";
  os << indent << "EffectiveExposure: " << this->EffectiveExposure << "\n";
  os << indent << "ToneMap: " << (this->ToneMap == Reinhard ? "Reinhard" : "Clamp") << "\n";
  os << indent << "Atlas: " << this->CurrentAtlasSize[0] << "x" << this->CurrentAtlasSize[1]
     << (this->CurrentAtlas ? "" : " (none)") << "\n";
}
