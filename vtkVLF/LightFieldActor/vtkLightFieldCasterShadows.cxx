// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldCasterShadows.h"

#include "ObjectMesh.h"
#include "ObjectShadows.h"
#include "vtkLightFieldGatherFilter.h"
#include "vtkVirtualLightField.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkLightFieldCasterShadows);

struct vtkLightFieldCasterShadows::Maps
{
  mesolight::vlf::ObjectShadows Shadows;
  mesolight::vlf::ShadowGpuData Gpu;
};

//------------------------------------------------------------------------------
vtkLightFieldCasterShadows::vtkLightFieldCasterShadows()
  : Built(new Maps)
{
}

vtkLightFieldCasterShadows::~vtkLightFieldCasterShadows() = default;

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::SetCaster(vtkPolyData* caster)
{
  if (this->Caster != caster)
  {
    this->Caster = caster;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLightFieldCasterShadows::GetCaster()
{
  return this->Caster;
}

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::SetMode(int mode)
{
  mode = std::min(std::max(mode, 0), 5);
  if (mode != this->Mode)
  {
    this->Mode = mode;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::SetResolution(int texels)
{
  texels = std::min(std::max(texels, 16), 4096);
  if (texels != this->Resolution)
  {
    this->Resolution = texels;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::SetFieldUnitSphere(const double centre[3], double scale)
{
  if (!(scale > 0.0) || !std::isfinite(scale))
  {
    this->ClearFieldUnitSphere();
    return;
  }
  if (scale != this->FieldScale || !std::equal(centre, centre + 3, this->FieldCentre))
  {
    std::copy(centre, centre + 3, this->FieldCentre);
    this->FieldScale = scale;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::ClearFieldUnitSphere()
{
  if (this->FieldScale != 0.0)
  {
    std::fill(this->FieldCentre, this->FieldCentre + 3, 0.0);
    this->FieldScale = 0.0;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldCasterShadows::HasShadows() const
{
  return this->Built->Gpu.Mode != 0 && this->Built->Gpu.EmitterCount > 0;
}

//------------------------------------------------------------------------------
const mesolight::vlf::ShadowGpuData& vtkLightFieldCasterShadows::GetGpu() const
{
  return this->Built->Gpu;
}

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::GetWorldToUnitSphere(float columnMajor[16]) const
{
  std::fill(columnMajor, columnMajor + 16, 0.0f);
  for (int i = 0; i < 3; ++i)
  {
    columnMajor[i * 5] = static_cast<float>(this->Scale);
    columnMajor[12 + i] = static_cast<float>(-this->Centre[i] * this->Scale);
  }
  columnMajor[15] = 1.0f;
}

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::Update(vtkObject* reporter)
{
  namespace vlf = mesolight::vlf;
  vtkPolyData* caster = this->Mode != 0 ? this->Caster.Get() : nullptr;
  if (caster == this->BuiltCaster && (!caster || caster->GetMTime() == this->BuiltTime) &&
    this->Mode == this->BuiltMode && this->Resolution == this->BuiltResolution &&
    this->FieldScale == this->BuiltFieldScale &&
    std::equal(this->FieldCentre, this->FieldCentre + 3, this->BuiltFieldCentre))
  {
    return;
  }
  this->BuiltCaster = caster;
  this->BuiltTime = caster ? caster->GetMTime() : 0;
  this->BuiltMode = this->Mode;
  this->BuiltResolution = this->Resolution;
  this->BuiltFieldScale = this->FieldScale;
  std::copy(this->FieldCentre, this->FieldCentre + 3, this->BuiltFieldCentre);
  Maps& d = *this->Built;
  d.Shadows.Clear();
  d.Gpu = vlf::ShadowGpuData();
  ++this->Version;
  const std::string before = this->Problem;
  this->Problem.clear();
  if (!caster)
  {
    return;
  }
  vtkFieldData* fields = caster->GetFieldData();
  vtkFloatArray* packed = vtkFloatArray::SafeDownCast(
    fields ? fields->GetAbstractArray(vtkLightFieldGatherFilter::GetEmittersName()) : nullptr);
  std::vector<vlf::ShadowEmitter> emitters;
  if (!packed || !vtkVirtualLightField::GetAttachedUnitSphere(caster, this->Centre, &this->Scale) ||
    !vlf::UnpackEmitters(
      packed->GetPointer(0), static_cast<std::size_t>(packed->GetNumberOfValues()), emitters))
  {
    this->Problem = "the Shadow Caster carries no light field emitters: connect the output of "
                    "Light Field Gather (or a filter after it) as the Shadow Caster";
  }
  else if (caster->GetNumberOfPolys() == 0 || caster->GetNumberOfPoints() == 0)
  {
    this->Problem = "the Shadow Caster has no polygons";
  }
  else if (this->FieldScale > 0.0 && !this->SameUnitSphere())
  {
    std::ostringstream why;
    why << "it was gathered from another light field than the one it shadows (its field's unit "
           "sphere: centre ("
        << this->Centre[0] << ", " << this->Centre[1] << ", " << this->Centre[2] << "), radius "
        << 1.0 / this->Scale << "; this field's: centre (" << this->FieldCentre[0] << ", "
        << this->FieldCentre[1] << ", " << this->FieldCentre[2] << "), radius "
        << 1.0 / this->FieldScale
        << "): give Light Field Gather this field as its light field input";
    this->Problem = why.str();
  }
  if (this->Problem.empty())
  {
    vlf::ObjectMesh mesh;
    mesh.Positions.reserve(static_cast<std::size_t>(caster->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < caster->GetNumberOfPoints(); ++i)
    {
      double p[3];
      caster->GetPoint(i, p);
      mesh.Positions.emplace_back(static_cast<float>((p[0] - this->Centre[0]) * this->Scale),
        static_cast<float>((p[1] - this->Centre[1]) * this->Scale),
        static_cast<float>((p[2] - this->Centre[2]) * this->Scale));
    }
    vtkNew<vtkIdList> ids;
    vtkCellArray* polys = caster->GetPolys();
    for (polys->InitTraversal(); polys->GetNextCell(ids);)
    {
      for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
      {
        mesh.Triangles.emplace_back(static_cast<unsigned>(ids->GetId(0)),
          static_cast<unsigned>(ids->GetId(k)), static_cast<unsigned>(ids->GetId(k + 1)));
      }
    }
    mesh.ComputeNormals();
    vlf::ShadowSettings settings;
    settings.Mode = static_cast<vlf::ShadowMode>(this->Mode);
    settings.Resolution = this->Resolution;
    // The field's ambient term makes the shadow the share of the lighting blocked (no stripes
    // from the field's direction aliasing, see ObjectShadows.h); an older gather output has none.
    vtkDataArray* ambient = vtkArrayDownCast<vtkDataArray>(
      fields->GetAbstractArray(vtkLightFieldGatherFilter::GetAmbientName()));
    if (ambient && ambient->GetNumberOfValues() == 3)
    {
      d.Shadows.SetAmbient(glm::vec3(static_cast<float>(ambient->GetComponent(0, 0)),
        static_cast<float>(ambient->GetComponent(1, 0)),
        static_cast<float>(ambient->GetComponent(2, 0))));
    }
    else
    {
      d.Shadows.ClearAmbient();
    }
    this->Problem = d.Shadows.Build(emitters, mesh, settings);
    d.Gpu = vlf::PackShadowsForGpu(d.Shadows);
  }
  if (!this->Problem.empty() && this->Problem != before)
  {
    vtkWarningWithObjectMacro(
      reporter ? reporter : this, << "the Shadow Caster casts no shadow: " << this->Problem << ".");
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldCasterShadows::SameUnitSphere() const
{
  // Both come from the same float normalisation when the fields are one scene's (a field and
  // its snapshot, or two propagations of it); a millionth of the sphere allows for the float to
  // double round trips and nothing a user could see.
  const double tolerance = 1e-6;
  double offset = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    offset = std::max(offset, std::abs(this->Centre[i] - this->FieldCentre[i]));
  }
  return std::abs(this->Scale / this->FieldScale - 1.0) <= tolerance &&
    offset * this->FieldScale <= tolerance;
}

//------------------------------------------------------------------------------
void vtkLightFieldCasterShadows::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Caster: " << (this->Caster ? "set" : "(none)") << "\n";
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "FieldUnitSphere: ";
  if (this->FieldScale > 0.0)
  {
    os << "centre (" << this->FieldCentre[0] << ", " << this->FieldCentre[1] << ", "
       << this->FieldCentre[2] << "), scale " << this->FieldScale << "\n";
  }
  else
  {
    os << "(not checked)\n";
  }
  os << indent << "Version: " << this->Version << "\n";
  os << indent << "Problem: " << (this->Problem.empty() ? "(none)" : this->Problem) << "\n";
}
