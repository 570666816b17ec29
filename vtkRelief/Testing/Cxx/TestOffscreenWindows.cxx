// SPDX-License-Identifier: BSD-3-Clause
// Many offscreen windows, one after another, in one process: what the GL tests and the CLI do.
// Each window's X connection closes before the next one opens, so the X server sees its last
// client leave every time. An Xvfb started without -noreset resets then, and a window that
// connects during the reset aborts in VTK ("bad X server connection"); under scripts/xvfb.sh
// (-noreset) every window opens. Run under plain `xvfb-run -a`, this test aborts within a few
// dozen windows.
#include "ImageCompare.h"
#include "ReliefScene.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

TEST(OffscreenWindows, TwoHundredWindowsOneAfterAnother)
{
  using namespace mesolight;
  vtkNew<vtkSphereSource> sphere;
  ReliefSceneOptions size;
  size.Width = size.Height = 64;
  for (int i = 0; i < 200; ++i)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    auto window = MakeOffscreenWindow(size, renderer);
    const Frame frame = CaptureFrame(window);
    ASSERT_GT(CompareFrames(frame, frame, 1.0).CoveredBoth, 64 * 64 / 10) << "window " << i;
  }
}
