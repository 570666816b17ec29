// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefSurfaceRepresentation.h"

#include "vtkAppendPolyData.h"
#include "vtkAttachReliefTexture.h"
#include "vtkCompositeLightFieldMapper.h"
#include "vtkCompositeReliefMapper.h"
#include "vtkDataObjectLeaves.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIrradianceProbesTexture.h" // the visible share's array names
#include "vtkLight.h"
#include "vtkLightFieldCasterShadows.h"
#include "vtkLightFieldReliefShadowHook.h"
#include "vtkLightFieldReliefSurface.h"
#include "vtkLightFieldRepresentation.h" // GatherShadowCaster
#include "vtkMatrix4x4.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkPVView.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReliefProperty.h"
#include "vtkVirtualLightField.h"

#include "SurfaceRelief.h" // SurfacePlaneOf: the command line's plane rule
#include "TriangleScene.h"

#include "vtkCellArray.h"

#include <algorithm>
#include <exception>
#include <vector>

vtkStandardNewMacro(vtkReliefSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkReliefSurfaceRepresentation::vtkReliefSurfaceRepresentation()
{
  // ParaView's geometry representations draw through a composite mapper: replace the
  // superclass' mappers by relief ones, then wire them up again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  auto* mapper = vtkCompositeReliefMapper::New();
  auto* lodMapper = vtkCompositeReliefMapper::New();
  mapper->SetReliefProperty(this->ReliefProperty);
  lodMapper->SetReliefProperty(this->ReliefProperty);
  // Errors of the shared settings reach whoever watches the (full-resolution) mapper.
  this->ReliefProperty->SetMessageOwner(mapper);
  this->Mapper = mapper;
  this->LODMapper = lodMapper;
  // The relief texture's bake is the one source of truth unless the user overrides it.
  this->ReliefProperty->SetUseTextureDepthScale(true);
  // Float albedos (EXR) are colours, not scalars to map through a lookup table.
  this->AttachedColorTexture->SetColorModeToDirectScalars();
  this->AttachedColorTexture->InterpolateOn();
  this->AttachedColorTexture->MipmapOn();
  // The Shadow Caster's maps, drawn on the relief while it is lit by the field.
  this->CasterShadows = vtkSmartPointer<vtkLightFieldCasterShadows>::New();
  this->ObjectShadow = vtkSmartPointer<vtkLightFieldReliefShadowHook>::New();
  this->ObjectShadow->SetCasterShadows(this->CasterShadows);
  mapper->SetRadianceHook(this->ObjectShadow);
  lodMapper->SetRadianceHook(this->ObjectShadow);
  this->SetupDefaults();
  this->SetNumberOfInputPorts(3); // 1: the Light Field, 2: the Shadow Caster
}

//------------------------------------------------------------------------------
vtkReliefSurfaceRepresentation::~vtkReliefSurfaceRepresentation() = default;

//------------------------------------------------------------------------------
int vtkReliefSurfaceRepresentation::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataObject");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  if (port == 2)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkReliefSurfaceRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  this->AddPlaneTextureCoordinates();
  this->UpdateFieldLighting(inputVector[1]);
  this->UpdateShadowCaster(inputVector[2]);
  return 1;
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::UpdateShadowCaster(vtkInformationVector* casterInput)
{
  // Every rank gathers (a collective), lit by the field or not: FieldLit is the same on all.
  vtkPolyData* piece =
    this->GetNumberOfInputConnections(2) > 0 ? vtkPolyData::GetData(casterInput, 0) : nullptr;
  vtkSmartPointer<vtkPolyData> whole = vtkLightFieldRepresentation::GatherShadowCaster(piece);
  // The maps live in the field's unit sphere and darken the field's lighting: none without it.
  this->CasterShadows->SetCaster(this->FieldLit ? whole.Get() : nullptr);
  // A caster gathered from another field than the one lighting the relief casts no shadow.
  double centre[3], scale = 0.0;
  if (this->FieldLit && this->FieldSurface->GetFieldUnitSphere(centre, &scale))
  {
    this->CasterShadows->SetFieldUnitSphere(centre, scale);
  }
  else
  {
    this->CasterShadows->ClearFieldUnitSphere();
  }
  this->CasterShadows->Update(this->Mapper);
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetShadowMode(int mode)
{
  this->CasterShadows->SetMode(mode);
  this->CasterShadows->Update(this->Mapper);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetShadowMapResolution(int texels)
{
  this->CasterShadows->SetResolution(texels);
  this->CasterShadows->Update(this->Mapper);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::AddPlaneTextureCoordinates()
{
  // The pieces delivered to the mapper: the multiblock maker's leaves (the geometry filter's
  // polydata, shared or copied).
  std::vector<vtkPolyData*> bare;
  int textured = 0;
  for (vtkDataObject* leaf :
    mesolight::DataObjectLeaves(this->MultiBlockMaker->GetOutputDataObject(0)))
  {
    auto* poly = vtkPolyData::SafeDownCast(leaf);
    if (poly && poly->GetNumberOfPoints() > 0 && !poly->GetPointData()->GetTCoords())
    {
      bare.push_back(poly);
    }
    textured = textured || vtkAttachReliefTexture::GetAttachedReliefTexture(leaf) != nullptr;
  }
  // Every rank's representation updates together (one pipeline), so the collectives match.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool parallel = controller && controller->GetNumberOfProcesses() > 1;
  int any[2] = { bare.empty() ? 0 : 1, textured };
  if (parallel)
  {
    const int mine[2] = { any[0], any[1] };
    controller->AllReduce(mine, any, 2, vtkCommunicator::MAX_OP);
  }
  // Without a relief texture there is nothing to address: the mapper's "No relief texture ...
  // apply Attach Relief Texture" is the one message, not a complaint about the surface's shape.
  if (!any[0] || !any[1])
  {
    return;
  }
  // One frame for the whole surface: every rank's bare pieces.
  vtkNew<vtkAppendPolyData> append;
  for (vtkPolyData* poly : bare)
  {
    append->AddInputData(poly);
  }
  vtkNew<vtkPolyData> local;
  if (!bare.empty())
  {
    append->Update();
    local->ShallowCopy(append->GetOutput());
  }
  vtkSmartPointer<vtkPolyData> whole =
    vtkLightFieldReliefSurface::GatherWholeSurface(local, parallel ? controller : nullptr);
  mesolight::TriangleMesh mesh;
  mesh.Positions.resize(static_cast<std::size_t>(whole->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < whole->GetNumberOfPoints(); ++i)
  {
    double p[3];
    whole->GetPoint(i, p);
    mesh.Positions[static_cast<std::size_t>(i)] = glm::vec3(p[0], p[1], p[2]);
  }
  if (vtkCellArray* polys = whole->GetPolys())
  {
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
    {
      for (vtkIdType k = 1; k + 1 < count; ++k) // fans: a relief surface is planar
      {
        mesh.Triangles.emplace_back(static_cast<unsigned>(ids[0]), static_cast<unsigned>(ids[k]),
          static_cast<unsigned>(ids[k + 1]));
      }
    }
  }
  std::vector<std::size_t> triangles(mesh.Triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    triangles[t] = t;
  }
  mesolight::SurfacePlane plane;
  try
  {
    plane = mesolight::SurfacePlaneOf(mesh, triangles, "the Relief Surface's input");
  }
  catch (const std::exception& e)
  {
    // The same on every rank (the whole surface); the mapper then refuses the bare pieces.
    vtkErrorMacro(<< e.what()
                  << ". It has no texture coordinates, and only a planar surface gets its "
                     "plane's: apply Texture Map to Plane (or Texture Map to Cylinder / Sphere) "
                     "to it first.");
    return;
  }
  for (vtkPolyData* poly : bare)
  {
    vtkNew<vtkFloatArray> tcoords;
    tcoords->SetName("PlaneTextureCoordinates");
    tcoords->SetNumberOfComponents(2);
    tcoords->SetNumberOfTuples(poly->GetNumberOfPoints());
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i)
    {
      double p[3];
      poly->GetPoint(i, p);
      const glm::vec2 uv = plane.TextureCoordinate(glm::vec3(p[0], p[1], p[2]));
      tcoords->SetTuple2(i, uv.x, uv.y);
    }
    poly->GetPointData()->SetTCoords(tcoords);
  }
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::UpdateFieldLighting(vtkInformationVector* fieldInput)
{
  // Every rank's representation updates together and the connection is the same on all (one
  // proxy property), so the collectives below match.
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  const bool parallel = controller && controller->GetNumberOfProcesses() > 1;
  if (this->GetNumberOfInputConnections(1) == 0)
  {
    if (this->FieldLit || this->GatheredProducer || this->GatheredInput)
    {
      this->FieldLit = false;
      this->GatheredInput = nullptr;
      this->GatheredProducer = nullptr;
      this->GatheredPropagation = -1;
      this->FieldSurface->SetLightFieldProducer(nullptr);
      this->FieldSurface->SetSurfaceData(nullptr);
      this->FieldLights->RemoveAllItems();
      static_cast<vtkCompositeReliefMapper*>(this->Mapper)->SetIrradianceProbesData(nullptr);
      static_cast<vtkCompositeReliefMapper*>(this->LODMapper)->SetIrradianceProbesData(nullptr);
      this->ReliefProperty->SetLights(nullptr);
      this->ReliefProperty->RemoveDepthLimitPlane();
      this->UpdateDisplayTransform();
    }
    return;
  }
  vtkAlgorithm* connected = this->GetInputAlgorithm(1, 0);
  vtkVirtualLightField* producer = vtkVirtualLightField::FindUpstream(connected);
  const int propagation = producer ? producer->GetPropagationCount() : -1;
  vtkDataObject* geometry = this->GeometryFilter->GetOutputDataObject(0);
  // The shown geometry's points and polygons, not the data objects holding them: the geometry
  // filter executes again after every MarkModified (a relief setting the visible-share map needs)
  // and hands on the same arrays in new objects, which must not gather the probes again.
  vtkMTimeType geometryTime = 0;
  for (vtkDataObject* leaf : mesolight::DataObjectLeaves(geometry))
  {
    if (auto* poly = vtkPolyData::SafeDownCast(leaf))
    {
      if (vtkPoints* points = poly->GetPoints())
      {
        geometryTime =
          std::max({ geometryTime, points->GetMTime(), points->GetData()->GetMTime() });
      }
      geometryTime = std::max(geometryTime, poly->GetPolys()->GetMTime());
    }
  }
  // The connection too: another wrong choice (no field upstream either) is reported again.
  int changed =
    (connected != this->GatheredInput || producer != this->GatheredProducer ||
      propagation != this->GatheredPropagation || geometryTime != this->GatheredGeometryTime)
    ? 1
    : 0;
  // The visible-share map's inputs: the relief texture (with the data), its depth scale, its edge.
  double depthScale = 0.0;
  bool walled = false;
  vtkSmartPointer<vtkImageData> texture = this->ShownReliefTexture(depthScale, walled);
  // The attached texture comes as a new image sharing the data's array each time: the array says
  // whether it changed.
  vtkDataArray* texels = texture ? texture->GetPointData()->GetScalars() : nullptr;
  const int edge = this->LightFieldOcclusion ? (walled ? 1 : 0) : 2;
  int shareChanged = (texels != this->SharedTexture ||
                       (texels ? texels->GetMTime() : 0) != this->SharedTextureTime ||
                       depthScale != this->SharedDepthScale || edge != this->SharedEdge)
    ? 1
    : 0;
  if (parallel)
  {
    int mine[2] = { changed, shareChanged };
    int any[2] = { 0, 0 };
    controller->AllReduce(mine, any, 2, vtkCommunicator::MAX_OP);
    changed = any[0];
    shareChanged = any[1];
  }
  if (!changed && !shareChanged)
  {
    return; // the probes and the map are still those of this field, geometry and relief
  }
  this->SharedTexture = texels;
  this->SharedTextureTime = texels ? texels->GetMTime() : 0;
  this->SharedDepthScale = depthScale;
  this->SharedEdge = edge;
  this->FieldSurface->SetSceneOcclusion(this->LightFieldOcclusion);
  this->FieldSurface->SetReliefTextureData(this->LightFieldOcclusion ? texture : nullptr);
  this->FieldSurface->SetReliefDepthScale(depthScale);
  this->FieldSurface->SetWalledRelief(walled);
  if (!changed)
  {
    // The same field and surface: vtkLightFieldReliefSurface keeps its probes and recomputes the
    // map (or drops it) only.
    if (producer)
    {
      this->FieldSurface->Update();
    }
    this->UseFieldSurfaceOutputs(producer != nullptr);
    return;
  }
  this->GatheredInput = connected;
  this->GatheredProducer = producer;
  this->GatheredPropagation = propagation;
  this->GatheredGeometryTime = geometryTime;

  // The shown surface, this rank's piece: the geometry filter's polygonal output.
  vtkNew<vtkAppendPolyData> append;
  for (vtkDataObject* leaf : mesolight::DataObjectLeaves(geometry))
  {
    auto* poly = vtkPolyData::SafeDownCast(leaf);
    if (poly && poly->GetNumberOfPoints() > 0)
    {
      append->AddInputData(poly);
    }
  }
  vtkNew<vtkPolyData> surface;
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    surface->ShallowCopy(append->GetOutput());
  }
  // The field's log-average luminance from the atlas its output carries (the Light Field
  // representation's automatic exposure), the same on every rank.
  double logAverage = 0.0;
  for (vtkDataObject* leaf : mesolight::DataObjectLeaves(vtkDataObject::GetData(fieldInput, 0)))
  {
    int size[2] = { 0, 0 };
    if (vtkFloatArray* atlas = vtkVirtualLightField::GetAttachedAtlas(leaf, size))
    {
      logAverage = vtkCompositeLightFieldMapper::LogAverageLuminance(
        atlas->GetPointer(0), atlas->GetNumberOfTuples());
      break;
    }
  }
  if (parallel)
  {
    double most = 0.0;
    controller->AllReduce(&logAverage, &most, 1, vtkCommunicator::MAX_OP);
    logAverage = most;
  }
  this->FieldLogAverage = logAverage;

  if (!producer)
  {
    // The same on every rank (one pipeline), so no rank is left in a collective.
    vtkErrorMacro("The Relief Surface's Light Field must be the output of a Mesolight Virtual "
                  "Light Field filter (directly or through pass-through filters); the relief is "
                  "drawn with the view's lights.");
  }
  this->FieldSurface->SetLightFieldProducer(producer);
  this->FieldSurface->SetSurfaceData(surface);
  this->FieldSurface->Modified(); // a new propagation leaves the producer's pointer the same
  if (producer)
  {
    this->FieldSurface->Update();
    ++this->ProbeGatherings;
  }
  this->UseFieldSurfaceOutputs(producer != nullptr);
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::UseFieldSurfaceOutputs(bool updated)
{
  vtkImageData* probes = updated ? this->FieldSurface->GetProbesOutput() : nullptr;
  this->FieldLights->RemoveAllItems();
  vtkSmartPointer<vtkImageData> kept;
  if (probes && probes->GetNumberOfPoints() > 0)
  {
    kept = vtkSmartPointer<vtkImageData>::New();
    kept->DeepCopy(probes);
    vtkCollectionSimpleIterator it;
    vtkLightCollection* lights = this->FieldSurface->GetEmitterLights();
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      this->FieldLights->AddItem(light);
    }
  }
  // Without probes (an error was reported) the relief is drawn the ordinary way.
  this->FieldLit = kept != nullptr;
  static_cast<vtkCompositeReliefMapper*>(this->Mapper)->SetIrradianceProbesData(kept);
  static_cast<vtkCompositeReliefMapper*>(this->LODMapper)->SetIrradianceProbesData(kept);
  this->ReliefProperty->SetLights(this->FieldLit ? this->FieldLights.Get() : nullptr);
  // A relief on an emitter of the field (a lamp, a window) still emits its light.
  const double none[3] = { 0.0, 0.0, 0.0 };
  this->ReliefProperty->SetEmission(
    this->FieldLit ? this->FieldSurface->GetSurfaceEmission() : none);
  // A relief mounted on a wall of the field replaces the wall: its depth lies behind its plane
  // (by up to the depth scale), so without the limit the Light Field representation's wall a
  // few mm behind the patch would hide the relief's deeper parts.
  double origin[3], normal[3];
  if (this->FieldLit && this->FieldSurface->GetDepthLimitPlane(origin, normal))
  {
    this->ReliefProperty->SetDepthLimitPlane(origin, normal);
  }
  else
  {
    this->ReliefProperty->RemoveDepthLimitPlane();
  }
  this->UpdateDisplayTransform();
  this->UpdateAlbedo();
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkReliefSurfaceRepresentation::ShownReliefTexture(
  double& depthScale, bool& walled)
{
  vtkSmartPointer<vtkImageData> texture;
  for (vtkDataObject* leaf :
    mesolight::DataObjectLeaves(this->MultiBlockMaker->GetOutputDataObject(0)))
  {
    if ((texture = vtkAttachReliefTexture::GetAttachedReliefTexture(leaf)))
    {
      break;
    }
  }
  // The depth scale the mapper draws with (vtkReliefShading: the bake's unless overridden).
  depthScale = this->ReliefProperty->GetDepthScale();
  vtkDataArray* baked =
    texture ? texture->GetFieldData()->GetArray("MesolightDepthScale") : nullptr;
  if (baked && baked->GetNumberOfTuples() > 0 && this->ReliefProperty->GetUseTextureDepthScale())
  {
    depthScale = std::min(baked->GetComponent(0, 0), 10.0);
  }
  // Without silhouettes a relief that does not repeat is walled at its texture's border.
  walled = !this->ReliefProperty->GetSilhouettes() && !this->ReliefProperty->GetRepeatTexture();
  return texture;
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetLightFieldOcclusion(bool on)
{
  this->LightFieldOcclusion = on;
  this->MarkModified(); // RequestData recomputes the map (or drops it)
}

//------------------------------------------------------------------------------
int vtkReliefSurfaceRepresentation::GetVisibleShareMaps()
{
  return this->FieldSurface->GetVisibleShareComputations();
}

//------------------------------------------------------------------------------
vtkDoubleArray* vtkReliefSurfaceRepresentation::GetVisibleShareValues()
{
  this->VisibleShareValues = vtkSmartPointer<vtkDoubleArray>::New();
  vtkImageData* probes = this->FieldLit ? this->FieldSurface->GetProbesOutput() : nullptr;
  vtkFieldData* fields = probes ? probes->GetFieldData() : nullptr;
  vtkDataArray* share =
    fields ? fields->GetArray(vtkIrradianceProbesTexture::GetVisibleShareName()) : nullptr;
  vtkDataArray* size =
    fields ? fields->GetArray(vtkIrradianceProbesTexture::GetVisibleShareSizeName()) : nullptr;
  if (share && size && size->GetNumberOfTuples() >= 2)
  {
    const vtkIdType values = share->GetNumberOfTuples() * share->GetNumberOfComponents();
    this->VisibleShareValues->SetNumberOfValues(values + 2);
    this->VisibleShareValues->SetValue(0, size->GetComponent(0, 0));
    this->VisibleShareValues->SetValue(1, size->GetComponent(1, 0));
    for (vtkIdType v = 0; v < values; ++v)
    {
      this->VisibleShareValues->SetValue(v + 2,
        share->GetComponent(
          v / share->GetNumberOfComponents(), v % share->GetNumberOfComponents()));
    }
  }
  return this->VisibleShareValues;
}

//------------------------------------------------------------------------------
int vtkReliefSurfaceRepresentation::GetVisibleShareRanks()
{
  return this->FieldSurface->GetVisibleShareRanks();
}

//------------------------------------------------------------------------------
double vtkReliefSurfaceRepresentation::GetVisibleShareSeconds()
{
  return this->FieldSurface->GetVisibleShareSeconds();
}

//------------------------------------------------------------------------------
double vtkReliefSurfaceRepresentation::GetVisibleShareCpuSeconds()
{
  return this->FieldSurface->GetVisibleShareCpuSeconds();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::UpdateDisplayTransform()
{
  double exposure = this->UserExposure;
  if (this->FieldLit && this->LightFieldAutoExposure && this->FieldLogAverage > 0.0)
  {
    exposure *= 0.18 / this->FieldLogAverage; // vtkCompositeLightFieldMapper's middle grey
  }
  this->ReliefProperty->SetExposure(exposure);
  this->ReliefProperty->SetEncodeSRGB(this->FieldLit); // the Light Field representation's
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetLightFieldAutoExposure(bool on)
{
  this->LightFieldAutoExposure = on;
  this->UpdateDisplayTransform();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetExposure(double exposure)
{
  this->UserExposure = exposure;
  this->UpdateDisplayTransform();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetLightFieldAlbedo(bool on)
{
  this->LightFieldAlbedo = on;
  this->UpdateAlbedo();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetDiffuseColor(double r, double g, double b)
{
  this->UserDiffuseColor[0] = r;
  this->UserDiffuseColor[1] = g;
  this->UserDiffuseColor[2] = b;
  this->UpdateAlbedo();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::UpdateAlbedo()
{
  // A texture's colours multiply the shading (vtkReliefImplFS.glsl) and an array's replace the
  // diffuse colour: the wall's Kd stands in for Solid Color only.
  double origin[3], normal[3];
  const bool solid = !this->Actor->GetTexture() && !this->Mapper->GetScalarVisibility();
  const bool wall = this->FieldLit && this->LightFieldAlbedo && solid &&
    this->FieldSurface->GetDepthLimitPlane(origin, normal);
  const double* color = wall ? this->FieldSurface->GetSurfaceDiffuse() : this->UserDiffuseColor;
  this->Superclass::SetDiffuseColor(color[0], color[1], color[2]);
}

//------------------------------------------------------------------------------
vtkLightCollection* vtkReliefSurfaceRepresentation::GetFieldLights()
{
  return this->FieldLights;
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetTexture(vtkTexture* texture)
{
  this->UserTexture = texture;
  this->Superclass::SetTexture(texture);
}

//------------------------------------------------------------------------------
int vtkReliefSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* requestType, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(requestType, inInfo, outInfo))
  {
    return 0;
  }
  if (requestType == vtkPVView::REQUEST_RENDER())
  {
    this->UpdateAttachedColorTexture();
    this->UpdateAlbedo(); // the texture and the colouring by an array are known now
    // The field's probes, emitter lights and depth limit are those of the data where it is: a
    // display transform moves the relief away from the light it was lit with. Said once per
    // transform.
    const bool moved = this->FieldLit && !this->Actor->GetMatrix()->IsIdentity();
    if (moved && !this->WarnedDisplayTransform)
    {
      vtkWarningMacro("The Relief Surface is lit by its Light Field where its data lies; the "
                      "display's Translation, Scale, Orientation or Origin move it away from that "
                      "light. Move the surface with a Transform filter before Attach Relief "
                      "Texture instead.");
    }
    this->WarnedDisplayTransform = moved;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::UpdateAttachedColorTexture()
{
  if (this->UserTexture)
  {
    return;
  }
  vtkSmartPointer<vtkImageData> color;
  for (vtkDataObject* leaf : mesolight::DataObjectLeaves(this->Mapper->GetInputDataObject(0, 0)))
  {
    if ((color = vtkAttachReliefTexture::GetAttachedColorTexture(leaf)))
    {
      break;
    }
  }
  if (!color)
  {
    if (this->Actor->GetTexture() == this->AttachedColorTexture)
    {
      this->Actor->SetTexture(nullptr);
    }
    return;
  }
  // Re-upload only when the texels changed: the detached image shares the field array.
  auto* shown = vtkImageData::SafeDownCast(this->AttachedColorTexture->GetInput());
  if (!shown || shown->GetPointData()->GetScalars() != color->GetPointData()->GetScalars())
  {
    this->AttachedColorTexture->SetInputData(color);
  }
  if (this->Actor->GetTexture() != this->AttachedColorTexture)
  {
    this->Actor->SetTexture(this->AttachedColorTexture);
  }
}

//------------------------------------------------------------------------------
vtkReliefProperty* vtkReliefSurfaceRepresentation::GetReliefProperty()
{
  return this->ReliefProperty;
}

// Each proxy command sets the shared property and marks the representation modified.
#define MESOLIGHT_FORWARD(Name, Type, PropertySetter)                                              \
  void vtkReliefSurfaceRepresentation::Set##Name(Type value)                                       \
  {                                                                                                \
    this->ReliefProperty->PropertySetter(value);                                                   \
    this->Modified();                                                                              \
  }

MESOLIGHT_FORWARD(ReliefMethod, int, SetMethod)
MESOLIGHT_FORWARD(LinearSteps, int, SetLinearSteps)
MESOLIGHT_FORWARD(RefinementSteps, int, SetRefinementSteps)
MESOLIGHT_FORWARD(AdaptiveSteps, bool, SetAdaptiveSteps)
MESOLIGHT_FORWARD(MinimumSteps, int, SetMinimumSteps)
MESOLIGHT_FORWARD(SelfShadowing, bool, SetSelfShadowing)
MESOLIGHT_FORWARD(SurfaceCurvature, bool, SetSurfaceCurvature)
MESOLIGHT_FORWARD(WriteDepth, bool, SetWriteDepth)
MESOLIGHT_FORWARD(LevelOfDetail, bool, SetLevelOfDetail)
MESOLIGHT_FORWARD(NormalFilter, int, SetNormalFilter)
MESOLIGHT_FORWARD(FarViewRays, int, SetFarViewRays)
MESOLIGHT_FORWARD(ToneMapping, bool, SetToneMapping)
MESOLIGHT_FORWARD(LightSetThreshold, double, SetLightSetThreshold)
MESOLIGHT_FORWARD(ShadowedLights, int, SetShadowedLights)
#undef MESOLIGHT_FORWARD

// The settings the relief's visible-share map depends on: RequestData recomputes the map when a
// Light Field lights the relief (vtkPVDataRepresentation::MarkModified: a plain Modified does not
// make the view update the representation).
#define MESOLIGHT_FORWARD_SHARED(Name, Type, PropertySetter)                                       \
  void vtkReliefSurfaceRepresentation::Set##Name(Type value)                                       \
  {                                                                                                \
    this->ReliefProperty->PropertySetter(value);                                                   \
    this->MarkModified();                                                                          \
  }

MESOLIGHT_FORWARD_SHARED(ReliefDepthScale, double, SetDepthScale)
MESOLIGHT_FORWARD_SHARED(Silhouettes, bool, SetSilhouettes)
MESOLIGHT_FORWARD_SHARED(RepeatTexture, bool, SetRepeatTexture)
#undef MESOLIGHT_FORWARD_SHARED

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetOverrideDepthScale(bool on)
{
  this->ReliefProperty->SetUseTextureDepthScale(!on);
  this->MarkModified(); // the visible-share map's depth scale (see above)
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FieldLit: " << this->FieldLit << "\n";
  os << indent << "CasterShadows:\n";
  this->CasterShadows->PrintSelf(os, indent.GetNextIndent());
  os << indent << "LightFieldAutoExposure: " << this->LightFieldAutoExposure << "\n";
  os << indent << "LightFieldOcclusion: " << this->LightFieldOcclusion << "\n";
  os << indent << "LightFieldAlbedo: " << this->LightFieldAlbedo << "\n";
  os << indent << "UserDiffuseColor: " << this->UserDiffuseColor[0] << " "
     << this->UserDiffuseColor[1] << " " << this->UserDiffuseColor[2] << "\n";
  os << indent << "ProbeGatherings: " << this->ProbeGatherings << "\n";
  os << indent << "ReliefProperty:\n";
  this->ReliefProperty->PrintSelf(os, indent.GetNextIndent());
}
