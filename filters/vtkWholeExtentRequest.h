// Filters of this module that need their whole input image (stencils, cones, light sampling,
// writing a file) ask the pipeline for it the same way.
#ifndef vtkWholeExtentRequest_h
#define vtkWholeExtentRequest_h

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace mesolight
{
/** Sets the update extent of input port 0's first connection to its whole extent. */
inline void RequestWholeInputExtent(vtkInformationVector** inputVector)
{
  if (inputVector[0]->GetNumberOfInformationObjects() > 0)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    int wholeExtent[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), wholeExtent, 6);
  }
}
} // namespace mesolight

#endif
