// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldReflectionWorker
 * @brief   the progressive mode's worker thread: traces the reflections of one resting view
 *
 * Private to Mesolight::LightFieldActor (header not installed). Wither 2005 §2.4.2.2.3: the
 * high-quality rendering progresses in another thread while the view rests. Trace() starts one
 * thread on the mirror rectangle of a view, row by row, abandoned between rows by Cancel() or
 * Stop(); the finished image is kept with the view and the trace key (options, object, shadows)
 * it belongs to, and Take() hands it over when a frame shows that same view and key. Stop()
 * must run before anything the thread reads (the tracer, the field, the object's instance, the
 * shadow maps) changes or goes away.
 */
#ifndef vtkLightFieldReflectionWorker_h
#define vtkLightFieldReflectionWorker_h

#include "WalkthroughTracer.h" // For ViewFrame, PixelRect, TraceOptions

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

class vtkLightFieldReflectionWorker
{
public:
  vtkLightFieldReflectionWorker();
  ~vtkLightFieldReflectionWorker(); // stops the thread
  vtkLightFieldReflectionWorker(const vtkLightFieldReflectionWorker&) = delete;
  vtkLightFieldReflectionWorker& operator=(const vtkLightFieldReflectionWorker&) = delete;

  /** Cancels the trace under way and waits for its thread to end. */
  void Stop();
  /** Cancels the trace under way at its next row, without waiting (the view changed). */
  void Cancel();
  /** Drops the finished image (the field changed). */
  void Forget();

  /**
   * Traces the reflections of view with tracer unless the finished image or the trace under
   * way is already that of (view, key). A view without mirrors is finished at once (empty).
   */
  void Trace(const mesolight::vlf::WalkthroughTracer& tracer, const mesolight::vlf::ViewFrame& view,
    const mesolight::vlf::TraceOptions& options, std::uint64_t key);
  /** Copies the finished image of (view, key) and its rectangle; false when there is none. */
  bool Take(const mesolight::vlf::ViewFrame& view, std::uint64_t key, std::vector<float>& image,
    mesolight::vlf::PixelRect& rect);
  /** Waits until no trace runs or seconds passed; true when the image of (view, key) is
   * finished. */
  bool Wait(double seconds, const mesolight::vlf::ViewFrame& view, std::uint64_t key);

private:
  bool HasLocked(const mesolight::vlf::ViewFrame& view, std::uint64_t key) const;

  std::thread Worker;
  std::atomic<unsigned> Generation{ 0 };
  std::mutex Mutex;
  std::condition_variable Done;
  bool Running = false;
  mesolight::vlf::ViewFrame RunningView;
  std::uint64_t RunningKey = 0;
  bool Ready = false;
  std::uint64_t ReadyKey = 0;
  mesolight::vlf::ViewFrame ReadyView;
  mesolight::vlf::PixelRect ReadyRect;
  std::vector<float> ReadyImage;
};

#endif
