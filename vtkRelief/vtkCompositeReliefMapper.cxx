// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCompositeReliefMapper.h"

#include "vtkAttachReliefTexture.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataObjectLeaves.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLVertexBufferObjectGroup.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefGeometryCache.h"
#include "vtkReliefShading.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkTexture.h"
#include "vtk_glew.h" // before vtkCompositeMapperHelper2.h: VTK 9.1's uses GLenum undeclared

#include "vtkCompositeMapperHelper2.h"

#include <algorithm>
#include <vector>

//==============================================================================
// The helper that draws the blocks (internal to this mapper, as in ParaView's
// EmbossingRepresentations): a vtkOpenGLPolyDataMapper whose relief steps are the parent's
// vtkReliefShading, with the parent's vtkReliefProperty: the same calls vtkReliefMapper makes.
class vtkCompositeReliefMapperHelper : public vtkCompositeMapperHelper2
{
public:
  static vtkCompositeReliefMapperHelper* New();
  vtkTypeMacro(vtkCompositeReliefMapperHelper, vtkCompositeMapperHelper2);

protected:
  vtkCompositeReliefMapperHelper() = default;
  ~vtkCompositeReliefMapperHelper() override = default;

  vtkReliefShading* Shading() const
  {
    return static_cast<vtkCompositeReliefMapper*>(this->Parent)->Shading;
  }

  void RenderPieceStart(vtkRenderer* ren, vtkActor* actor) override
  {
    auto* parent = static_cast<vtkCompositeReliefMapper*>(this->Parent);
    this->ReadyToDraw = false;
    // What decides whether the frame can be drawn, for BeginFrame (not the mapper, nor the actor
    // and its properties, which ParaView modifies as it renders).
    vtkTexture* albedo = actor->GetTexture();
    std::vector<vtkObject*> frameInputs{ parent->GetReliefProperty(), parent->CurrentReliefTexture,
      parent->CurrentLightSet, parent->IrradianceProbesData, albedo,
      albedo ? albedo->GetInput() : nullptr };
    for (const auto& entry : this->Data)
    {
      frameInputs.push_back(entry.first);
    }
    if (!this->Shading()->BeginFrame(this, parent->CurrentReliefTexture, frameInputs))
    {
      return;
    }
    // Every block must carry a relief (texture coordinates); prepared copies are made once.
    vtkReliefGeometryCache* geometry = this->Shading()->GetGeometryCache();
    std::vector<vtkPolyData*> inputs;
    // The blocks share one vertex buffer: the curved march only when every block is curved.
    bool curved = !this->Data.empty();
    for (const auto& entry : this->Data)
    {
      inputs.push_back(entry.first);
      vtkPolyData* prepared = geometry->Prepare(entry.first);
      if (!prepared)
      {
        this->Shading()->FrameFailed();
        return;
      }
      curved = curved && vtkReliefGeometryCache::IsCurved(prepared);
    }
    geometry->KeepOnly(inputs);
    this->Shading()->SetCurvedGeometry(curved);
    if (!this->Shading()->StartDraw(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()),
          parent->GetReliefProperty(), parent->CurrentReliefTexture, parent->CurrentLightSet,
          parent->IrradianceProbesData, actor))
    {
      this->Shading()->FrameFailed();
      return;
    }
    this->Superclass::RenderPieceStart(ren, actor);
    this->ReadyToDraw = true;
  }

  void RenderPieceDraw(vtkRenderer* ren, vtkActor* actor) override
  {
    if (this->ReadyToDraw)
    {
      this->Superclass::RenderPieceDraw(ren, actor);
    }
  }

  void RenderPieceFinish(vtkRenderer* ren, vtkActor* actor) override
  {
    if (this->ReadyToDraw)
    {
      this->Superclass::RenderPieceFinish(ren, actor);
      this->Shading()->FinishDraw();
    }
    this->ReadyToDraw = false;
  }

  // Draws each block's prepared copy (triangles, normals, tangents) and adds the attributes
  // the helper does not upload itself: tangents, and the relief texture coordinates (the
  // helper uploads "tcoord" only when the actor has a texture).
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* actor, vtkCompositeMapperHelperData* hdata,
    vtkIdType& voffset, std::vector<unsigned char>& colors, std::vector<float>& norms) override
  {
    vtkPolyData* source = hdata->Data;
    vtkPolyData* prepared = this->Shading()->GetGeometryCache()->Prepare(source);
    if (!prepared)
    {
      this->Superclass::AppendOneBufferObject(ren, actor, hdata, voffset, colors, norms);
      return;
    }
    hdata->Data = prepared; // same points as the source, triangulated
    this->Superclass::AppendOneBufferObject(ren, actor, hdata, voffset, colors, norms);
    hdata->Data = source;
    vtkDataArray* tangents = prepared->GetPointData()->GetTangents();
    vtkDataArray* tcoords =
      prepared->GetPointData()->GetArray(vtkReliefGeometryCache::GetReliefTCoordsName());
    vtkIdType offset = 0;
    vtkIdType total = 0;
    // Reused blocks (the superclass found their vertices already uploaded) keep ours too.
    if (!this->VBOs->ArrayExists("tangentMC", tangents, offset, total) || offset != voffset)
    {
      this->VBOs->AppendDataArray("tangentMC", tangents, VTK_FLOAT);
    }
    if (!this->VBOs->ArrayExists("mlTCoordMC", tcoords, offset, total) || offset != voffset)
    {
      this->VBOs->AppendDataArray("mlTCoordMC", tcoords, VTK_FLOAT);
    }
    vtkDataArray* quadrics =
      prepared->GetPointData()->GetArray(vtkReliefGeometryCache::GetReliefQuadricsName());
    if (quadrics &&
      (!this->VBOs->ArrayExists("mlQuadricMC", quadrics, offset, total) || offset != voffset))
    {
      this->VBOs->AppendDataArray("mlQuadricMC", quadrics, VTK_FLOAT);
    }
  }

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override
  {
    return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor) ||
      this->Shading()->ShaderKeyChanged(&cellBO);
  }

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override
  {
    std::string vs = shaders[vtkShader::Vertex]->GetSource();
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    this->Shading()->ReplaceShaderValuesBefore(
      vs, fs, this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity == 0);
    shaders[vtkShader::Vertex]->SetSource(vs);
    shaders[vtkShader::Fragment]->SetSource(fs);
    this->Superclass::ReplaceShaderValues(shaders, ren, actor);
    fs = shaders[vtkShader::Fragment]->GetSource();
    this->Shading()->ReplaceShaderValuesAfter(fs, this->LastBoundBO);
    shaders[vtkShader::Fragment]->SetSource(fs);
  }

  void SetMapperShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override
  {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
    this->Shading()->SetShaderParameters(cellBO.Program, ren, actor);
  }

  bool ReadyToDraw = false;

private:
  vtkCompositeReliefMapperHelper(const vtkCompositeReliefMapperHelper&) = delete;
  void operator=(const vtkCompositeReliefMapperHelper&) = delete;
};

vtkStandardNewMacro(vtkCompositeReliefMapperHelper);

//==============================================================================
vtkStandardNewMacro(vtkCompositeReliefMapper);

//------------------------------------------------------------------------------
vtkCompositeReliefMapper::vtkCompositeReliefMapper()
{
  this->Shading->SetMessageOwner(this);
  this->GetReliefProperty(); // the default settings, reporting to this mapper
}

//------------------------------------------------------------------------------
vtkCompositeReliefMapper::~vtkCompositeReliefMapper() = default;

//------------------------------------------------------------------------------
vtkCompositeMapperHelper2* vtkCompositeReliefMapper::CreateHelper()
{
  return vtkCompositeReliefMapperHelper::New();
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::SetReliefTextureData(vtkImageData* image)
{
  if (this->ReliefTextureData != image)
  {
    this->ReliefTextureData = image;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::SetLightSetData(vtkImageData* lights)
{
  if (this->LightSetData != lights)
  {
    this->LightSetData = lights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::SetIrradianceProbesData(vtkImageData* probes)
{
  if (this->IrradianceProbesData != probes)
  {
    this->IrradianceProbesData = probes;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::SetRadianceHook(vtkReliefRadianceHook* hook)
{
  if (this->Shading->SetRadianceHook(hook))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkReliefRadianceHook* vtkCompositeReliefMapper::GetRadianceHook()
{
  return this->Shading->GetRadianceHook();
}

//------------------------------------------------------------------------------
vtkImageData* vtkCompositeReliefMapper::GetIrradianceProbesData()
{
  return this->IrradianceProbesData;
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::Render(vtkRenderer* ren, vtkActor* actor)
{
  this->CurrentReliefTexture = this->ReliefTextureData;
  this->CurrentLightSet = this->LightSetData;
  vtkDataObject* input = this->GetInputDataObject(0, 0);
  const std::vector<vtkDataObject*> blocks = mesolight::DataObjectLeaves(input);
  for (vtkDataObject* block : blocks)
  {
    if (!this->CurrentReliefTexture)
    {
      this->CurrentReliefTexture = vtkAttachReliefTexture::GetAttachedReliefTexture(block);
    }
    if (!this->CurrentLightSet)
    {
      this->CurrentLightSet = vtkAttachReliefTexture::GetAttachedLightSet(block);
    }
  }
  this->Superclass::Render(ren, actor);
}

//------------------------------------------------------------------------------
vtkReliefProperty* vtkCompositeReliefMapper::GetReliefProperty()
{
  return this->Shading->GetReliefProperty();
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::SetReliefProperty(vtkReliefProperty* property)
{
  if (this->Shading->SetReliefProperty(property))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkCompositeReliefMapper::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Shading->GetReliefPropertyMTime());
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Shading->ReleaseGraphicsResources(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkCompositeReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->Shading->PrintForMapper(os, indent);
  os << indent << "ReliefTextureData: " << this->ReliefTextureData.Get() << "\n";
  os << indent << "LightSetData: " << this->LightSetData.Get() << "\n";
  os << indent << "IrradianceProbesData: " << this->IrradianceProbesData.Get() << "\n";
}
