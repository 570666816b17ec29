// SPDX-License-Identifier: BSD-3-Clause
#include "vtkProceduralReliefSource.h"
#include "ParallelFor.h"
#include "Progress.h"

#include "ProceduralHeightFields.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cctype>
#include <cstring>

vtkStandardNewMacro(vtkProceduralReliefSource);

namespace
{
const char* const PatternNames[vtkProceduralReliefSource::NUMBER_OF_PATTERNS] = { "Bricks", "Stone",
  "HemisphereTorus", "Flat", "SineWave" };

bool EqualsNoCase(const char* a, const char* b)
{
  for (; *a && *b; ++a, ++b)
  {
    if (std::tolower(static_cast<unsigned char>(*a)) !=
      std::tolower(static_cast<unsigned char>(*b)))
    {
      return false;
    }
  }
  return *a == *b;
}
}

//------------------------------------------------------------------------------
vtkProceduralReliefSource::vtkProceduralReliefSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
const char* vtkProceduralReliefSource::GetPatternName(int pattern)
{
  if (pattern < 0 || pattern >= NUMBER_OF_PATTERNS)
  {
    return nullptr;
  }
  return PatternNames[pattern];
}

//------------------------------------------------------------------------------
bool vtkProceduralReliefSource::SetPatternByName(const char* name)
{
  if (name)
  {
    for (int p = 0; p < NUMBER_OF_PATTERNS; ++p)
    {
      if (EqualsNoCase(name, PatternNames[p]))
      {
        this->SetPattern(p);
        return true;
      }
    }
  }
  vtkErrorMacro("Unknown pattern name \""
    << (name ? name : "(null)")
    << "\"; expected one of Bricks, Stone, HemisphereTorus, Flat, SineWave.");
  return false;
}

//------------------------------------------------------------------------------
void vtkProceduralReliefSource::SetResolution(int w, int h)
{
  w = std::min(16384, std::max(1, w));
  h = std::min(16384, std::max(1, h));
  if (w != this->Resolution[0] || h != this->Resolution[1])
  {
    this->Resolution[0] = w;
    this->Resolution[1] = h;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkProceduralReliefSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int extent[6] = { 0, this->Resolution[0] - 1, 0, this->Resolution[1] - 1, 0, 0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
    outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  }
  vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(0), VTK_FLOAT, 1);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outputVector->GetInformationObject(1), VTK_UNSIGNED_CHAR, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkProceduralReliefSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  vtkImageData* depthImage = vtkImageData::GetData(outputVector, 0);
  vtkImageData* albedoImage = vtkImageData::GetData(outputVector, 1);
  if (!depthImage || !albedoImage)
  {
    vtkErrorMacro("Missing output image.");
    return 0;
  }

  const int w = this->Resolution[0];
  const int h = this->Resolution[1];
  // The pattern is cheap to sample, so the whole extent is always produced.
  for (vtkImageData* image : { depthImage, albedoImage })
  {
    image->Initialize();
    image->SetExtent(0, w - 1, 0, h - 1, 0, 0);
    image->SetOrigin(0.0, 0.0, 0.0);
    image->SetSpacing(1.0, 1.0, 1.0);
  }

  const vtkIdType n = static_cast<vtkIdType>(w) * h;
  vtkNew<vtkFloatArray> depth;
  depth->SetName("Depth");
  depth->SetNumberOfComponents(1);
  depth->SetNumberOfTuples(n);
  vtkNew<vtkUnsignedCharArray> albedo;
  albedo->SetName("Albedo");
  albedo->SetNumberOfComponents(3);
  albedo->SetNumberOfTuples(n);

  mesolight::HeightFieldParameters params;
  params.Pattern = static_cast<mesolight::ReliefPattern>(this->Pattern);
  params.Seed = this->Seed;
  params.BrickRows = this->BrickRows;
  params.BrickColumns = this->BrickColumns;
  params.MortarWidth = static_cast<float>(this->MortarWidth);
  params.StoneOctaves = this->StoneOctaves;
  params.FlatDepth = static_cast<float>(this->FlatDepth);
  params.SineFrequency[0] = this->SineFrequency[0];
  params.SineFrequency[1] = this->SineFrequency[1];

  float* depthPtr = depth->GetPointer(0);
  unsigned char* albedoPtr = albedo->GetPointer(0);

  // Rows are generated in parallel, in a few serial chunks so that progress can be
  // reported and an abort honoured from the calling thread.
  const int chunks = std::max(1, std::min(h, 16));
  for (int c = 0; c < chunks && !this->GetAbortExecute(); ++c)
  {
    const int rowBegin = static_cast<int>(static_cast<long long>(h) * c / chunks);
    const int rowEnd = static_cast<int>(static_cast<long long>(h) * (c + 1) / chunks);
    mesolight::ParallelFor(static_cast<std::size_t>(rowBegin), static_cast<std::size_t>(rowEnd), 0,
      [&](std::size_t begin, std::size_t end)
      {
        mesolight::GenerateHeightFieldRows(
          params, w, h, static_cast<int>(begin), static_cast<int>(end), depthPtr, albedoPtr);
      });
    this->UpdateProgress(static_cast<double>(c + 1) / chunks);
  }

  depthImage->GetPointData()->SetScalars(depth);
  albedoImage->GetPointData()->SetScalars(albedo);
  return 1;
}

//------------------------------------------------------------------------------
void vtkProceduralReliefSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const char* name = GetPatternName(this->Pattern);
  os << indent << "Pattern: " << (name ? name : "(invalid)") << "\n";
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "FlatDepth: " << this->FlatDepth << "\n";
  os << indent << "SineFrequency: (" << this->SineFrequency[0] << ", " << this->SineFrequency[1]
     << ")\n";
  os << indent << "BrickRows: " << this->BrickRows << "\n";
  os << indent << "BrickColumns: " << this->BrickColumns << "\n";
  os << indent << "MortarWidth: " << this->MortarWidth << "\n";
  os << indent << "StoneOctaves: " << this->StoneOctaves << "\n";
}
