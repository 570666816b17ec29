// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefGeometryCache.h"

#include "SurfaceQuadrics.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataTangents.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkReliefGeometryCache);

namespace
{
const char* const ReliefTCoordsName = "vtkReliefMapperTCoords";
const char* const ReliefQuadricsName = "vtkReliefMapperQuadrics";

bool AllTriangles(vtkPolyData* poly)
{
  if (poly->GetNumberOfStrips() > 0)
  {
    return false;
  }
  vtkCellArray* polys = poly->GetPolys();
  return polys->IsHomogeneous() == 3;
}

bool UsableDirection(const double v[3])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]) &&
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) > 1e-20;
}

// Degenerate triangles (zero area, or coinciding texture coordinates) give zero or NaN normals
// and tangents. Replace them by a usable frame so the shader never receives NaN.
void SanitizeFrame(vtkPolyData* mesh)
{
  vtkPointData* pd = mesh->GetPointData();
  vtkDataArray* normals = pd->GetNormals();
  auto* tangents = vtkFloatArray::SafeDownCast(pd->GetTangents());
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkSmartPointer<vtkDataArray> ownNormals;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double nrm[3];
    normals->GetTuple(i, nrm);
    if (!UsableDirection(nrm))
    {
      if (!ownNormals) // the normals may be the user's: change a copy
      {
        ownNormals = vtkSmartPointer<vtkDataArray>::Take(normals->NewInstance());
        ownNormals->DeepCopy(normals);
        pd->SetNormals(ownNormals);
        normals = ownNormals;
      }
      normals->SetTuple3(i, 0.0, 0.0, 1.0);
      nrm[0] = nrm[1] = 0.0;
      nrm[2] = 1.0;
    }
    float* t = tangents->GetPointer(3 * i);
    const double tangent[3] = { t[0], t[1], t[2] };
    if (UsableDirection(tangent))
    {
      continue;
    }
    double perp[3];
    vtkMath::Perpendiculars(nrm, perp, nullptr, 0.0);
    if (!UsableDirection(perp))
    {
      perp[0] = 1.0;
      perp[1] = perp[2] = 0.0;
    }
    t[0] = static_cast<float>(perp[0]);
    t[1] = static_cast<float>(perp[1]);
    t[2] = static_cast<float>(perp[2]);
  }
}

// The per-vertex quadrics of a curved mesh (Oliveira & Policarpo 2005, "An efficient
// representation for surface details"), added as a 2-component float array only when some vertex
// is curved: a flat mesh gets no array, and the shader then has no curvature code at all.
bool AddQuadrics(vtkPolyData* mesh, std::string& error)
{
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tcoords = mesh->GetPointData()->GetArray(ReliefTCoordsName);
  std::vector<glm::dvec3> positions(static_cast<size_t>(n)), nrm(static_cast<size_t>(n));
  std::vector<glm::dvec2> uv(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], q[3];
    mesh->GetPoint(i, p);
    normals->GetTuple(i, q);
    positions[static_cast<size_t>(i)] = glm::dvec3(p[0], p[1], p[2]);
    nrm[static_cast<size_t>(i)] = glm::dvec3(q[0], q[1], q[2]);
    uv[static_cast<size_t>(i)] =
      glm::dvec2(tcoords->GetComponent(i, 0), tcoords->GetComponent(i, 1));
  }
  std::vector<std::array<long long, 3>> triangles;
  triangles.reserve(static_cast<size_t>(mesh->GetNumberOfPolys()));
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    if (count == 3)
    {
      triangles.push_back({ static_cast<long long>(ids[0]), static_cast<long long>(ids[1]),
        static_cast<long long>(ids[2]) });
    }
  }
  std::vector<glm::vec2> quadrics;
  try
  {
    quadrics = mesolight::ComputeSurfaceQuadrics(positions, nrm, uv, triangles);
  }
  catch (const std::exception& e)
  {
    error = e.what();
    return false;
  }
  if (!mesolight::AnySurfaceQuadric(quadrics))
  {
    return true;
  }
  vtkNew<vtkFloatArray> array;
  array->SetName(ReliefQuadricsName);
  array->SetNumberOfComponents(2);
  array->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    array->SetTypedComponent(i, 0, quadrics[static_cast<size_t>(i)].x);
    array->SetTypedComponent(i, 1, quadrics[static_cast<size_t>(i)].y);
  }
  mesh->GetPointData()->AddArray(array);
  return true;
}
} // namespace

//------------------------------------------------------------------------------
vtkReliefGeometryCache::vtkReliefGeometryCache() = default;

//------------------------------------------------------------------------------
vtkReliefGeometryCache::~vtkReliefGeometryCache() = default;

//------------------------------------------------------------------------------
const char* vtkReliefGeometryCache::GetReliefTCoordsName()
{
  return ReliefTCoordsName;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkReliefGeometryCache::Prepare(vtkPolyData* input)
{
  if (!input)
  {
    return nullptr;
  }
  PreparedGeometry& cached = this->Prepared[input];
  if (cached.Prepared && input->GetMTime() <= cached.SourceTime)
  {
    return cached.Prepared;
  }
  cached.Prepared = nullptr;
  cached.SourceTime = input->GetMTime();

  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro(<< "The input has no point texture coordinates (2 components). A relief surface "
                     "is addressed by texture coordinates: in ParaView apply Texture Map to "
                     "Plane (or Texture Map to Cylinder/Sphere) to the surface first; in VTK "
                     "use vtkTextureMapToPlane, or tcoords from the mesh file.");
    return nullptr;
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro(<< "The input has no polygons: a relief is drawn on surfaces only (in "
                     "ParaView, apply Extract Surface first).");
    return nullptr;
  }
  for (vtkIdType i = 0; i < tcoords->GetNumberOfTuples(); ++i)
  {
    if (!std::isfinite(tcoords->GetComponent(i, 0)) || !std::isfinite(tcoords->GetComponent(i, 1)))
    {
      vtkErrorMacro(<< "Texture coordinate " << i << " is not finite (NaN or Inf).");
      return nullptr;
    }
  }

  vtkSmartPointer<vtkPolyData> mesh = input;
  if (!AllTriangles(mesh))
  {
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(mesh);
    triangles->PassVertsOff();
    triangles->PassLinesOff();
    triangles->Update();
    mesh = triangles->GetOutput();
  }
  if (!mesh->GetPointData()->GetNormals())
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(mesh);
    normals->SplittingOff();
    normals->ConsistencyOff();
    normals->AutoOrientNormalsOff();
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    normals->Update();
    mesh = normals->GetOutput();
  }
  vtkFloatArray* tangents = vtkFloatArray::SafeDownCast(mesh->GetPointData()->GetTangents());
  if (!tangents || tangents->GetNumberOfComponents() != 3)
  {
    vtkNew<vtkPolyDataTangents> tangentFilter;
    tangentFilter->SetInputData(mesh);
    tangentFilter->ComputePointTangentsOn();
    tangentFilter->ComputeCellTangentsOff();
    tangentFilter->Update();
    mesh = tangentFilter->GetOutput();
    vtkDataArray* computed = mesh->GetPointData()->GetTangents();
    if (!computed)
    {
      vtkErrorMacro(<< "Could not compute tangents for the input.");
      return nullptr;
    }
    // The OpenGL mapper uploads tangents only as floats.
    vtkNew<vtkFloatArray> asFloat;
    asFloat->DeepCopy(computed);
    asFloat->SetName("Tangents");
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(mesh);
    copy->GetPointData()->SetTangents(asFloat);
    mesh = copy;
  }
  else
  {
    vtkNew<vtkPolyData> copy;
    copy->ShallowCopy(mesh);
    vtkNew<vtkFloatArray> own;
    own->DeepCopy(tangents);
    copy->GetPointData()->SetTangents(own);
    mesh = copy;
  }
  SanitizeFrame(mesh);
  vtkNew<vtkFloatArray> reliefTCoords;
  reliefTCoords->SetName(ReliefTCoordsName);
  reliefTCoords->SetNumberOfComponents(2);
  vtkDataArray* meshTCoords = mesh->GetPointData()->GetTCoords();
  reliefTCoords->SetNumberOfTuples(meshTCoords->GetNumberOfTuples());
  for (vtkIdType i = 0; i < meshTCoords->GetNumberOfTuples(); ++i)
  {
    reliefTCoords->SetTypedComponent(i, 0, static_cast<float>(meshTCoords->GetComponent(i, 0)));
    reliefTCoords->SetTypedComponent(i, 1, static_cast<float>(meshTCoords->GetComponent(i, 1)));
  }
  mesh->GetPointData()->AddArray(reliefTCoords);
  std::string error;
  if (!AddQuadrics(mesh, error))
  {
    vtkErrorMacro(<< "Could not compute the surface quadrics of the input: " << error);
    return nullptr;
  }
  cached.Prepared = mesh;
  return mesh;
}

//------------------------------------------------------------------------------
const char* vtkReliefGeometryCache::GetReliefQuadricsName()
{
  return ReliefQuadricsName;
}

//------------------------------------------------------------------------------
bool vtkReliefGeometryCache::IsCurved(vtkPolyData* prepared)
{
  return prepared && prepared->GetPointData()->GetArray(ReliefQuadricsName) != nullptr;
}

//------------------------------------------------------------------------------
void vtkReliefGeometryCache::KeepOnly(const std::vector<vtkPolyData*>& inputs)
{
  for (auto it = this->Prepared.begin(); it != this->Prepared.end();)
  {
    if (std::find(inputs.begin(), inputs.end(), it->first) == inputs.end())
    {
      it = this->Prepared.erase(it);
    }
    else
    {
      ++it;
    }
  }
}

//------------------------------------------------------------------------------
void vtkReliefGeometryCache::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PreparedInputs: " << this->Prepared.size() << "\n";
}
