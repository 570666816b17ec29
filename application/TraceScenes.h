// SPDX-License-Identifier: BSD-3-Clause
// Built-in scenes of `mesolight trace` (Ahern 1999's pictures): three textured spheres on a
// checker plane, and a bump- and roughness-mapped ring. Procedural textures, made in code.
#ifndef mesolight_TraceScenes_h
#define mesolight_TraceScenes_h

#include <vtkSmartPointer.h>

class vtkEmbreeRayTracer;
class vtkImageData;
class vtkRenderer;

namespace mesolight
{

// An unsigned-char RGB checker of squares x squares cells, size x size pixels.
vtkSmartPointer<vtkImageData> MakeCheckerImage(int size, int squares, double dark, double light);
// A globe-like map (oceans and continents from a few sines), width 2 x height.
vtkSmartPointer<vtkImageData> MakeGlobeImage(int height);
// A bump map (red, green = slopes along s, t mapped to [0, 1]) of interlaced bands: a knot-like
// relief for the ring.
vtkSmartPointer<vtkImageData> MakeKnotBumpImage(int width, int height, double strength);

// Fills the renderer with the scene and attaches its material maps to the tracer; sets the
// camera. False for an unknown name.
bool BuildSpheresScene(vtkRenderer* renderer, vtkEmbreeRayTracer* tracer);
bool BuildRingScene(vtkRenderer* renderer, vtkEmbreeRayTracer* tracer);

} // namespace mesolight

#endif
