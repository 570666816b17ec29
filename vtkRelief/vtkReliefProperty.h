// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefProperty
 * @brief   The settings of a relief surface: the height-field intersection method, its step
 *          counts, the depth scale, shadows, silhouettes, depth write, measurement outputs and
 *          light-set shading.
 *
 * Like vtkProperty for an actor or vtkVolumeProperty for a volume: vtkReliefMapper and
 * vtkCompositeReliefMapper each hold one (GetReliefProperty()), several mappers can share one
 * (SetReliefProperty()), and a mapper's modification time includes its property's.
 *
 * Methods (the relief thesis §4 and later work), all sharing one march skeleton:
 *  - Non-iterative: TextureMapping (no displacement), Bump (normals only), Parallax,
 *    ParallaxOffsetLimiting, ParallaxSlope.
 *  - Unsafe iterative: IterativeParallax, BinarySearch, Secant.
 *  - Safe iterative: LinearSearch (steep parallax, McGuire & McGuire 2005), ParallaxOcclusion
 *    (linear + one secant step, Tatarchuk 2006), Relief (linear + binary, Policarpo et al. 2005),
 *    Interval (linear + interval steps).
 *  - Empty-space skipping: RelaxedConeBinary and RelaxedConeInterval need a relaxed cone map,
 *    ConservativeCone a conservative one (vtkConeMapFilter output as the relief texture);
 *    MaximumMipmap traces exactly through a min-depth pyramid the mapper builds itself.
 *
 * Units: DepthScale is dimensionless: the world depth of depth = 1 divided by the world length
 * of one unit of u (the texture's width on the mesh). The same convention is used when baking
 * the normals; if the relief texture carries a different "MesolightDepthScale" field value, the
 * mapper rescales its normals so shading stays consistent with the marched geometry.
 *
 * The method names used on command lines ("relief", "pom", ...) are defined here once
 * (GetMethodName, GetMethodFromName).
 */

#ifndef vtkReliefProperty_h
#define vtkReliefProperty_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkClampedSetter.h"      // for mesolightSetClampMacro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for Messages

#include <string> // for GetMethodNameList

class vtkLightCollection;
class vtkReliefMessageForwarder;

class MESOLIGHTRELIEF_EXPORT vtkReliefProperty : public vtkObject
{
public:
  static vtkReliefProperty* New();
  vtkTypeMacro(vtkReliefProperty, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Height-field intersection methods (see the class description). */
  enum MethodType
  {
    TextureMapping = 0,
    Bump,
    Parallax,
    ParallaxOffsetLimiting,
    ParallaxSlope,
    IterativeParallax,
    BinarySearch,
    Secant,
    LinearSearch,
    ParallaxOcclusion,
    Relief,
    Interval,
    RelaxedConeBinary,
    RelaxedConeInterval,
    ConservativeCone,
    MaximumMipmap,
    NumberOfMethods
  };

  /** The cone map a relief texture carries (vtkConeMapFilter), or a method needs. */
  enum ConeMapKind
  {
    NoConeMap = 0,
    RelaxedConeMap = 1,
    ConservativeConeMap = 2
  };

  /** What the fragments show. */
  enum OutputType
  {
    ShadedOutput = 0, ///< the lit surface (default)
    HitUOutput = 1,   ///< hit u as 24-bit fixed point in RGB
    HitVOutput = 2,   ///< hit v, likewise
    /// white where the first light reaches the hit point, else black
    LightVisibilityOutput = 3,
    /// red where a NaN or Inf arose on the way to the colour, else green
    NonFiniteCheckOutput = 4,
    /// relief-texture samples the fragment took, as a 16-bit count in R (high) and G (low)
    /// bytes: the march's cost, independent of the machine (mesolight::DecodeSampleCount)
    SampleCountOutput = 5,
    NumberOfOutputs
  };

  ///@{
  /**
   * Height-field intersection method. Default: MaximumMipmap, the exact traversal (its hits
   * are the exact first intersection with the bilinear height field; docs/relief-methods.md,
   * "The default"). On curved geometry with SurfaceCurvature on it marches the curved layer
   * with Relief's search instead, to keep the silhouettes (vtkReliefShaderSource::
   * GetMarchMethod). Before: Relief 10+8, which missed by 1.6-44 texels on real maps at 85
   * degrees.
   */
  mesolightSetClampMacro(Method, int, TextureMapping, NumberOfMethods - 1);
  vtkGetMacro(Method, int);
  void SetMethodToTextureMapping() { this->SetMethod(TextureMapping); }
  void SetMethodToSteepParallax() { this->SetMethod(LinearSearch); }
  void SetMethodToParallaxOcclusion() { this->SetMethod(ParallaxOcclusion); }
  void SetMethodToRelief() { this->SetMethod(Relief); }
  void SetMethodToMaximumMipmap() { this->SetMethod(MaximumMipmap); }
  ///@}

  ///@{
  /**
   * Short method names used on the command line: "texture", "bump", "parallax",
   * "parallax-limit", "parallax-slope", "iterative-parallax", "binary", "secant", "linear" (also
   * "steep"), "pom", "relief", "interval", "relaxed-cone", "relaxed-cone-interval", "cone",
   * "max-mipmap". GetMethodName returns "unknown" outside the methods; GetMethodFromName -1 for
   * an unknown (or null) name; SetMethodByName reports an error listing the names and returns
   * false, leaving the method unchanged. GetMethodNameList: every name, comma-separated, as the
   * errors about an unknown name list them.
   */
  static const char* GetMethodName(int method);
  static int GetMethodFromName(const char* name);
  static std::string GetMethodNameList();
  bool SetMethodByName(const char* name);
  ///@}

  /** The cone map a method needs in the relief texture (ConeMapKind). */
  static int GetRequiredConeMap(int method);

  ///@{
  /**
   * Number of linear-search steps from the surface to depth 1 and of refinement steps (binary
   * search; default 8). Clamped to [1, 1024] and [0, 64]. For iterative parallax LinearSteps
   * counts iterations, for cone stepping cone steps, and for MaximumMipmap (the default method)
   * it is the iteration budget of the traversal: default 64, exact on real maps at 85 degrees
   * (docs/relief-methods.md). Choosing another method, give its steps too (10 was the default
   * for Relief).
   */
  mesolightSetClampMacro(LinearSteps, int, 1, 1024);
  vtkGetMacro(LinearSteps, int);
  mesolightSetClampMacro(RefinementSteps, int, 0, 64);
  vtkGetMacro(RefinementSteps, int);
  ///@}

  ///@{
  /**
   * View-angle adaptive step counts (Tatarchuk 2006): LinearSteps at grazing angles down to
   * MinimumSteps (clamped to [1, 1024], default 4) head-on. Default off.
   */
  vtkSetMacro(AdaptiveSteps, bool);
  vtkGetMacro(AdaptiveSteps, bool);
  vtkBooleanMacro(AdaptiveSteps, bool);
  mesolightSetClampMacro(MinimumSteps, int, 1, 1024);
  vtkGetMacro(MinimumSteps, int);
  ///@}

  ///@{
  /**
   * Filter where texels are smaller than pixels (the relief textures get mipmaps; with the
   * visible normal filter only the normal's moments, from mip level 2 up). The march
   * stays at the base level (an averaged height field fills the cracks a supersampled frame
   * keeps); the shading normal is filtered over the pixel footprint (NormalFilter) and where the
   * footprint exceeds a texel, linear and refinement steps stop at the footprint's size. Where
   * a texel covers a pixel or more the frame and the hits are those of level of detail off.
   * Default on; test ReliefLevelOfDetail, benchmark `mesolight bench relief-aliasing`.
   */
  vtkSetMacro(LevelOfDetail, bool);
  vtkGetMacro(LevelOfDetail, bool);
  vtkBooleanMacro(LevelOfDetail, bool);
  ///@}

  /** How level of detail filters the shading normal over a pixel footprint. */
  enum NormalFilterKind
  {
    /**
     * The footprint's mean normal, its length dimming the diffuse light and widening the
     * highlight (Toksvig 2005): in compact storage the plain mean of the same moments the
     * visible filters read, in float storage the mip-mapped normal. Blind to which facets a
     * grazing view sees; one view ray per pixel (FarViewRays is the visible filters').
     */
    MeanNormalFilter = 0,
    /**
     * The footprint's visible mean normal: second moments of the normal, mip-mapped (LEAN
     * mapping, Olano and Baker 2010), weighted by the area each facet shows the viewer
     * (compact storage, one more RGBA16F texture pair from mip level 2 up, 1.33 bytes per
     * texel; float storage uses the mean). Facets turned from the viewer count negatively (as
     * the ones hiding them count positively): the default before MaskedNormalFilter.
     */
    VisibleNormalFilter = 1,
    /**
     * The visible normal of the facets the viewer sees (the default): where the footprint's
     * level is computed per texel (levels 0 and 1), each facet counts by the area it turns to
     * the viewer, and facets turned away are left out (masked) instead of counting negatively as
     * in the moments, so a grazing view weighs the tops and faces turned to it and not the far
     * walls of the cracks; at the levels above, the moments' Gaussian model of the footprint's
     * normals leaves them out in the same way (docs/relief-methods.md, "The masked filter's
     * moments"). No more memory. (Smith's height-correlated masking on top of it, Heitz 2014,
     * stopped paying once far pixels took several view rays: docs/relief-methods.md, "Masked
     * facets".)
     */
    MaskedNormalFilter = 2
  };

  ///@{
  /** NormalFilterKind (default MaskedNormalFilter); read only with LevelOfDetail on. */
  mesolightSetClampMacro(NormalFilter, int, MeanNormalFilter, MaskedNormalFilter);
  vtkGetMacro(NormalFilter, int);
  ///@}

  ///@{
  /**
   * Normal filter names used on the command line: "mean", "visible", "masked".
   * GetNormalFilterName returns "unknown" outside the kinds; GetNormalFilterFromName -1 for an
   * unknown (or null) name.
   */
  static const char* GetNormalFilterName(int filter);
  static int GetNormalFilterFromName(const char* name);
  ///@}

  ///@{
  /**
   * The most view rays per far pixel (level of detail with the visible normal filters): where a
   * pixel's footprint is longer than two texels along its major axis, about one view ray per
   * minor axis' length along it, rounded up to an odd count and at most this many (an even
   * value counts as the odd one below it), enters at evenly spaced points of the pixel along its
   * major screen axis, each in a strip of its own across it (an N-rooks pattern), the middle one
   * through the pixel's centre (its hit is the depth written and its miss a silhouette); each is
   * traced and shaded as the pixel's one ray would be (its normals filtered over its strip) and
   * self-shadowed hard from its own hit (one ray's soft far shadow stands in for the rays it
   * does not trace), and their colours are averaged (a far grazing pixel covers many facets, of
   * which one ray meets one). 1: one ray per pixel. Near pixels always take one ray. Default 3
   * (3 rays at 45 and 80 degrees): far error on four real maps at 2 wall widths 0.35x relief
   * 10+8 without level of detail, against 0.45x with one ray, at 3.2x the relief samples per far
   * pixel (docs/relief-methods.md, "Several view rays per far pixel" and "Each far view ray's own
   * hard shadow"); test ReliefLevelOfDetail.AveragesViewRaysAcrossAFarFootprint. Under a light
   * set the rays take the lights' shadow marches in turn, so a pixel marches each light once
   * (interleaved sampling; test FarViewRaysTakeTheLightSetsShadowsInTurn).
   */
  mesolightSetClampMacro(FarViewRays, int, 1, 8);
  vtkGetMacro(FarViewRays, int);
  ///@}

  ///@{
  /**
   * Depth of depth = 1 relative to the world width of the texture (dimensionless, default 0.05).
   * 0 renders a flat (normal-mapped) surface. Clamped to [0, 10]; NaN is refused with an error.
   */
  void SetDepthScale(double depthScale);
  vtkGetMacro(DepthScale, double);
  ///@}

  ///@{
  /**
   * Use the depth scale the relief texture was baked with (its field array
   * "MesolightDepthScale") instead of DepthScale, so the bake is the one source of truth;
   * DepthScale still applies to textures that carry none. Default off (DepthScale wins).
   */
  vtkSetMacro(UseTextureDepthScale, bool);
  vtkGetMacro(UseTextureDepthScale, bool);
  vtkBooleanMacro(UseTextureDepthScale, bool);
  ///@}

  ///@{
  /** Hard self-shadowing toward each light by marching the height field. Default on. */
  vtkSetMacro(SelfShadowing, bool);
  vtkGetMacro(SelfShadowing, bool);
  vtkBooleanMacro(SelfShadowing, bool);
  ///@}

  ///@{
  /**
   * Discard fragments whose hit point leaves the [0,1]^2 texture domain (an object's
   * silhouette). Default on. Off, a relief that does not repeat is walled at the texture's
   * border, recessed into its surface: a view ray below the surface that reaches the border meets
   * a side wall there, and a shadow ray is blocked (docs/relief-against-path-tracer.md, "The
   * relief's edge").
   */
  vtkSetMacro(Silhouettes, bool);
  vtkGetMacro(Silhouettes, bool);
  vtkBooleanMacro(Silhouettes, bool);
  ///@}

  ///@{
  /**
   * Relief mapping on curved meshes (Oliveira & Policarpo 2005, "An efficient representation
   * for surface details"; Policarpo, Oliveira & Comba 2005): on a mesh that is not flat, each
   * vertex carries the quadric z = a u^2 + b v^2 of the surface in its tangent space (fitted on
   * the CPU from the mesh's curvature along the texture axes), the view ray's depth is lowered by
   * it as it marches, and with Silhouettes on a fragment whose ray leaves the relief layer without
   * a hit is discarded: the outline of a convex mesh is cut where it turns away from the viewer,
   * not only at the texture's edge. Default on. A flat mesh (a = b = 0 everywhere) draws with the
   * flat march whatever this says, at no cost. Used by the searches that step along the ray
   * (LinearSearch, ParallaxOcclusion, Relief, Interval and the cone methods); the other methods
   * ignore it.
   */
  vtkSetMacro(SurfaceCurvature, bool);
  vtkGetMacro(SurfaceCurvature, bool);
  vtkBooleanMacro(SurfaceCurvature, bool);
  ///@}

  ///@{
  /** Write gl_FragDepth from the hit point instead of the mesh surface. Default on. */
  vtkSetMacro(WriteDepth, bool);
  vtkGetMacro(WriteDepth, bool);
  vtkBooleanMacro(WriteDepth, bool);
  ///@}

  ///@{
  /**
   * A plane the written depth goes no deeper than (world coordinates: a point on it and its
   * normal toward the relief's front side; default none). The relief lies behind its surface by
   * up to the depth scale; mounted a few mm in front of a wall drawn by another actor, its deep
   * parts lie behind that wall, whose fragments then win the depth test and hide them. With the
   * plane set between the two (vtkLightFieldReliefSurface::GetDepthLimitPlane), a view ray's
   * depth is that of its hit or, where the hit is behind the plane, of the ray's crossing of the
   * plane: the relief replaces the wall it is mounted on, as the command line's relief replaces
   * the wall it hides (vtkLightFieldActor::AddHiddenSurface), and still orders by its true depth
   * against anything in front of the plane. Only with WriteDepth.
   */
  void SetDepthLimitPlane(const double origin[3], const double normal[3]);
  void RemoveDepthLimitPlane();
  bool GetHasDepthLimitPlane() const { return this->HasDepthLimitPlane; }
  vtkGetVector3Macro(DepthLimitOrigin, double);
  vtkGetVector3Macro(DepthLimitNormal, double);
  ///@}

  ///@{
  /**
   * How the relief is stored on the GPU (vtkReliefTextureCache). By default compactly, with
   * only what the method reads: 16-bit depth; no normals when they are the depth's own (as
   * vtkReliefTextureFilter bakes them, checked at upload: the shader shades the surface it
   * marches from the depth), else 8-bit octahedral normals; 8-bit cone ratios for cone methods,
   * an 8-bit min-depth pyramid from level 2 for MaximumMipmap, half-float normal moments from mip
   * level 2 with LevelOfDetail: 2 to 5.4 bytes per texel (3.7 for the default), the hits as
   * exact as with float textures. FloatTextures: the float RGBA texture and float pyramid
   * instead (16 to 37 bytes per texel); off by default, on only to measure what compact storage
   * costs (mesolight bench relief --texture-storage).
   */
  vtkSetMacro(FloatTextures, bool);
  vtkGetMacro(FloatTextures, bool);
  vtkBooleanMacro(FloatTextures, bool);
  ///@}

  ///@{
  /** Repeat the relief texture outside [0,1] (tiling) instead of clamping. Default off. */
  vtkSetMacro(RepeatTexture, bool);
  vtkGetMacro(RepeatTexture, bool);
  vtkBooleanMacro(RepeatTexture, bool);
  ///@}

  ///@{
  /**
   * What the fragments show (OutputType): the shaded surface, or measurement outputs that tests
   * and benchmarks compare with exact CPU references (see mesolight::DecodeHitCoordinate).
   */
  mesolightSetClampMacro(Output, int, ShadedOutput, NumberOfOutputs - 1);
  vtkGetMacro(Output, int);
  ///@}

  ///@{
  /**
   * Light-set shading: Exposure scales it (default 1) before Reinhard's x / (1 + x) when
   * ToneMapping is on (the default, as in ParaView). Why on: a light set carries the
   * environment's whole irradiance and the renderer's lights add to it, so at exposure 1 a
   * sky-lit surface shades above 1 and, clamped, about a quarter of it is white; tone mapped,
   * the first image is exposed. The defaults are mesolight::ReliefLightSetDisplay
   * (common/DisplayTransform.h). Off: the shading is clamped (for measurements in radiance).
   */
  mesolightSetClampMacro(Exposure, double, 0.0, 1e6);
  vtkGetMacro(Exposure, double);
  vtkSetMacro(ToneMapping, bool);
  vtkGetMacro(ToneMapping, bool);
  vtkBooleanMacro(ToneMapping, bool);
  ///@}

  ///@{
  /**
   * Radiance the surface emits (RGB, default 0), added to the light-set or probe shading before
   * Exposure: a relief on an emitter of a light field (a lamp, a window) shows the emitter's
   * light, as the field and its CPU reference do (vtkLightFieldReliefSurface's
   * GetSurfaceEmission). Not used without a light set or probes (VTK's own lights: the actor's
   * ambient term).
   */
  vtkSetVector3Macro(Emission, double);
  vtkGetVector3Macro(Emission, double);
  ///@}

  ///@{
  /**
   * Encode the light-set / probe shading with the sRGB curve after exposure and tone mapping
   * (default off: relief colours go to the framebuffer linear, as VTK's). On for a relief drawn
   * beside a light field walkthrough, whose radiance is sRGB-encoded (vtkLightFieldActor), so
   * both show the same radiance as the same pixel value.
   */
  vtkSetMacro(EncodeSRGB, bool);
  vtkGetMacro(EncodeSRGB, bool);
  vtkBooleanMacro(EncodeSRGB, bool);
  ///@}

  ///@{
  /**
   * VTK lights to shade instead of the renderer's (default null: the renderer's). A relief lit
   * by a light field in a view whose lights are for other data (ParaView's light kit) is lit by
   * the field's emitters only: its own lights (vtkReliefMapper::ConfigureEmitterLight). The
   * same limit and self-shadowing apply as to the renderer's lights.
   */
  void SetLights(vtkLightCollection* lights);
  vtkLightCollection* GetLights();
  ///@}

  ///@{
  /**
   * Skips for light sets, each measurable (mesolight bench ibl): lights whose luminance is below
   * LightSetThreshold times the strongest light's are skipped entirely (default 0: none);
   * with ShadowedLights = K > 0 only the K strongest lights facing a pixel march their shadows,
   * the rest are weighted by the visible fraction of those K (default 0: all march).
   */
  mesolightSetClampMacro(LightSetThreshold, double, 0.0, 1.0);
  vtkGetMacro(LightSetThreshold, double);
  mesolightSetClampMacro(ShadowedLights, int, 0, 1 << 16);
  vtkGetMacro(ShadowedLights, int);
  ///@}

  ///@{
  /**
   * Lights behind the shading normal contribute nothing and skip their shadow march (default
   * on). Off marches them anyway, only to measure what the culling saves.
   */
  vtkSetMacro(ShadowCulling, bool);
  vtkGetMacro(ShadowCulling, bool);
  vtkBooleanMacro(ShadowCulling, bool);
  ///@}

  ///@{
  /**
   * Errors and warnings of this property also reach the observers of this owner: a mapper
   * sets itself as the owner of the property it makes, so users watching the mapper hear
   * about refused settings. Not referenced (a weak pointer); without an owner, or without
   * observers on it, messages are displayed as usual.
   */
  void SetMessageOwner(vtkObject* owner);
  vtkObject* GetMessageOwner();
  ///@}

protected:
  vtkReliefProperty();
  ~vtkReliefProperty() override;

  int Method = MaximumMipmap;
  int LinearSteps = 64;
  int RefinementSteps = 8;
  double DepthScale = 0.05;
  bool UseTextureDepthScale = false;
  bool SelfShadowing = true;
  bool Silhouettes = true;
  bool SurfaceCurvature = true;
  bool WriteDepth = true;
  bool HasDepthLimitPlane = false;
  double DepthLimitOrigin[3] = { 0.0, 0.0, 0.0 };
  double DepthLimitNormal[3] = { 0.0, 0.0, 1.0 };
  bool RepeatTexture = false;
  bool FloatTextures = false;
  int Output = ShadedOutput;
  bool AdaptiveSteps = false;
  int MinimumSteps = 4;
  bool LevelOfDetail = true;
  int NormalFilter = MaskedNormalFilter;
  int FarViewRays = 3;
  double Exposure; // mesolight::ReliefLightSetDisplay, set in the constructor
  double Emission[3] = { 0.0, 0.0, 0.0 };
  bool ToneMapping; // idem
  bool EncodeSRGB = false;
  vtkSmartPointer<vtkLightCollection> Lights;
  double LightSetThreshold = 0.0;
  int ShadowedLights = 0;
  bool ShadowCulling = true;

  vtkSmartPointer<vtkReliefMessageForwarder> Messages; // made by SetMessageOwner

private:
  vtkReliefProperty(const vtkReliefProperty&) = delete;
  void operator=(const vtkReliefProperty&) = delete;
};

#endif
