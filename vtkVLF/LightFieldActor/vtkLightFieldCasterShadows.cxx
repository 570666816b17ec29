// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldCasterShadows.h"

#include "ObjectMesh.h"
#include "ObjectShadows.h"
#include "vtkLightFieldGatherFilter.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <algorithm>
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
    this->Mode == this->BuiltMode && this->Resolution == this->BuiltResolution)
  {
    return;
  }
  this->BuiltCaster = caster;
  this->BuiltTime = caster ? caster->GetMTime() : 0;
  this->BuiltMode = this->Mode;
  this->BuiltResolution = this->Resolution;
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
  vtkDataArray* normalisation = vtkArrayDownCast<vtkDataArray>(
    fields ? fields->GetAbstractArray(vtkLightFieldGatherFilter::GetToUnitSphereName()) : nullptr);
  std::vector<vlf::ShadowEmitter> emitters;
  if (!packed || !normalisation || normalisation->GetNumberOfValues() != 4 ||
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
  if (this->Problem.empty())
  {
    this->Scale = normalisation->GetComponent(3, 0);
    for (int i = 0; i < 3; ++i)
    {
      this->Centre[i] = normalisation->GetComponent(i, 0);
    }
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
void vtkLightFieldCasterShadows::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Caster: " << (this->Caster ? "set" : "(none)") << "\n";
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "Version: " << this->Version << "\n";
  os << indent << "Problem: " << (this->Problem.empty() ? "(none)" : this->Problem) << "\n";
}
