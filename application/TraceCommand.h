// SPDX-License-Identifier: BSD-3-Clause
// `mesolight trace` (the Embree ray tracer of Ahern 1999 on built-in scenes, and the path-traced
// Cornell box) and `mesolight bench trace` (rays per second, path samples per second).
#ifndef mesolight_TraceCommand_h
#define mesolight_TraceCommand_h

#include "RgbImage.h"

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace mesolight
{

/** mesolight trace [--scene spheres|ring|cornell] [options]; `args` excludes "trace". */
int RunTraceCommand(const std::vector<std::string>& args);

/** mesolight bench trace [options]; `args` excludes "bench trace". */
int RunTraceBenchmark(const std::vector<std::string>& args);

/**
 * The PNG pixels of a path-traced image (`trace --out`, built-in or OBJ scene): exposure 1,
 * clamped (non-finite values to 0), sRGB, 8 bits per channel.
 */
vtkSmartPointer<vtkImageData> ToDisplayBytes(const RgbImage& image);
/** Writes an image as PNG; false when it cannot be written. */
bool WritePng(vtkImageData* image, const std::string& fileName);

} // namespace mesolight

#endif
