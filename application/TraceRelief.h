// SPDX-License-Identifier: BSD-3-Clause
// `mesolight trace --relief SURFACE=DEPTH_IMAGE`: the relief of a named planar surface as real
// geometry (DisplaceSurface, vtkScene/core/SurfaceRelief.h), so that the path tracer renders the
// exact reference of a relief surface lit by the scene (the light field's `vlf render --relief`
// is measured against it), and the relief's pixel mask of the same camera.
#ifndef mesolight_TraceRelief_h
#define mesolight_TraceRelief_h

#include "PinholeCamera.h"
#include "RgbImage.h"

#include <string>

namespace mesolight
{
class CommandLine;
class EmbreeScene;
struct TriangleScene;

/** Declares --relief, --relief-depth-scale, --relief-height, --relief-normalize,
 * --relief-subdivision and --relief-mask. */
void AddTraceReliefOptions(CommandLine& cl);

/** The depth map of an image file exactly as the relief mapper sees it (vtkOIIOImageReader +
 * vtkReliefTextureFilter: luminance, scaled to [0, 1], or its range stretched to [0, 1] with
 * `normalize` (NormalizeRange: elevations), inverted for a height image; row 0 at the bottom).
 * False with a message in error. */
bool ReadDepthMapImage(const std::string& file, bool isHeight, bool normalize,
  std::vector<float>& depth, int& width, int& height, std::string& error);

/**
 * Applies --relief to the scene (its triangles replaced by the displaced mesh; the surface's name
 * returned in surface, empty without --relief). False with a message in error (bad option,
 * unreadable image, unknown or non-planar surface). Prints what it built on stdout.
 */
bool ApplyTraceRelief(
  const CommandLine& cl, TriangleScene& scene, std::string& surface, std::string& error);

/**
 * The share of each pixel (4 x 4 stratified rays) whose first hit is a triangle of the named
 * surface, in all three channels: 1 for a pixel wholly on the relief.
 */
RgbImage SurfaceMask(const TriangleScene& scene, const EmbreeScene& embree,
  const std::string& surface, const PinholeCamera& camera, int width, int height);

} // namespace mesolight

#endif
