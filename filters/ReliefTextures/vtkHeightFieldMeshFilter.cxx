// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHeightFieldMeshFilter.h"
#include "ParallelFor.h"
#include "Progress.h"

#include "ScalarConversion.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkHeightFieldMeshFilter);

namespace
{
template <typename T>
void ToUnitRGBA(const T* data, vtkIdType n, float* out)
{
  mesolight::ParallelFor(0, static_cast<std::size_t>(4 * n), 0,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        out[k] = static_cast<float>(mesolight::ToUnitValue(data[k]));
      }
    });
}

/// Serial chunks of a parallel loop over [0, n): progress + abort from the calling thread.
template <typename Functor>
bool ChunkedFor(
  vtkAlgorithm* self, vtkIdType n, double progressBegin, double progressEnd, const Functor& functor)
{
  const vtkIdType chunks = std::max<vtkIdType>(1, std::min<vtkIdType>(n, 16));
  for (vtkIdType c = 0; c < chunks; ++c)
  {
    if (self->GetAbortExecute())
    {
      return false;
    }
    mesolight::ParallelFor(static_cast<std::size_t>(n * c / chunks),
      static_cast<std::size_t>(n * (c + 1) / chunks), 0,
      [&](std::size_t begin, std::size_t end)
      { functor(static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end)); });
    self->UpdateProgress(
      progressBegin + (progressEnd - progressBegin) * static_cast<double>(c + 1) / chunks);
  }
  return true;
}
}

//------------------------------------------------------------------------------
vtkHeightFieldMeshFilter::vtkHeightFieldMeshFilter() = default;

//------------------------------------------------------------------------------
int vtkHeightFieldMeshFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  // Optional so that a missing input gets our own, explicit error message.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkHeightFieldMeshFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!input)
  {
    vtkErrorMacro("No input: connect a relief texture (e.g. vtkReliefTextureFilter's output).");
    return 0;
  }
  if (!output)
  {
    vtkErrorMacro("Missing output.");
    return 0;
  }

  int dims[3];
  input->GetDimensions(dims);
  if (input->GetNumberOfPoints() < 1 || dims[0] < 1 || dims[1] < 1)
  {
    vtkErrorMacro("The input relief texture is empty.");
    return 0;
  }
  if (dims[2] != 1)
  {
    vtkErrorMacro("The input relief texture must be a 2D image in the XY plane; got "
      << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
    return 0;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  const vtkIdType n = input->GetNumberOfPoints();
  if (!scalars || scalars->GetNumberOfComponents() != 4 || scalars->GetNumberOfTuples() != n)
  {
    vtkErrorMacro("The input must be a relief texture: point scalars with 4 components "
                  "(RGB = packed normal, A = depth), one tuple per texel; got "
      << (scalars ? scalars->GetNumberOfComponents() : 0) << " component(s).");
    return 0;
  }
  const int w = dims[0];
  const int h = dims[1];

  // Relief texels as unit floats (float/double as is, integers / type max).
  std::vector<float> rgba(static_cast<size_t>(4 * n));
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(
      ToUnitRGBA(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)), n, rgba.data()));
    default:
      vtkErrorMacro("Unsupported relief scalar type " << scalars->GetDataTypeAsString() << ".");
      return 0;
  }

  // Depth scale: the baked one (field data) when asked for, else DepthScale.
  bool hasBaked = false;
  double bakedScale = 0.0;
  if (vtkDataArray* baked = input->GetFieldData()->GetArray("MesolightDepthScale"))
  {
    if (baked->GetNumberOfTuples() > 0 && std::isfinite(baked->GetComponent(0, 0)))
    {
      hasBaked = true;
      bakedScale = baked->GetComponent(0, 0);
    }
  }
  const double depthScale = (this->UseInputDepthScale && hasBaked) ? bakedScale : this->DepthScale;
  double normalRatio = 1.0;
  if (hasBaked && depthScale != bakedScale)
  {
    if (bakedScale > 0.0)
    {
      // n ~ (k dd/dx, k dd/dy, 1): changing k scales the tangential components.
      normalRatio = depthScale / bakedScale;
    }
    else
    {
      vtkWarningMacro("The normals were baked with DepthScale 0 (flat): they cannot be "
                      "rescaled to DepthScale "
        << depthScale << " and are used as they are.");
    }
  }

  // Frame of the textured plane.
  double a[3];
  double b[3];
  vtkMath::Subtract(this->Point1, this->Origin, a);
  vtkMath::Subtract(this->Point2, this->Origin, b);
  const double width = vtkMath::Norm(a);
  double lengthB = vtkMath::Norm(b);
  double nrm[3];
  vtkMath::Cross(a, b, nrm);
  if (width <= 0.0 || lengthB <= 0.0 || vtkMath::Normalize(nrm) <= 0.0)
  {
    vtkErrorMacro("Origin, Point1 and Point2 must span a plane (non-zero, non-parallel edges).");
    return 0;
  }
  double t[3] = { a[0] / width, a[1] / width, a[2] / width };
  double bn[3] = { b[0] / lengthB, b[1] / lengthB, b[2] / lengthB };
  const double squareLengthB = width * static_cast<double>(h) / static_cast<double>(w);
  if (this->SquareTexels)
  {
    lengthB = squareLengthB;
    b[0] = bn[0] * lengthB;
    b[1] = bn[1] * lengthB;
    b[2] = bn[2] * lengthB;
  }
  // The normals are baked for square texels; texels stretched along v (a
  // geographic map on its ground proportions) make every slope along v that much gentler.
  const double normalRatioV = normalRatio * squareLengthB / lengthB;
  const double displacement = depthScale * width;

  if (w == 1 || h == 1)
  {
    vtkWarningMacro("The relief texture is " << w << " x " << h
                                             << " texels: no quads, the mesh has points only.");
  }

  // Points, normals, texture coordinates, depth.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> depthArray;
  depthArray->SetName("Depth");
  depthArray->SetNumberOfComponents(1);
  depthArray->SetNumberOfTuples(n);

  float* pts = static_cast<float*>(points->GetVoidPointer(0));
  float* nor = normals->GetPointer(0);
  float* tc = tcoords->GetPointer(0);
  float* dep = depthArray->GetPointer(0);
  const float* texels = rgba.data();
  const double* origin = this->Origin;
  const auto makePoints = [&](vtkIdType begin, vtkIdType end)
  {
    for (vtkIdType k = begin; k < end; ++k)
    {
      const int i = static_cast<int>(k % w);
      const int j = static_cast<int>(k / w);
      const double u = (i + 0.5) / w;
      const double v = (j + 0.5) / h;
      const float* texel = texels + 4 * k;
      const double d = texel[3];
      for (int c = 0; c < 3; ++c)
      {
        pts[3 * k + c] =
          static_cast<float>(origin[c] + u * a[c] + v * b[c] - nrm[c] * d * displacement);
      }
      // Unpack the tangent-space normal and bring it to world space.
      double tn[3] = { (2.0 * texel[0] - 1.0) * normalRatio, (2.0 * texel[1] - 1.0) * normalRatioV,
        2.0 * texel[2] - 1.0 };
      double wn[3];
      for (int c = 0; c < 3; ++c)
      {
        wn[c] = tn[0] * t[c] + tn[1] * bn[c] + tn[2] * nrm[c];
      }
      if (vtkMath::Normalize(wn) <= 0.0)
      {
        wn[0] = nrm[0];
        wn[1] = nrm[1];
        wn[2] = nrm[2];
      }
      for (int c = 0; c < 3; ++c)
      {
        nor[3 * k + c] = static_cast<float>(wn[c]);
      }
      tc[2 * k] = static_cast<float>(u);
      tc[2 * k + 1] = static_cast<float>(v);
      dep[k] = static_cast<float>(d);
    }
  };
  if (!ChunkedFor(this, n, 0.0, 0.7, makePoints))
  {
    return 1;
  }

  // Two triangles per grid quad, counter-clockwise seen from +N.
  const vtkIdType quadsX = w - 1;
  const vtkIdType quads = static_cast<vtkIdType>(w - 1) * (h - 1);
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(2 * quads + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(6 * quads);
  vtkIdType* off = offsets->GetPointer(0);
  vtkIdType* conn = connectivity->GetPointer(0);
  const auto makeTriangles = [&](vtkIdType begin, vtkIdType end)
  {
    for (vtkIdType q = begin; q < end; ++q)
    {
      const vtkIdType i = q % quadsX;
      const vtkIdType j = q / quadsX;
      const vtkIdType p00 = j * w + i;
      const vtkIdType p10 = p00 + 1;
      const vtkIdType p01 = p00 + w;
      const vtkIdType p11 = p01 + 1;
      vtkIdType* c = conn + 6 * q;
      c[0] = p00;
      c[1] = p10;
      c[2] = p11;
      c[3] = p00;
      c[4] = p11;
      c[5] = p01;
      off[2 * q] = 6 * q;
      off[2 * q + 1] = 6 * q + 3;
    }
  };
  if (quads > 0 && !ChunkedFor(this, quads, 0.7, 1.0, makeTriangles))
  {
    return 1;
  }
  off[2 * quads] = 6 * quads;
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->SetNormals(normals);
  output->GetPointData()->SetTCoords(tcoords);
  output->GetPointData()->AddArray(depthArray);
  return 1;
}

//------------------------------------------------------------------------------
void vtkHeightFieldMeshFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Point1: (" << this->Point1[0] << ", " << this->Point1[1] << ", "
     << this->Point1[2] << ")\n";
  os << indent << "Point2: (" << this->Point2[0] << ", " << this->Point2[1] << ", "
     << this->Point2[2] << ")\n";
  os << indent << "SquareTexels: " << (this->SquareTexels ? "On" : "Off") << "\n";
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "UseInputDepthScale: " << (this->UseInputDepthScale ? "On" : "Off") << "\n";
}
