// SPDX-License-Identifier: BSD-3-Clause
// Filters of this module that need their whole input image (stencils, cones, light sampling,
// writing a file) ask the pipeline for it the same way: its whole extent, as piece 0 of 1. The
// piece matters under MPI (pvbatch, mpiexec): a rank asked for piece 1 of 2 would otherwise pass
// that piece number up, and an image source that cannot split (a reader, a procedural source)
// is run for piece 0 only (vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST): every other rank got an
// empty image. Each rank computes the whole image; what depends on it is needed whole there.
#ifndef vtkWholeExtentRequest_h
#define vtkWholeExtentRequest_h

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace mesolight
{
/** Asks for the whole image on an input port's first connection: its whole extent, piece 0 of 1,
 * no ghost levels. */
inline void RequestWholeInputExtent(vtkInformationVector** inputVector, int port = 0)
{
  if (inputVector[port]->GetNumberOfInformationObjects() > 0)
  {
    vtkInformation* inInfo = inputVector[port]->GetInformationObject(0);
    int wholeExtent[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), wholeExtent, 6);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
}
} // namespace mesolight

#endif
