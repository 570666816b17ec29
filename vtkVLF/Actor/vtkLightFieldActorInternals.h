// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor's state shared with vtkLightFieldMapper (private header): the field, its
// tracer and atlas, the scene polydata, this frame's screen image and the progressive worker.
#ifndef vtkLightFieldActorInternals_h
#define vtkLightFieldActorInternals_h

#include "vtkLightFieldActor.h"

#include "LightField.h"
#include "TextureAtlas.h"
#include "WalkthroughTracer.h"

#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

struct vtkLightFieldActor::Internals
{
  std::unique_ptr<mesolight::vlf::LightField> Owned; // LoadLightField's
  const mesolight::vlf::LightField* Field = nullptr;
  std::unique_ptr<mesolight::vlf::WalkthroughTracer> Tracer;
  std::unique_ptr<mesolight::vlf::TextureAtlas> Atlas;
  vtkSmartPointer<vtkPolyData> Scene;
  unsigned long AtlasVersion = 0; // bumped whenever the atlas changes

  // This frame's screen image: RGBA floats over Rect (viewport pixels), placed at window pixel
  // Origin; AllScreen in raytrace mode.
  mesolight::vlf::PixelRect Rect;
  int Origin[2] = { 0, 0 };
  std::vector<float> Screen;
  bool AllScreen = false;
  bool ScreenValid = false; // the mapper may use Screen this frame

  // Progressive worker: traces the reflections of one view on its own thread.
  std::thread Worker;
  std::atomic<unsigned> Generation{ 0 };
  std::mutex Mutex;
  std::condition_variable Done;
  bool WorkerRunning = false;
  mesolight::vlf::ViewFrame WorkerView;
  int WorkerKey = 0; // trace options the worker uses (vtkLightFieldActor::TraceKey)
  bool SharpReady = false;
  int SharpKey = 0;
  mesolight::vlf::ViewFrame SharpView;
  mesolight::vlf::PixelRect SharpRect;
  std::vector<float> Sharp;

  mesolight::vlf::ViewFrame LastView;
  bool HaveLastView = false;
  bool WarnedNoMirrors = false;
  bool WarnedParallel = false;
  bool WarnedInsideWall = false;

  void StopWorker()
  {
    ++this->Generation;
    if (this->Worker.joinable())
    {
      this->Worker.join();
    }
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->WorkerRunning = false;
  }
  ~Internals() { this->StopWorker(); }
};

#endif
