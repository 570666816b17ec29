// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkEmbreeRayTracer
 * @brief Ray traces the visible actors of a vtkRenderer on the CPU with Embree (Ahern 1999).
 *
 * An image source (no inputs): set a renderer, update, and the output is a vtkImageData of
 * the renderer's view (unsigned char RGB point scalars "RGB", plus the linear colours as float
 * "Radiance"), the renderer's own camera, lights and background. What it takes from the scene:
 *
 * - Actors (visible, with a mapper whose input is vtkPolyData): triangulated by
 *   vtkTriangleFilter, placed by the actor's matrix; point normals give smooth shading, point
 *   texture coordinates feed the texture maps. Scalar colouring, lines, points and composite
 *   data are not traced (a warning says so).
 * - Analytic spheres: an actor whose mapper's input algorithm is a full vtkSphereSource
 *   (theta 0-360, phi 0-180) placed by a similarity transform is traced as an exact sphere
 *   (AnalyticSpheres, on by default); its texture axis is the actor's z axis and its meridian
 *   the actor's x axis (the sphere source's poles lie on z).
 * - vtkProperty: ambient, diffuse and specular coefficients times their colours, specular
 *   power; NormalScale scales bump maps. Opacity is ignored. The specular colour is also the
 *   mirror reflectivity (Ahern 1999 §1), so shiny actors reflect; Reflections turns that off.
 * - Material maps: the actor's vtkTexture is the diffuse map; SetMaterialMap adds a map per
 *   channel (diffuse, specular, ambient, shininess, bump, roughness) for an actor. A map
 *   multiplies the constant colour; shininess and roughness read the red channel (roughness
 *   comes only from a roughness map, as in Ahern); bump maps tilt the normal by
 *   (2 red - 1, 2 green - 1) x NormalScale along the texture's tangent and bitangent.
 * - Lights: every switched-on vtkLight (headlights, camera lights, scene lights; directional,
 *   positional, spot with cone angle, exponent and attenuation), colour = diffuse colour x
 *   intensity, all casting shadows when Shadows is on. No lights and automatic light
 *   creation on: one white headlight, as VTK would add.
 *
 * Progressive refinement fires RefinementEvent after every level with GetPartialImage()
 * holding the image so far (on the thread that called Update), so an observer can show it.
 * The traced scene is read at every execution; call Modified() after changing geometry
 * (changes of actors, properties, lights and the camera are noticed).
 */
#ifndef vtkEmbreeRayTracer_h
#define vtkEmbreeRayTracer_h

#include "MesolightRayTracingModule.h" // for export macro
#include "vtkCommand.h"                // for vtkCommand::UserEvent
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // for members

#include <memory> // for std::unique_ptr

class vtkActor;
class vtkImageData;
class vtkRenderer;

class MESOLIGHTRAYTRACING_EXPORT vtkEmbreeRayTracer : public vtkImageAlgorithm
{
public:
  static vtkEmbreeRayTracer* New();
  vtkTypeMacro(vtkEmbreeRayTracer, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum MaterialChannel
  {
    DIFFUSE_MAP = 0,
    SPECULAR_MAP,
    AMBIENT_MAP,
    SHININESS_MAP,
    BUMP_MAP,
    ROUGHNESS_MAP,
    NUMBER_OF_MATERIAL_CHANNELS
  };
  enum
  {
    RefinementEvent = vtkCommand::UserEvent + 604
  };

  ///@{
  /** The renderer whose actors, lights, camera and background are traced. */
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer();
  ///@}

  /** A texture map (RGB image, unsigned char 0-255 or float) for one channel of an actor;
   * nullptr removes it. */
  void SetMaterialMap(vtkActor* actor, int channel, vtkImageData* image);
  void RemoveAllMaterialMaps();

  ///@{
  /** Image size in pixels; 0 takes the renderer's size. */
  vtkSetClampMacro(Width, int, 0, 16384);
  vtkGetMacro(Width, int);
  vtkSetClampMacro(Height, int, 0, 16384);
  vtkGetMacro(Height, int);
  ///@}

  ///@{
  /** Reflection recursion limit (default 5). */
  vtkSetClampMacro(MaxDepth, int, 0, 64);
  vtkGetMacro(MaxDepth, int);
  ///@}

  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);
  vtkBooleanMacro(Shadows, bool);
  vtkSetMacro(Reflections, bool);
  vtkGetMacro(Reflections, bool);
  vtkBooleanMacro(Reflections, bool);
  vtkSetMacro(AnalyticSpheres, bool);
  vtkGetMacro(AnalyticSpheres, bool);
  vtkBooleanMacro(AnalyticSpheres, bool);

  ///@{
  /** Distributed rays per rough reflection at a primary hit (Ahern 1999 used 40; default 16). */
  vtkSetClampMacro(GlossySamples, int, 1, 1024);
  vtkGetMacro(GlossySamples, int);
  ///@}

  ///@{
  /** Bilinear (default) or nearest texture lookups. */
  vtkSetMacro(BilinearTextures, bool);
  vtkGetMacro(BilinearTextures, bool);
  vtkBooleanMacro(BilinearTextures, bool);
  ///@}

  ///@{
  /** Adaptive supersampling: 3 x 3 rays in pixels differing from a neighbour by more than
   * AdaptiveThreshold (largest RGB channel difference, colours in [0, 1]). */
  vtkSetMacro(AdaptiveSupersampling, bool);
  vtkGetMacro(AdaptiveSupersampling, bool);
  vtkBooleanMacro(AdaptiveSupersampling, bool);
  vtkSetClampMacro(AdaptiveThreshold, double, 0.0, 10.0);
  vtkGetMacro(AdaptiveThreshold, double);
  ///@}

  ///@{
  /** Progressive refinement: 1 ray, then 2 x 2 blocks, 4 x 4, ... down to single pixels. */
  vtkSetMacro(Progressive, bool);
  vtkGetMacro(Progressive, bool);
  vtkBooleanMacro(Progressive, bool);
  ///@}

  ///@{
  /** Threads: 1 traces on the calling thread only, any other value on all of vtkSMPTools'
   * threads (vtkSMPTools::Initialize sets how many). Seed: the random-number stream of the
   * distributed rays (the same value gives the same image). */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  vtkSetMacro(Seed, vtkTypeUInt64);
  vtkGetMacro(Seed, vtkTypeUInt64);
  ///@}

  /** The image so far during progressive refinement (valid in RefinementEvent observers). */
  vtkImageData* GetPartialImage();

  ///@{
  /** Rays of the last execution. */
  vtkGetMacro(PrimaryRays, vtkTypeUInt64);
  vtkGetMacro(ShadowRays, vtkTypeUInt64);
  vtkGetMacro(SecondaryRays, vtkTypeUInt64);
  vtkGetMacro(SupersampledPixels, vtkTypeUInt64);
  vtkGetMacro(AnalyticSphereCount, int);
  vtkGetMacro(TriangleCount, vtkIdType);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkEmbreeRayTracer();
  ~vtkEmbreeRayTracer() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Width = 0;
  int Height = 0;
  int MaxDepth = 5;
  bool Shadows = true;
  bool Reflections = true;
  bool AnalyticSpheres = true;
  int GlossySamples = 16;
  bool BilinearTextures = true;
  bool AdaptiveSupersampling = false;
  double AdaptiveThreshold = 0.1;
  bool Progressive = false;
  int NumberOfThreads = 0;
  vtkTypeUInt64 Seed = 0;
  vtkTypeUInt64 PrimaryRays = 0;
  vtkTypeUInt64 ShadowRays = 0;
  vtkTypeUInt64 SecondaryRays = 0;
  vtkTypeUInt64 SupersampledPixels = 0;
  int AnalyticSphereCount = 0;
  vtkIdType TriangleCount = 0;

private:
  vtkEmbreeRayTracer(const vtkEmbreeRayTracer&) = delete;
  void operator=(const vtkEmbreeRayTracer&) = delete;

  bool ImageSize(int& width, int& height);
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
