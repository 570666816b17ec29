// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAttachReliefTexture.h"

#include "TextureProportions.h"
#include "vtkReliefPlaneFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkWholeExtentRequest.h"

#include <cmath>
#include <sstream>
#include <string>

vtkStandardNewMacro(vtkAttachReliefTexture);

namespace
{
// Field-data names: <prefix>, <prefix>Size, and the image's own field arrays under
// <prefix><name without "Mesolight">.
const char* const ReliefPrefix = "MesolightReliefTexture";
const char* const LightSetPrefix = "MesolightLightSet";
const char* const ColorPrefix = "MesolightColorTexture";
const char* const ImageFieldArrays[] = { "MesolightDepthScale", "MesolightConeType" };
// A flat surface whose drawn proportions differ from the map's by more than this is warned about.
constexpr double StretchTolerance = 0.02;

// How many times as tall as wide, per texture unit, a flat surface draws its texture; 0 when it
// is not a flat vtkPolyData of polygons with texture coordinates (curved meshes are parametrised
// with a stretch of their own).
double FlatSurfaceHeightOverWidth(vtkDataSet* surface)
{
  vtkPolyData* polyData = vtkPolyData::SafeDownCast(surface);
  vtkDataArray* tcoords = polyData ? polyData->GetPointData()->GetTCoords() : nullptr;
  if (!tcoords || tcoords->GetNumberOfComponents() < 2 || !polyData->GetPolys())
  {
    return 0.0;
  }
  mesolight::TextureProportions proportions;
  auto point = [&](vtkIdType id)
  {
    double p[3];
    polyData->GetPoint(id, p);
    return glm::dvec3(p[0], p[1], p[2]);
  };
  auto tcoord = [&](vtkIdType id)
  { return glm::dvec2(tcoords->GetComponent(id, 0), tcoords->GetComponent(id, 1)); };
  const vtkIdType points = polyData->GetNumberOfPoints();
  auto cells = vtk::TakeSmartPointer(polyData->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType size = 0;
    const vtkIdType* ids = nullptr;
    cells->GetCurrentCell(size, ids);
    for (vtkIdType k = 1; k + 1 < size; ++k) // a fan over the polygon
    {
      const vtkIdType a = ids[0], b = ids[k], c = ids[k + 1];
      if (a < 0 || b < 0 || c < 0 || a >= points || b >= points || c >= points)
      {
        return 0.0; // a broken cell: the mapper reports it
      }
      proportions.AddTriangle(point(a), point(b), point(c), tcoord(a), tcoord(b), tcoord(c));
    }
  }
  return proportions.IsFlat() ? proportions.GetHeightOverWidth() : 0.0;
}

vtkSmartPointer<vtkImageData> Detach(vtkDataObject* data, const char* prefix)
{
  vtkFieldData* field = data ? data->GetFieldData() : nullptr;
  if (!field)
  {
    return nullptr;
  }
  vtkDataArray* texels = field->GetArray(prefix);
  vtkDataArray* size = field->GetArray((std::string(prefix) + "Size").c_str());
  if (!texels || !size || size->GetNumberOfValues() < 2)
  {
    return nullptr;
  }
  const int w = static_cast<int>(size->GetComponent(0, 0));
  const int h = static_cast<int>(size->GetComponent(1, 0));
  if (w < 1 || h < 1 || texels->GetNumberOfTuples() != static_cast<vtkIdType>(w) * h)
  {
    return nullptr;
  }
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->GetPointData()->SetScalars(texels); // shared: uploads are keyed by this array
  for (const char* name : ImageFieldArrays)
  {
    if (vtkAbstractArray* a = field->GetAbstractArray((std::string(prefix) + (name + 9)).c_str()))
    {
      vtkSmartPointer<vtkAbstractArray> copy =
        vtkSmartPointer<vtkAbstractArray>::Take(a->NewInstance());
      copy->DeepCopy(a);
      copy->SetName(name);
      image->GetFieldData()->AddArray(copy);
    }
  }
  return image;
}
} // namespace

//------------------------------------------------------------------------------
vtkAttachReliefTexture::vtkAttachReliefTexture()
{
  this->SetNumberOfInputPorts(4);
}

//------------------------------------------------------------------------------
void vtkAttachReliefTexture::SetReliefTextureConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
void vtkAttachReliefTexture::SetLightSetConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(2, output);
}

//------------------------------------------------------------------------------
void vtkAttachReliefTexture::SetColorTextureConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(3, output);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkAttachReliefTexture::GetAttachedReliefTexture(vtkDataObject* data)
{
  return Detach(data, ReliefPrefix);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkAttachReliefTexture::GetAttachedLightSet(vtkDataObject* data)
{
  return Detach(data, LightSetPrefix);
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> vtkAttachReliefTexture::GetAttachedColorTexture(vtkDataObject* data)
{
  return Detach(data, ColorPrefix);
}

//------------------------------------------------------------------------------
int vtkAttachReliefTexture::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  // The relief texture (port 1) is needed, but a missing one is said by RequestData in the
  // user's words (the executive's 'has 0 connections but is not optional' named no fix), and
  // the surface still passes on.
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkAttachReliefTexture::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // The surface gets the requested piece; the textures are needed whole on every piece.
  this->Superclass::RequestUpdateExtent(request, inputVector, outputVector);
  mesolight::RequestWholeInputExtent(inputVector, 1);
  mesolight::RequestWholeInputExtent(inputVector, 2);
  mesolight::RequestWholeInputExtent(inputVector, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkAttachReliefTexture::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0], 0);
  vtkImageData* relief = vtkImageData::GetData(inputVector[1], 0);
  vtkImageData* lights = inputVector[2]->GetNumberOfInformationObjects() > 0
    ? vtkImageData::GetData(inputVector[2], 0)
    : nullptr;
  vtkImageData* color = inputVector[3]->GetNumberOfInformationObjects() > 0
    ? vtkImageData::GetData(inputVector[3], 0)
    : nullptr;
  vtkDataSet* output = vtkDataSet::GetData(outputVector, 0);
  if (!input || !output)
  {
    vtkErrorMacro(<< "No input surface.");
    return 0;
  }
  output->ShallowCopy(input);
  vtkNew<vtkFieldData> field; // the input's field data stays untouched
  field->ShallowCopy(input->GetFieldData());
  output->SetFieldData(field);
  if (inputVector[1]->GetNumberOfInformationObjects() == 0)
  {
    vtkErrorMacro(<< "No Relief Texture input: connect Mesolight Relief Texture's (or Cone Map's) "
                     "output as the Relief Texture input (ParaView: select this filter, then Edit "
                     "> Change Input...; VTK: SetReliefTextureConnection). The surface is passed "
                     "on without a relief.");
    return 1;
  }
  if (!this->Attach(relief, 1, ReliefPrefix, field))
  {
    vtkErrorMacro(<< "The relief texture (input port 1) must be a non-empty 2D image with point "
                     "scalars: connect Mesolight Relief Texture's (or Cone Map's) output as the "
                     "Relief Texture input (VTK: vtkReliefTextureFilter's output).");
    return 0;
  }
  // A flat surface that draws the map out of its proportions (ParaView's Plane is square
  // whatever the map) stretches every feature of the relief: say so, and what to use instead.
  const double drawn = FlatSurfaceHeightOverWidth(input);
  const double ground = vtkReliefPlaneFilter::GetGroundProportions(relief);
  std::string stretchWarning;
  if (drawn > 0.0 && std::abs(std::log(drawn / ground)) > std::log(1.0 + StretchTolerance))
  {
    std::ostringstream stretch;
    stretch.precision(3);
    stretch << "The surface draws the relief texture at a height / width of " << drawn
            << " (per unit of its texture coordinates), where the map's height / width on the "
               "ground is "
            << ground << ": every feature of the relief is drawn "
            << (drawn > ground ? drawn / ground : ground / drawn)
            << (drawn > ground ? " times too tall" : " times too wide")
            << ". Make the surface with Filters > Mesolight > Mesolight Relief Plane (input: the "
               "Relief Texture), which takes the map's proportions, or scale the texture "
               "coordinates: for a surface placed on a wall, a Calculator before this filter "
               "(Point Data, Result TCoords, e.g. TextureCoordinates_X * "
            << (drawn < ground ? ground / drawn : 1.0) << " * iHat + TextureCoordinates_Y * "
            << (drawn > ground ? drawn / ground : 1.0)
            << " * jHat) repeats the map at its proportions (VTK: vtkReliefPlaneFilter).";
    stretchWarning = stretch.str();
  }
  // Once, not at every re-execution (a colour texture attached, a setting changed).
  if (!stretchWarning.empty() && stretchWarning != this->LastStretchWarning)
  {
    vtkWarningMacro(<< stretchWarning);
  }
  this->LastStretchWarning = stretchWarning;
  // A light set or colour image that cannot be attached (an empty one from a source that failed,
  // e.g. Median Cut Lights on a 1 x 1 map) is an error, but the relief stays: drawn without it
  // (lit by the view's lights; its own colour), as the mapper draws a malformed light set.
  if (lights && !this->Attach(lights, 2, LightSetPrefix, field))
  {
    vtkErrorMacro(<< "The light set (input port 2) must be a non-empty 2D image with point "
                     "scalars: connect Mesolight Median Cut Lights' second output (LightTexture) "
                     "as the Light Set input (VTK: vtkMedianCutLights' output port 1); if its "
                     "source failed, see its error. The relief is drawn without it.");
  }
  if (color && !this->Attach(color, 3, ColorPrefix, field))
  {
    vtkErrorMacro(<< "The colour texture (input port 3) must be a non-empty 2D image with point "
                     "scalars in the relief texture's coordinates, e.g. Mesolight Depth "
                     "Hallucination's Albedo output. The relief is drawn without it.");
  }
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkAttachReliefTexture::Attach(
  vtkImageData* image, int port, const char* prefix, vtkFieldData* field)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  if (!scalars || dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    return false;
  }
  AttachedArray& kept = this->AttachedArrays[port];
  if (kept.Source != scalars || kept.SourceTime != scalars->GetMTime() || !kept.Attached)
  {
    kept.Attached = vtkSmartPointer<vtkDataArray>::Take(scalars->NewInstance());
    kept.Attached->ShallowCopy(scalars); // the same memory under our name
    kept.Attached->SetName(prefix);
    kept.Source = scalars;
    kept.SourceTime = scalars->GetMTime();
  }
  field->AddArray(kept.Attached);
  vtkNew<vtkIntArray> size;
  size->SetName((std::string(prefix) + "Size").c_str());
  size->InsertNextValue(dims[0]);
  size->InsertNextValue(dims[1]);
  field->AddArray(size);
  for (const char* name : ImageFieldArrays)
  {
    if (vtkAbstractArray* a = image->GetFieldData()->GetAbstractArray(name))
    {
      vtkSmartPointer<vtkAbstractArray> copy =
        vtkSmartPointer<vtkAbstractArray>::Take(a->NewInstance());
      copy->DeepCopy(a);
      copy->SetName((std::string(prefix) + (name + 9)).c_str()); // drop "Mesolight"
      field->AddArray(copy);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkAttachReliefTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
