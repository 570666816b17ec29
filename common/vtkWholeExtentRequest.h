// SPDX-License-Identifier: BSD-3-Clause
// Filters of this module that need their whole input image (stencils, cones, light sampling,
// writing a file) ask the pipeline for it the same way.
#ifndef vtkWholeExtentRequest_h
#define vtkWholeExtentRequest_h

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace mesolight
{
/** Sets the update extent of an input port's first connection to its whole extent. */
inline void RequestWholeInputExtent(vtkInformationVector** inputVector, int port = 0)
{
  if (inputVector[port]->GetNumberOfInformationObjects() > 0)
  {
    vtkInformation* inInfo = inputVector[port]->GetInformationObject(0);
    int wholeExtent[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), wholeExtent, 6);
  }
}
} // namespace mesolight

#endif
