// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor's state shared with vtkLightFieldMapper (private header): the field, its
// tracer and atlas, the scene polydata, this frame's screen image and the progressive worker.
#ifndef vtkLightFieldActorInternals_h
#define vtkLightFieldActorInternals_h

#include "vtkLightFieldActor.h"

#include "EmitterLights.h"
#include "IrradianceVolume.h"
#include "LightField.h"
#include "ObjectGatherer.h"
#include "ObjectMesh.h"
#include "TextureAtlas.h"
#include "WalkthroughTracer.h"

#include "vtkActor.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

// Seconds since t: the figures vtkLightFieldActor's GetLast*Seconds report.
inline double SecondsSince(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

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
  std::uint64_t WorkerKey = 0; // trace options the worker uses (vtkLightFieldActor::TraceKey)
  bool SharpReady = false;
  std::uint64_t SharpKey = 0;
  mesolight::vlf::ViewFrame SharpView;
  mesolight::vlf::PixelRect SharpRect;
  std::vector<float> Sharp;

  mesolight::vlf::ViewFrame LastView;
  bool HaveLastView = false;
  bool WarnedNoMirrors = false;
  bool WarnedParallel = false;
  bool WarnedInsideWall = false;

  // The movable object (vtkLightFieldActor::SetMovableObject): its actor (weak), its mesh in
  // model coordinates as last read, its placement (model -> unit sphere), its gathered shading.
  vtkWeakPointer<vtkActor> Object;
  vtkPolyData* ObjectData = nullptr; // identity only, never dereferenced after it changes
  vtkMTimeType ObjectDataTime = 0;
  mesolight::vlf::ObjectMesh ObjectModel;
  unsigned long ObjectMeshVersion = 0; // bumped when ObjectModel is reread
  bool ObjectUsable = false;
  bool ObjectPlaced = false;
  glm::mat4 ObjectPlacement{ 1.0f };
  int ObjectGatherSubdivision = -1;
  int ObjectGatherDirections = -1;
  int ObjectGatherVolume = -1;
  unsigned long ObjectGatherMesh = 0;
  bool ObjectIgnored = false;
  unsigned long TracedMesh = 0; // (mesh version, subdivision) the tracer's instance holds
  int TracedSubdivision = -1;
  unsigned long ObjectVersion = 1;
  unsigned long ObjectVersionAtLastFrame = 0;
  std::unique_ptr<mesolight::vlf::ObjectGatherer> Gatherer;
  bool Gathered = false;
  // The irradiance volume of ObjectIrradianceVolume, for the field it was built from.
  std::unique_ptr<mesolight::vlf::IrradianceVolume> Volume;
  const mesolight::vlf::LightField* VolumeField = nullptr;
  int VolumeResolution = 0;
  std::unique_ptr<mesolight::vlf::LightApproximation> Lights;
  std::string ObjectProblemWarned;
  void ForgetObjectState()
  {
    this->ObjectData = nullptr;
    this->ObjectDataTime = 0;
    this->ObjectUsable = false;
    this->ObjectPlaced = false;
    this->ObjectGatherSubdivision = -1;
    this->ObjectGatherDirections = -1;
    this->ObjectGatherVolume = -1;
    this->TracedMesh = 0;
    this->TracedSubdivision = -1;
    this->Gatherer.reset();
    this->Gathered = false;
    this->Lights.reset();
    ++this->ObjectVersion;
  }

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
