// SPDX-License-Identifier: BSD-3-Clause
#include "vtkGeometryImageToMesh.h"
#include "vtkGeometryImageToMeshCore.h"

#include "GeometryImageMesh.h"
#include "Progress.h"
#include "vtkWholeExtentRequest.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

vtkStandardNewMacro(vtkGeometryImageToMesh);

//------------------------------------------------------------------------------
vtkGeometryImageToMesh::vtkGeometryImageToMesh()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
void vtkGeometryImageToMesh::SetNormalImageConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
int vtkGeometryImageToMesh::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  // Port 0 is optional too, so that a missing input gets our own, explicit error message.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkGeometryImageToMesh::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Each image whole, whatever its size: a normal image of another size gets our message.
  mesolight::RequestWholeInputExtent(inputVector, 0);
  mesolight::RequestWholeInputExtent(inputVector, 1);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkGeometryImageToMeshCore::ToGeometryImage(vtkImageData* image, vtkImageData* normalImage,
  mesolight::GeometryImage& geometry, std::string& error)
{
  if (!image)
  {
    error = "no geometry image: connect an image whose pixels are XYZ positions";
    return false;
  }
  int dims[3];
  image->GetDimensions(dims);
  if (image->GetNumberOfPoints() < 1 || dims[2] != 1)
  {
    std::ostringstream s;
    s << "the geometry image must be a 2D image; got " << dims[0] << " x " << dims[1] << " x "
      << dims[2] << " pixels";
    error = s.str();
    return false;
  }
  vtkDataArray* positions = image->GetPointData()->GetScalars();
  if (!positions || positions->GetNumberOfComponents() != 3)
  {
    std::ostringstream s;
    s << "a geometry image needs 3 components per pixel (XYZ); got "
      << (positions ? positions->GetNumberOfComponents() : 0)
      << " (a colour or depth image is not a geometry image)";
    error = s.str();
    return false;
  }
  vtkDataArray* normals = nullptr;
  if (normalImage)
  {
    int ndims[3];
    normalImage->GetDimensions(ndims);
    normals = normalImage->GetPointData()->GetScalars();
    if (ndims[0] != dims[0] || ndims[1] != dims[1] || ndims[2] != 1 || !normals ||
      normals->GetNumberOfComponents() != 3)
    {
      std::ostringstream s;
      s << "the normal image must have 3 components and the geometry image's size (" << dims[0]
        << " x " << dims[1] << "); got " << ndims[0] << " x " << ndims[1] << " with "
        << (normals ? normals->GetNumberOfComponents() : 0) << " component(s)";
      error = s.str();
      return false;
    }
  }
  else if (vtkDataArray* own = image->GetPointData()->GetArray("Normals"))
  {
    normals = own->GetNumberOfComponents() == 3 && own != positions ? own : nullptr;
  }
  geometry = mesolight::GeometryImage();
  geometry.Width = dims[0];
  geometry.Height = dims[1];
  const vtkIdType n = image->GetNumberOfPoints();
  geometry.Positions.resize(static_cast<size_t>(n));
  if (normals)
  {
    geometry.Normals.resize(static_cast<size_t>(n));
  }
  for (vtkIdType k = 0; k < n; ++k)
  {
    double p[3];
    positions->GetTuple(k, p);
    geometry.Positions[k] = glm::dvec3(p[0], p[1], p[2]);
    if (normals)
    {
      normals->GetTuple(k, p);
      geometry.Normals[k] = glm::dvec3(p[0], p[1], p[2]);
    }
  }
  return true;
}

namespace
{
// The output and the renderer are single precision: a mesh none of whose triangles has a finite,
// non-zero area there (constant or collinear positions, or positions so small or large that the
// areas underflow or overflow) renders nothing. "" when some triangle is usable, else why not.
std::string DegenerateMeshProblem(const mesolight::GeometryImageMesh& mesh)
{
  glm::dvec3 lower(std::numeric_limits<double>::max());
  glm::dvec3 upper(-std::numeric_limits<double>::max());
  for (const glm::ivec3& t : mesh.Triangles)
  {
    const glm::vec3 a(mesh.Points[t[0]]), b(mesh.Points[t[1]]), c(mesh.Points[t[2]]);
    const glm::vec3 n = glm::cross(b - a, c - a);
    // The cross product itself (area squared would underflow at far larger sizes).
    if (std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) &&
      (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f))
    {
      return std::string();
    }
    for (int k = 0; k < 3; ++k)
    {
      lower = glm::min(lower, mesh.Points[t[k]]);
      upper = glm::max(upper, mesh.Points[t[k]]);
    }
  }
  const glm::dvec3 size = upper - lower;
  const double extent = std::max({ size.x, size.y, size.z });
  std::ostringstream why;
  why << "every triangle has zero or non-finite area in single precision: ";
  if (!(extent > 0.0))
  {
    why << "all its positions are the same point";
  }
  else if (extent > 1e18 || !std::isfinite(static_cast<float>(extent)))
  {
    why << "its positions span " << extent << " units, too large (at most about 1e18)";
  }
  else if (extent < 1e-18)
  {
    why << "its positions span " << extent << " units, too small (at least about 1e-18)";
  }
  else
  {
    why << "its positions are collinear";
  }
  return why.str();
}
} // namespace

//------------------------------------------------------------------------------
int vtkGeometryImageToMesh::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkImageData* normalInput = vtkImageData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro("Missing output.");
    return 0;
  }
  mesolight::GeometryImage geometry;
  std::string error;
  if (!vtkGeometryImageToMeshCore::ToGeometryImage(input, normalInput, geometry, error))
  {
    vtkErrorMacro(<< "Cannot mesh the geometry image: " << error << ".");
    return 0;
  }
  if (input->GetPointData()->GetScalars()->GetDataType() == VTK_UNSIGNED_CHAR)
  {
    // Positions in 256 steps a side are rarely meant: an 8-bit RGB image is a colour picture.
    vtkWarningMacro("The geometry image is 8-bit: its RGB values are read as XYZ positions in "
                    "256 steps. Is it a colour picture? A geometry image stores positions, "
                    "usually as float (.exr, .tif).");
  }
  mesolight::GeometryImageMesh mesh;
  const mesolight::ProgressCallback progress = mesolight::AlgorithmProgress(this);
  try
  {
    mesh = this->Tolerance > 0.0
      ? mesolight::SampleAdaptive(geometry, this->Tolerance, progress, this->MaximumCellSize)
      : mesolight::SampleRegular(geometry, this->Stride, progress);
  }
  catch (const mesolight::GeometryImageMeshError& e)
  {
    vtkErrorMacro(<< "Cannot mesh the geometry image: " << e.what() << ".");
    return 0;
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }
  if (!mesh.Triangles.empty())
  {
    error = DegenerateMeshProblem(mesh);
    if (!error.empty())
    {
      vtkErrorMacro(<< "Cannot mesh the geometry image: " << error << ".");
      return 0;
    }
  }

  const vtkIdType np = static_cast<vtkIdType>(mesh.Points.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(np);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(np);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(np);
  for (vtkIdType k = 0; k < np; ++k)
  {
    const glm::dvec3& p = mesh.Points[k];
    const glm::dvec3& nrm = mesh.Normals[k];
    points->SetPoint(k, p.x, p.y, p.z);
    normals->SetTuple3(k, nrm.x, nrm.y, nrm.z);
    tcoords->SetTuple2(k, mesh.TCoords[k].x, mesh.TCoords[k].y);
  }
  const vtkIdType nt = static_cast<vtkIdType>(mesh.Triangles.size());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(nt + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * nt);
  for (vtkIdType t = 0; t < nt; ++t)
  {
    offsets->SetValue(t, 3 * t);
    for (int c = 0; c < 3; ++c)
    {
      connectivity->SetValue(3 * t + c, mesh.Triangles[t][c]);
    }
  }
  offsets->SetValue(nt, 3 * nt);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->SetNormals(normals);
  output->GetPointData()->SetTCoords(tcoords);
  return 1;
}

//------------------------------------------------------------------------------
void vtkGeometryImageToMesh::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Stride: " << this->Stride << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "MaximumCellSize: " << this->MaximumCellSize << "\n";
}
