// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVWholeOutputPipeline
 * @brief   ParaView's executive for a filter whose output is the same for every piece asked.
 *
 * The Mesolight filters that need their whole input image (mesolight::RequestWholeInputExtent)
 * make their whole output on every rank, whatever piece is asked for. ParaView's executive still
 * records which piece an output was made for and runs the filter again when another is asked.
 * Under MPI, Apply asks each output for piece r of N, and the Mesolight filters downstream ask
 * for piece 0 of 1: every change baked a relief texture (or cut an environment map into lights)
 * twice on every rank. This executive serves a request for any piece with the output it has;
 * modification times, time steps and a released output decide as in
 * vtkPVCompositeDataPipeline, whose post filters (array conversions) it keeps. The plugin's XML
 * names it (`executive="vtkPVWholeOutputPipeline"`) for these filters.
 */
#ifndef vtkPVWholeOutputPipeline_h
#define vtkPVWholeOutputPipeline_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkPVCompositeDataPipeline.h"

class MESOLIGHTPARAVIEWRELIEF_EXPORT vtkPVWholeOutputPipeline : public vtkPVCompositeDataPipeline
{
public:
  static vtkPVWholeOutputPipeline* New();
  vtkTypeMacro(vtkPVWholeOutputPipeline, vtkPVCompositeDataPipeline);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkPVWholeOutputPipeline();
  ~vtkPVWholeOutputPipeline() override;

  int NeedToExecuteData(
    int outputPort, vtkInformationVector** inInfoVec, vtkInformationVector* outInfoVec) override;

private:
  vtkPVWholeOutputPipeline(const vtkPVWholeOutputPipeline&) = delete;
  void operator=(const vtkPVWholeOutputPipeline&) = delete;
};

#endif
