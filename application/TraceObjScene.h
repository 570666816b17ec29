// SPDX-License-Identifier: BSD-3-Clause
// `mesolight trace --scene FILE.obj`: the path tracer (vtkRayTracing/core/PathTracer.h) on any
// OBJ + MTL scene (Kd diffuse, Ks mirror, Ke one-sided emitters), seen from a walkthrough
// camera given exactly as to `vlf render` (LightFieldCamera.h), written as linear EXR: the
// independent per-pixel reference of the light field on a user's own scenes.
#ifndef mesolight_TraceObjScene_h
#define mesolight_TraceObjScene_h

#include <string>

namespace mesolight
{
class CommandLine;

/** True when the --scene value names a file rather than a built-in scene (ends in .obj). */
bool IsObjSceneName(const std::string& scene);

/** Declares the options only the OBJ path uses (--bounces). */
void AddTraceObjOptions(CommandLine& cl);

/** Checks every option and output, reads the scene, traces it, writes --out (sRGB PNG) and
 * --exr (linear). Returns the command's exit code (messages printed). */
int TraceObjScene(const CommandLine& cl, int width, int height, int threads);

} // namespace mesolight

#endif
