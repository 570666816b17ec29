// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCompositeLightFieldMapper.h"

#include "vtkLightFieldCasterShadows.h"
#include "vtkLightFieldGatherFilter.h"
#include "vtkLightFieldMapper.h"
#include "vtkLightFieldShading.h"
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

#include "vtkFieldData.h"
#include "vtkNew.h"

#include "ObjectShadows.h"
#include "WalkthroughImage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

// mlToneMap (glsl/vtkLightFieldFS.glsl) takes this ToneMap as the actor's: the same values.
static_assert(
  vtkCompositeLightFieldMapper::Clamp == static_cast<int>(mesolight::ToneMapOperator::Clamp) &&
    vtkCompositeLightFieldMapper::Reinhard ==
      static_cast<int>(mesolight::ToneMapOperator::Reinhard),
  "vtkCompositeLightFieldMapper's tone maps and mesolight::ToneMapOperator share their values");

// The movable object's shadow maps (vtkLightFieldCasterShadows) and their texture.
struct vtkCompositeLightFieldMapper::ShadowData
{
  vtkNew<vtkLightFieldCasterShadows> Maps;
  unsigned long UploadedVersion = 0;
  vtkSmartPointer<vtkTextureObject> Texture;
};

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

  // 0: VTK's own shading; 1: the atlas (the scene, shadows); 2: per-vertex Radiance (a
  // gathered surface).
  enum Variant
  {
    Ordinary = 0,
    Atlas = 1,
    VertexRadiance = 2
  };

  void RenderPieceStart(vtkRenderer* ren, vtkActor* actor) override
  {
    vtkCompositeLightFieldMapper* owner = this->Owner();
    this->Radiance = owner->VertexRadiance ? VertexRadiance
      : owner->PrepareAtlas(ren)           ? Atlas
                                           : Ordinary;
    if (this->Radiance == VertexRadiance && !owner->PrepareBlankTexture(ren))
    {
      this->Radiance = Ordinary;
    }
    if (this->Radiance != Ordinary)
    {
      this->Texture(owner)->Activate();
    }
    this->Shadowing = this->Radiance == Atlas && owner->PrepareShadowTexture(ren);
    if (this->Shadowing)
    {
      owner->Shadows->Texture->Activate();
    }
    this->Superclass::RenderPieceStart(ren, actor);
  }

  void RenderPieceFinish(vtkRenderer* ren, vtkActor* actor) override
  {
    this->Superclass::RenderPieceFinish(ren, actor);
    if (this->Shadowing)
    {
      this->Owner()->Shadows->Texture->Deactivate();
    }
    if (this->Radiance != Ordinary)
    {
      this->Texture(this->Owner())->Deactivate();
    }
  }

  // The draw's 2D texture: the atlas, or for a gathered surface a blank one, so that every
  // sampler of the shared fragment code points at a 2D texture (none is read).
  vtkTextureObject* Texture(vtkCompositeLightFieldMapper* owner) const
  {
    return this->Radiance == Atlas ? owner->AtlasTexture.Get() : owner->BlankTexture.Get();
  }

  // The atlas coordinates are our own attribute: the helper uploads "tcoord" only when the
  // actor has a texture.
  void AppendOneBufferObject(vtkRenderer* ren, vtkActor* actor, vtkCompositeMapperHelperData* hdata,
    vtkIdType& voffset, std::vector<unsigned char>& colors, std::vector<float>& norms) override
  {
    this->Superclass::AppendOneBufferObject(ren, actor, hdata, voffset, colors, norms);
    vtkPointData* pd = hdata->Data->GetPointData();
    auto append = [&](const char* attribute, const char* name, int components)
    {
      vtkDataArray* array = pd->GetArray(name);
      if (!array || array->GetNumberOfComponents() != components)
      {
        return;
      }
      vtkIdType offset = 0;
      vtkIdType total = 0;
      // Reused blocks (the superclass found their vertices already uploaded) keep ours too.
      if (!this->VBOs->ArrayExists(attribute, array, offset, total) || offset != voffset)
      {
        this->VBOs->AppendDataArray(attribute, array, VTK_FLOAT);
      }
    };
    append("mlAtlasTC", vtkVirtualLightField::GetAtlasCoordinatesName(), 2);
    // Shadow receivers (glsl/vtkLightFieldShadowFS.glsl): unit-sphere point, normal, Kd.
    append("mlShadowPoint", vtkVirtualLightField::GetReceiverPointName(), 3);
    append("mlShadowNormal", vtkVirtualLightField::GetReceiverNormalName(), 3);
    append("mlShadowKd", vtkVirtualLightField::GetReceiverDiffuseName(), 3);
    if (this->Owner()->VertexRadiance)
    {
      append("mlVertexRadiance", "Radiance", 3);
    }
  }

  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override
  {
    const auto built = this->BuiltRadiance.find(&cellBO);
    const bool changed =
      built == this->BuiltRadiance.end() || built->second != this->ShaderVariant();
    return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor) || changed;
  }

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override
  {
    this->BuiltRadiance[this->LastBoundBO] = this->ShaderVariant();
    if (this->Radiance == Ordinary)
    {
      this->Superclass::ReplaceShaderValues(shaders, ren, actor);
      return;
    }
    vtkLightFieldShading::ReplaceRadianceShaderValues(
      shaders, [&]() { this->Superclass::ReplaceShaderValues(shaders, ren, actor); },
      this->Radiance == VertexRadiance, this->Shadowing);
  }

  void SetMapperShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override
  {
    this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
    if (this->Radiance == Ordinary || !cellBO.Program)
    {
      return;
    }
    vtkCompositeLightFieldMapper* owner = this->Owner();
    vtkLightFieldShading::RadianceUniforms uniforms;
    // A gathered surface reads no atlas (unit 0 is never sampled).
    uniforms.AtlasUnit = this->Texture(owner)->GetTextureUnit();
    uniforms.ScreenUnit = uniforms.AtlasUnit; // no screen-space pass: never read (size 0)
    uniforms.Exposure = static_cast<float>(owner->GetEffectiveExposure());
    uniforms.ToneMap = owner->GetToneMap();
    vtkLightFieldShading::SetRadianceUniforms(cellBO.Program, uniforms);
    vtkLightFieldShading::SetShadowUniforms(cellBO.Program,
      this->Shadowing ? &owner->Shadows->Maps->GetGpu() : nullptr,
      this->Shadowing ? owner->Shadows->Texture->GetTextureUnit() : uniforms.AtlasUnit);
  }

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->BuiltRadiance.clear();
    this->Superclass::ReleaseGraphicsResources(window);
  }

  int Radiance = Ordinary; // this draw's variant
  bool Shadowing = false;  // this draw reads the shadow maps (compiled in only then: see
                           // vtkLightFieldShading::ReplaceRadianceShaderValues)
  int ShaderVariant() const { return this->Radiance + (this->Shadowing ? 4 : 0); }
  std::map<const void*, int> BuiltRadiance; // per cellBO: the variant its shader was built for

private:
  vtkCompositeLightFieldMapperHelper(const vtkCompositeLightFieldMapperHelper&) = delete;
  void operator=(const vtkCompositeLightFieldMapperHelper&) = delete;
};

vtkStandardNewMacro(vtkCompositeLightFieldMapperHelper);

//==============================================================================
vtkStandardNewMacro(vtkCompositeLightFieldMapper);

//------------------------------------------------------------------------------
vtkCompositeLightFieldMapper::vtkCompositeLightFieldMapper()
  : Shadows(new ShadowData)
{
}

vtkCompositeLightFieldMapper::~vtkCompositeLightFieldMapper() = default;

//------------------------------------------------------------------------------
void vtkCompositeLightFieldMapper::SetShadowCaster(vtkPolyData* caster)
{
  if (this->Shadows->Maps->GetCaster() != caster)
  {
    this->Shadows->Maps->SetCaster(caster);
    this->Modified();
  }
}

vtkPolyData* vtkCompositeLightFieldMapper::GetShadowCaster()
{
  return this->Shadows->Maps->GetCaster();
}

void vtkCompositeLightFieldMapper::SetShadowMode(int mode)
{
  mode = std::min(std::max(mode, 0), 5);
  if (mode != this->ShadowMode)
  {
    this->ShadowMode = mode;
    this->Shadows->Maps->SetMode(mode);
    this->Modified();
  }
}

void vtkCompositeLightFieldMapper::SetShadowMapResolution(int texels)
{
  texels = std::min(std::max(texels, 16), 4096);
  if (texels != this->ShadowMapResolution)
  {
    this->ShadowMapResolution = texels;
    this->Shadows->Maps->SetResolution(texels);
    this->Modified();
  }
}

const char* vtkCompositeLightFieldMapper::GetShadowProblem()
{
  return this->Shadows->Maps->GetProblem();
}

//------------------------------------------------------------------------------
bool vtkCompositeLightFieldMapper::PrepareBlankTexture(vtkRenderer* ren)
{
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    return false;
  }
  if (this->BlankTexture && this->BlankTexture->GetHandle() != 0 &&
    this->BlankTexture->GetContext() == window)
  {
    return true;
  }
  const float blank[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  return vtkLightFieldShading::UploadAtlasTexture(this->BlankTexture, window, 1, 1, blank);
}

//------------------------------------------------------------------------------
bool vtkCompositeLightFieldMapper::PrepareShadowTexture(vtkRenderer* ren)
{
  ShadowData& d = *this->Shadows;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!d.Maps->HasShadows() || !window)
  {
    return false;
  }
  if (d.Texture && d.Texture->GetHandle() != 0 && d.Texture->GetContext() == window &&
    d.UploadedVersion == d.Maps->GetVersion())
  {
    return true; // uploaded once per rebuild of the maps
  }
  const mesolight::vlf::ShadowGpuData& gpu = d.Maps->GetGpu();
  if (!vtkLightFieldShading::UploadShadowTexture(d.Texture, window, gpu))
  {
    vtkErrorMacro(<< "could not upload the " << gpu.Width << "x" << gpu.Height
                  << " shadow map texture: the object casts no shadow");
    d.UploadedVersion = 0;
    return false;
  }
  d.UploadedVersion = d.Maps->GetVersion();
  return true;
}

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
  // An empty piece (an MPI rank without cells) has nothing to warn about. A surface shaded by
  // Light Field Gather (no atlas, per-vertex Radiance, the field's log-average luminance) is
  // drawn with its own radiance.
  bool anyCells = false;
  double gatheredLogAverage = -1.0;
  for (vtkDataObject* block : blocks)
  {
    auto* poly = vtkPolyData::SafeDownCast(block);
    anyCells = anyCells || (poly && poly->GetNumberOfCells() > 0);
    vtkDataArray* average = poly && poly->GetFieldData()
      ? vtkArrayDownCast<vtkDataArray>(
          poly->GetFieldData()->GetAbstractArray(vtkLightFieldGatherFilter::GetLogAverageName()))
      : nullptr;
    vtkDataArray* radiance = poly ? poly->GetPointData()->GetArray("Radiance") : nullptr;
    if (average && average->GetNumberOfValues() == 1 && radiance &&
      radiance->GetNumberOfComponents() == 3)
    {
      gatheredLogAverage = average->GetComponent(0, 0);
    }
  }
  const bool vertexRadiance = !this->CurrentAtlas && gatheredLogAverage >= 0.0;
  if (vertexRadiance && this->CheckGatheredPositions && input &&
    input->GetMTime() != this->MovedCheckTime)
  {
    // Said once per change of the input.
    this->MovedCheckTime = input->GetMTime();
    WarnIfMovedSinceGathered(input, this);
  }
  if (vertexRadiance != this->VertexRadiance)
  {
    this->VertexRadiance = vertexRadiance;
    this->Modified(); // the blocks' buffers gain or lose the radiance attribute
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
  else if (this->VertexRadiance && this->AutoExposure && gatheredLogAverage > 0.0)
  {
    this->EffectiveExposure = this->Exposure * 0.18 / gatheredLogAverage;
  }
  if (this->CurrentAtlas)
  {
    // The caster must come from the field drawn (a field's output carries its unit sphere).
    double centre[3], scale = 0.0;
    bool known = false;
    for (vtkDataObject* block : blocks)
    {
      known = known || vtkVirtualLightField::GetAttachedUnitSphere(block, centre, &scale);
    }
    if (known)
    {
      this->Shadows->Maps->SetFieldUnitSphere(centre, scale);
    }
    else
    {
      this->Shadows->Maps->ClearFieldUnitSphere();
    }
    this->Shadows->Maps->Update(this);
  }
  if (!this->CurrentAtlas && !this->VertexRadiance && anyCells && !this->WarnedNoAtlas)
  {
    vtkWarningMacro("The input carries no light field atlas (field data '"
      << vtkVirtualLightField::GetAtlasName() << "' of Virtual Light Field's output): drawn "
      << "the ordinary way.");
    this->WarnedNoAtlas = true;
  }
  this->Superclass::Render(ren, actor);
}

//------------------------------------------------------------------------------
bool vtkCompositeLightFieldMapper::WarnIfMovedSinceGathered(
  vtkDataObject* data, vtkObject* reporter)
{
  // A Transform after Light Field Gather moves the surface away from where its light was
  // gathered and turns its Radiance as a vector.
  double moved = 0.0;
  for (vtkDataObject* block : mesolight::DataObjectLeaves(data))
  {
    moved = std::max(moved, MovedSinceGathered(vtkPolyData::SafeDownCast(block)));
  }
  if (moved > 0.0)
  {
    vtkWarningWithObjectMacro(reporter,
      "The gathered surface was moved after Light Field Gather (a point by up to "
        << moved
        << "): its light was gathered where it was, and a Transform turns its Radiance as a "
           "vector. Move it before Light Field Gather (Transform, then the gather).");
  }
  return moved > 0.0;
}

//------------------------------------------------------------------------------
double vtkCompositeLightFieldMapper::MovedSinceGathered(vtkPolyData* surface)
{
  vtkDataArray* at = surface
    ? surface->GetPointData()->GetArray(vtkLightFieldGatherFilter::GetGatheredAtName())
    : nullptr;
  if (!at || at->GetNumberOfComponents() != 4 ||
    at->GetNumberOfTuples() != surface->GetNumberOfPoints() || surface->GetNumberOfPoints() == 0)
  {
    return 0.0;
  }
  // A millionth of the surface's size, or a few float steps of its coordinates where they are
  // large (the positions are kept as floats), is no move; filters that interpolate point data
  // (Clip, Slice) interpolate the positions alike and move nothing.
  double bounds[6];
  surface->GetBounds(bounds);
  double largest = 0.0;
  for (const double b : bounds)
  {
    largest = std::max(largest, std::abs(b));
  }
  const double tolerance =
    std::max(1e-6 * surface->GetLength(), 8.0 * std::numeric_limits<float>::epsilon() * largest);
  double worst = 0.0;
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3], gathered[4];
    surface->GetPoint(i, p);
    at->GetTuple(i, gathered);
    const double w = gathered[3] != 0.0 ? gathered[3] : 1.0;
    const double d = std::sqrt((p[0] - gathered[0] / w) * (p[0] - gathered[0] / w) +
      (p[1] - gathered[1] / w) * (p[1] - gathered[1] / w) +
      (p[2] - gathered[2] / w) * (p[2] - gathered[2] / w));
    worst = std::max(worst, d);
  }
  return worst > tolerance ? worst : 0.0;
}

//------------------------------------------------------------------------------
double vtkCompositeLightFieldMapper::LogAverageLuminance(const float* rgba, vtkIdType texels)
{
  return mesolight::vlf::LogAverageLuminance(
    rgba, static_cast<std::size_t>(std::max<vtkIdType>(0, texels)));
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
  if (!vtkLightFieldShading::UploadAtlasTexture(this->AtlasTexture, window,
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
  if (this->Shadows->Texture)
  {
    this->Shadows->Texture->ReleaseGraphicsResources(win);
  }
  if (this->BlankTexture)
  {
    this->BlankTexture->ReleaseGraphicsResources(win);
  }
  this->Shadows->UploadedVersion = 0;
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
  os << indent << "VertexRadiance: " << this->VertexRadiance << "\n";
  os << indent << "ShadowMode: " << this->ShadowMode << "\n";
  os << indent << "ShadowMapResolution: " << this->ShadowMapResolution << "\n";
  os << indent << "CheckGatheredPositions: " << this->CheckGatheredPositions << "\n";
  os << indent << "ShadowCaster: " << (this->GetShadowCaster() ? "set" : "(none)") << "\n";
}
