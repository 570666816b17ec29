// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReflectionWorker.h"

#include <chrono>

namespace vlf = mesolight::vlf;

//------------------------------------------------------------------------------
vtkLightFieldReflectionWorker::vtkLightFieldReflectionWorker() = default;

//------------------------------------------------------------------------------
vtkLightFieldReflectionWorker::~vtkLightFieldReflectionWorker()
{
  this->Stop();
}

//------------------------------------------------------------------------------
void vtkLightFieldReflectionWorker::Stop()
{
  ++this->Generation;
  if (this->Worker.joinable())
  {
    this->Worker.join();
  }
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->Running = false;
}

//------------------------------------------------------------------------------
void vtkLightFieldReflectionWorker::Cancel()
{
  ++this->Generation;
}

//------------------------------------------------------------------------------
void vtkLightFieldReflectionWorker::Forget()
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->Ready = false;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReflectionWorker::HasLocked(const vlf::ViewFrame& view, std::uint64_t key) const
{
  return this->Ready && this->ReadyView == view && this->ReadyKey == key;
}

//------------------------------------------------------------------------------
void vtkLightFieldReflectionWorker::Trace(const vlf::WalkthroughTracer& tracer,
  const vlf::ViewFrame& view, const vlf::TraceOptions& options, std::uint64_t key)
{
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    if ((this->Running && this->RunningView == view && this->RunningKey == key) ||
      this->HasLocked(view, key))
    {
      return;
    }
  }
  const vlf::PixelRect rect = tracer.MirrorRect(view);
  if (rect.Empty())
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->ReadyImage.clear();
    this->ReadyRect = rect;
    this->ReadyView = view;
    this->ReadyKey = key;
    this->Ready = true;
    return;
  }
  this->Stop();
  const unsigned generation = this->Generation.load();
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Running = true;
    this->RunningView = view;
    this->RunningKey = key;
  }
  const vlf::WalkthroughTracer* traced = &tracer;
  this->Worker = std::thread(
    [this, traced, view, rect, options, generation, key]()
    {
      std::vector<float> image(rect.Pixels() * 4, 0.0f);
      bool cancelled = false;
      for (int row = rect.Y0; row < rect.Y1; ++row)
      {
        if (this->Generation.load() != generation)
        {
          cancelled = true;
          break;
        }
        traced->ShadeRows(
          view, rect, false, vlf::SpecularQuality::Traced, options, row, row + 1, image.data());
      }
      if (!cancelled)
      {
        vlf::WalkthroughTracer::DilateEdges(rect, image.data());
      }
      {
        std::lock_guard<std::mutex> lock(this->Mutex);
        if (!cancelled)
        {
          this->ReadyImage = std::move(image);
          this->ReadyRect = rect;
          this->ReadyView = view;
          this->ReadyKey = key;
          this->Ready = true;
        }
        this->Running = false;
      }
      this->Done.notify_all();
    });
}

//------------------------------------------------------------------------------
bool vtkLightFieldReflectionWorker::Take(
  const vlf::ViewFrame& view, std::uint64_t key, std::vector<float>& image, vlf::PixelRect& rect)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  if (!this->HasLocked(view, key))
  {
    return false;
  }
  image = this->ReadyImage;
  rect = this->ReadyRect;
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReflectionWorker::Wait(
  double seconds, const vlf::ViewFrame& view, std::uint64_t key)
{
  std::unique_lock<std::mutex> lock(this->Mutex);
  this->Done.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return !this->Running; });
  return this->HasLocked(view, key);
}
