// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVWholeOutputPipeline.h"

#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"

#include <algorithm>

vtkStandardNewMacro(vtkPVWholeOutputPipeline);

//------------------------------------------------------------------------------
vtkPVWholeOutputPipeline::vtkPVWholeOutputPipeline() = default;

//------------------------------------------------------------------------------
vtkPVWholeOutputPipeline::~vtkPVWholeOutputPipeline() = default;

//------------------------------------------------------------------------------
void vtkPVWholeOutputPipeline::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}

//------------------------------------------------------------------------------
int vtkPVWholeOutputPipeline::NeedToExecuteData(
  int outputPort, vtkInformationVector** inInfoVec, vtkInformationVector* outInfoVec)
{
  if (outputPort >= 0 && outputPort < outInfoVec->GetNumberOfInformationObjects())
  {
    vtkInformation* outInfo = outInfoVec->GetInformationObject(outputPort);
    vtkDataObject* data = outInfo->Get(vtkDataObject::DATA_OBJECT());
    vtkInformation* dataInfo = data ? data->GetInformation() : nullptr;
    // An output that was made (it records its piece) is the whole result: it is the piece asked
    // for, whichever that is, and needs no ghost levels (it has no piece boundaries).
    if (dataInfo && dataInfo->Has(vtkDataObject::DATA_NUMBER_OF_PIECES()) &&
      outInfo->Has(UPDATE_NUMBER_OF_PIECES()))
    {
      dataInfo->Set(vtkDataObject::DATA_PIECE_NUMBER(), outInfo->Get(UPDATE_PIECE_NUMBER()));
      dataInfo->Set(
        vtkDataObject::DATA_NUMBER_OF_PIECES(), outInfo->Get(UPDATE_NUMBER_OF_PIECES()));
      dataInfo->Set(vtkDataObject::DATA_NUMBER_OF_GHOST_LEVELS(),
        std::max(dataInfo->Get(vtkDataObject::DATA_NUMBER_OF_GHOST_LEVELS()),
          outInfo->Get(UPDATE_NUMBER_OF_GHOST_LEVELS())));
    }
  }
  return this->Superclass::NeedToExecuteData(outputPort, inInfoVec, outInfoVec);
}
