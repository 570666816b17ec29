// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldObjectMapper.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"

#include "EmitterLights.h"
#include "ObjectGatherer.h"
#include "PatchComparison.h" // ToWorld
#include "WalkthroughImage.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <chrono>
#include <cmath>
#include <sstream>

namespace vlf = mesolight::vlf;

vtkStandardNewMacro(vtkLightFieldObjectMapper);

//------------------------------------------------------------------------------
vtkLightFieldObjectMapper::vtkLightFieldObjectMapper()
{
  // The colours are display values already: no VTK lighting, the vertex colour as it is.
  vtkProperty* property = this->DrawActor->GetProperty();
  property->LightingOff();
  property->SetAmbient(1.0);
  property->SetDiffuse(0.0);
  property->SetSpecular(0.0);
  this->Delegate->SetInputData(this->Shaded);
  this->Delegate->SetScalarModeToUsePointData();
  this->Delegate->SetColorModeToDirectScalars();
  this->Delegate->ScalarVisibilityOn();
}

//------------------------------------------------------------------------------
vtkLightFieldObjectMapper::~vtkLightFieldObjectMapper() = default;

//------------------------------------------------------------------------------
void vtkLightFieldObjectMapper::SetLightFieldActor(vtkLightFieldActor* scene)
{
  if (this->Scene != scene)
  {
    this->Scene = scene;
    this->ShadedKey.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightFieldActor* vtkLightFieldObjectMapper::GetLightFieldActor()
{
  return this->Scene;
}

//------------------------------------------------------------------------------
const char* vtkLightFieldObjectMapper::GetShadingAsString(int shading)
{
  switch (shading)
  {
    case Flat:
      return "flat";
    case Lights:
      return "lights";
    case Gather:
      return "gather";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
int vtkLightFieldObjectMapper::GetShadingFromString(const std::string& name)
{
  for (int s = Flat; s <= Gather; ++s)
  {
    if (name == GetShadingAsString(s))
    {
      return s;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLightFieldObjectMapper::GetShadedMesh()
{
  return this->Shaded;
}

//------------------------------------------------------------------------------
bool vtkLightFieldObjectMapper::UpdateShadedMesh(vtkActor* act)
{
  vtkLightFieldActor* scene = this->Scene;
  this->LastShadingSeconds = 0.0;
  if (!scene)
  {
    return false;
  }
  if (!scene->GetMovableObject())
  {
    scene->SetMovableObject(act); // the mapper says which actor is the object
  }
  else if (scene->GetMovableObject() != act)
  {
    if (!this->WarnedForeign)
    {
      vtkWarningMacro(<< "this actor is not the light field actor's movable object: drawn "
                         "without the field's shading");
      this->WarnedForeign = true;
    }
    return false;
  }
  if (this->Shading == Gather)
  {
    scene->SetObjectSubdivision(this->Subdivision);
    scene->SetObjectGatherDirections(this->GatherDirections);
  }
  if (!scene->UpdateMovableObject())
  {
    return false;
  }
  const vlf::ShadedObject* shaded = vtkLightFieldActorCore::GetShadedObject(scene);
  const vlf::LightField* field = vtkLightFieldActorCore::GetLightField(scene);
  if (!shaded || !field)
  {
    return false;
  }
  double flat[3];
  act->GetProperty()->GetDiffuseColor(flat);
  std::ostringstream key;
  key << scene->GetObjectVersion() << ' ' << static_cast<const void*>(field) << ' ' << this->Shading
      << ' ' << scene->GetExposure() << ' ' << scene->GetToneMap() << ' ' << flat[0] << ' '
      << flat[1] << ' ' << flat[2];
  if (key.str() == this->ShadedKey)
  {
    return true;
  }
  const auto start = std::chrono::steady_clock::now();
  const vlf::LightApproximation* lights =
    this->Shading == Lights ? vtkLightFieldActorCore::GetEmitterLights(scene) : nullptr;
  if (lights && lights->Lights.empty() && !this->WarnedNoEmitters)
  {
    vtkWarningMacro(<< "the light field has no emitters: the object's lights shading shows only "
                       "the ambient term of the field's mean radiance");
    this->WarnedNoEmitters = true;
  }
  const float exposure = static_cast<float>(scene->GetExposure());
  const vlf::ToneMapOperator op = scene->GetToneMap() == vtkLightFieldActor::Reinhard
    ? vlf::ToneMapOperator::Reinhard
    : vlf::ToneMapOperator::Clamp;
  const vlf::ObjectMesh& mesh = shaded->Mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.Positions.size()));
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("ObjectColour");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(static_cast<vtkIdType>(mesh.Positions.size()));
  for (std::size_t i = 0; i < mesh.Positions.size(); ++i)
  {
    const glm::vec3 world = vlf::ToWorld(*field, mesh.Positions[i]);
    points->SetPoint(static_cast<vtkIdType>(i), world.x, world.y, world.z);
    glm::vec3 display(flat[0], flat[1], flat[2]);
    if (this->Shading == Gather && i < shaded->Radiance.size())
    {
      display = vlf::ToneMap(shaded->Radiance[i], exposure, op);
    }
    else if (this->Shading == Lights && lights)
    {
      const glm::vec3 n = i < mesh.Normals.size() ? mesh.Normals[i] : glm::vec3(0, 0, 1);
      display = vlf::ToneMap(
        vlf::ShadeWithLights(*lights, mesh.Positions[i], n, mesh.Diffuse), exposure, op);
    }
    for (int c = 0; c < 3; ++c)
    {
      const float v = std::isfinite(display[c]) ? std::min(1.0f, std::max(0.0f, display[c])) : 0;
      colours->SetComponent(static_cast<vtkIdType>(i), c, std::lround(255.0f * v));
    }
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(mesh.Triangles.size()),
    3 * static_cast<vtkIdType>(mesh.Triangles.size()));
  for (const glm::uvec3& t : mesh.Triangles)
  {
    const vtkIdType ids[3] = { t.x, t.y, t.z };
    polys->InsertNextCell(3, ids);
  }
  this->Shaded->Initialize();
  this->Shaded->SetPoints(points);
  this->Shaded->SetPolys(polys);
  this->Shaded->GetPointData()->SetScalars(colours);
  this->Shaded->Modified();
  this->ShadedKey = key.str();
  this->LastShadingSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectMapper::RenderPiece(vtkRenderer* ren, vtkActor* act)
{
  if (!this->UpdateShadedMesh(act))
  {
    this->Superclass::RenderPiece(ren, act);
    return;
  }
  // The shaded mesh is in world coordinates: the private actor keeps the identity matrix and
  // takes the user's visibility-related settings.
  vtkProperty* property = this->DrawActor->GetProperty();
  property->SetOpacity(act->GetProperty()->GetOpacity());
  property->SetRepresentation(act->GetProperty()->GetRepresentation());
  property->SetBackfaceCulling(act->GetProperty()->GetBackfaceCulling());
  this->Delegate->SetClippingPlanes(this->ClippingPlanes);
  this->Delegate->Render(ren, this->DrawActor);
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Delegate->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightFieldActor: " << static_cast<void*>(this->Scene.GetPointer()) << "\n";
  os << indent << "Shading: " << GetShadingAsString(this->Shading) << "\n";
  os << indent << "Subdivision: " << this->Subdivision << "\n";
  os << indent << "GatherDirections: " << this->GatherDirections << "\n";
  os << indent << "LastShadingSeconds: " << this->LastShadingSeconds << "\n";
}
