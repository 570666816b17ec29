// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Progress.h
 * @brief The one progress and abort convention of the Mesolight cores (plain C++17).
 *
 * A core takes a ProgressCallback, calls it with the fraction done in [0, 1] (non-decreasing)
 * and stops when it returns false: it then returns its "aborted" result (an empty image or map)
 * or throws its module's aborted error (MedianCutAbortedError, HallucinationAbortedError,
 * vlf::AbortedError). An empty callback never aborts. Callers that own only part of the work hand
 * on SubProgress(whole, begin, end); VTK filters hand on AlgorithmProgress(this), which maps the
 * fraction to UpdateProgress and GetAbortExecute (the abort flag VTK 9.1 and ParaView 5.11's VTK
 * both have).
 */
#ifndef mesolight_Progress_h
#define mesolight_Progress_h

#include <functional>

namespace mesolight
{

/// Called with the fraction done in [0, 1]; returning false asks the work to stop.
using ProgressCallback = std::function<bool(double fraction)>;

/// Reports `fraction` to `progress` (if any); false when the work must stop.
inline bool ReportProgress(const ProgressCallback& progress, double fraction)
{
  return !progress || progress(fraction);
}

/// The callback for a part of the work that is [begin, end] of the whole: its fraction f is
/// reported as begin + (end - begin) f. Empty when `whole` is.
inline ProgressCallback SubProgress(const ProgressCallback& whole, double begin, double end)
{
  if (!whole)
  {
    return {};
  }
  return [whole, begin, end](double fraction) { return whole(begin + (end - begin) * fraction); };
}

/**
 * The callback a VTK algorithm hands to a core: fraction f becomes
 * UpdateProgress(begin + (end - begin) f) and the answer is !GetAbortExecute(). A template so
 * that this header needs no VTK type (any class with those two members fits).
 */
template <class Algorithm>
ProgressCallback AlgorithmProgress(Algorithm* algorithm, double begin = 0.0, double end = 1.0)
{
  return [algorithm, begin, end](double fraction)
  {
    algorithm->UpdateProgress(begin + (end - begin) * fraction);
    return !algorithm->GetAbortExecute();
  };
}

/**
 * Clears the abort flag a previous run left set; the first thing an abortable RequestData does.
 * VTK 9.1's executive clears it before each RequestData, the VTK of ParaView 5.11 does not: one
 * abort (the GUI's Abort, a script's SetAbortExecute(1)) stopped every later run of the filter,
 * even after its settings changed. (SetAbortExecute(0) and the template keep this header VTK-free.)
 */
template <class Algorithm>
void ClearAbort(Algorithm* algorithm)
{
  algorithm->SetAbortExecute(0);
}

} // namespace mesolight

#endif
