// SPDX-License-Identifier: BSD-3-Clause
// WalkthroughTracer: the CPU side of the light field walkthrough (Wither 2005 §2.4.2.2), in plain
// C++ (GLM, no VTK types). It answers, per pixel of a view, what the four walkthrough modes
// need from the field:
//   - raytrace (§2.4.2.2.2): the first hit's radiance leaving toward the eye, looked up in the
//     field (three nearest directions with spherical weights, 8-neighbour cell interpolation);
//   - progressive while the camera moves (§2.4.2.2.3): mirror pixels read the field in the
//     reflected direction at low directional resolution (the nearest direction only, 8-neighbour
//     cells, one lookup per 2 x 2 pixel block): fast, blurry;
//   - progressive at rest and coherent (§2.4.2.2.3-4): mirror pixels trace the reflection
//     recursively to the first diffuse hit and read its total diffuse texture: sharp. Coherent
//     traces 4 x 4 pixel tiles as 16-ray packets (Embree), primary and reflected rays alike.
// Diffuse pixels of the progressive and coherent modes are the GPU's (TextureAtlas); this class
// fills a screen-space RGBA image over a pixel rectangle (alpha 1 where it has a value) that the
// GPU composites over mirror fragments.
//
// Everything is in the field's unit-sphere coordinates (LightField::Scene()). Pixel (i, j)
// covers [i, i+1) x [j, j+1), row 0 at the bottom (VTK and gl_FragCoord). The hit queries go
// through one EmbreeScene, which may hold a movable object (Wither 2005, "Interactive dynamic
// objects in a virtual light field") as an instanced geometry: SetObject gives its mesh (model
// coordinates), SetObjectPlacement its model -> unit sphere transform (only the instance moves,
// the static BVH stays), SetObjectRadiance the radiance leaving each of its points (gathered).
// Primary rays that hit it first give no screen value (its own actor draws it); reflected rays
// that hit it return its radiance, interpolated from its points: at every bounce of traced
// reflections, and at every bounce of the field-lookup qualities (Moving, Raytrace), whose field
// knows nothing of the object: there the mirror chain is followed by rays (only when a reflected
// ray can reach the object's bounding sphere or another mirror) and the field value is kept when
// the chain never meets the object. SetShadows gives the object's shadows (ObjectShadows): a
// diffuse surface seen in a mirror is darkened at the point the mirror ray lands on by the same
// ObjectShadows::Shade the raytrace mode applies to directly seen pixels (and the GPU's twin
// glsl/vtkLightFieldShadowFS.glsl to the progressive and coherent modes' diffuse pixels).
// SetReliefs gives the reliefs drawn on surfaces of the scene (the walkthrough's --relief), which
// the tracer keeps flat: a mirror ray that lands on one shows the relief's radiance along it
// (TracedReliefs, the CPU reference's exact height-field intersection and shading), darkened by
// the object's shadow at the point it landed on.
#ifndef mesolight_vlf_WalkthroughTracer_h
#define mesolight_vlf_WalkthroughTracer_h

#include "EmbreeScene.h"
#include "LightField.h"
#include "Lookup.h"
#include "ObjectMesh.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace mesolight
{
namespace vlf
{

// A perspective view in unit-sphere coordinates, as vtkCamera describes one (vertical view
// angle, aspect from the viewport).
struct ViewFrame
{
  glm::vec3 Eye{ 0.0f, 0.0f, 3.0f };
  glm::vec3 Forward{ 0.0f, 0.0f, -1.0f };
  glm::vec3 Right{ 1.0f, 0.0f, 0.0f };
  glm::vec3 Up{ 0.0f, 1.0f, 0.0f };
  float TanHalfHeight = 0.3f;
  int Width = 0;
  int Height = 0;

  // False for a degenerate camera (eye on the focal point, view up along the view direction,
  // angle outside (0, 180)) or an empty viewport.
  static bool Make(const glm::vec3& eye, const glm::vec3& focal, const glm::vec3& viewUp,
    float viewAngleDegrees, int width, int height, ViewFrame& frame);
  SceneRay Ray(float x, float y) const; // image point in pixels
  bool operator==(const ViewFrame& o) const;
  bool operator!=(const ViewFrame& o) const { return !(*this == o); }
};

struct PixelRect
{
  int X0 = 0, Y0 = 0, X1 = 0, Y1 = 0; // [X0, X1) x [Y0, Y1)
  int Width() const { return this->X1 - this->X0; }
  int Height() const { return this->Y1 - this->Y0; }
  bool Empty() const { return this->X1 <= this->X0 || this->Y1 <= this->Y0; }
  std::size_t Pixels() const
  {
    return this->Empty() ? 0 : static_cast<std::size_t>(this->Width()) * this->Height();
  }
};

// What a pixel's primary ray sees.
enum class PixelClass : std::uint8_t
{
  Background = 0, // missed the scene
  Diffuse = 1,    // front side of a surface without Ks
  Mirror = 2,     // front side of a surface with Ks > 0
  Emitter = 3,    // front side of an emitting surface
  BackFace = 4,   // a surface's back side (one-sided field: black), e.g. the eye inside a wall
  Object = 5      // the movable object (SetObject)
};

enum class SpecularQuality
{
  Moving,   // field lookup, nearest direction, bilinear cells (progressive, camera moving)
  Raytrace, // field lookup, spherical three-direction + 8-neighbour interpolation
  Traced    // reflection traced to the first diffuse hit, its total texture (at rest, coherent)
};

struct TraceOptions
{
  int MaximumDepth = 8; // mirror bounces followed before giving up (radiance 0 beyond)
  // Negative tests only: stop this many bounces short of the first diffuse hit (1: the last
  // segment is never traced, so a mirror shows only its own diffuse part).
  int BouncesShortForTesting = 0;
};

class ObjectShadows;

// Reliefs drawn on triangles of the field's scene, for the mirror rays that land on them:
// implemented where the reliefs are set up (application/LightFieldReliefs.cxx: the CPU
// reference's FieldRelief and ReliefRadiance). Called from several threads at once.
class TracedReliefs
{
public:
  virtual ~TracedReliefs() = default;
  // Whether scene triangle `triangle` carries a relief.
  virtual bool Covers(std::size_t triangle) const = 0;
  // The radiance the relief shows along a ray (unit sphere) that reached its triangle's plane;
  // false when the ray misses the relief (the flat surface's value is kept).
  virtual bool Radiance(std::size_t triangle, const glm::vec3& origin, const glm::vec3& direction,
    glm::vec3& radiance) const = 0;
};

class WalkthroughTracer
{
public:
  explicit WalkthroughTracer(const LightField& field);
  ~WalkthroughTracer();

  const LightField& Field() const { return this->LightFieldRef; }
  const EmbreeScene& Embree() const { return *this->Scene; }
  bool IsMirrorSurface(std::uint32_t surface) const { return this->Mirror[surface] != 0; }
  bool HasMirrors() const { return this->MirrorCount > 0; }

  ///@{
  // The movable object. Not thread-safe against shading running at the same time (callers stop
  // their workers first). SetObject throws std::invalid_argument for a mesh
  // ObjectMesh::Validate rejects and std::runtime_error when Embree fails; it clears the
  // radiance (black until SetObjectRadiance). The radiance has one value per point of the mesh
  // (other sizes: black).
  void SetObject(const ObjectMesh& model);
  void SetObjectPlacement(const glm::mat4& modelToUnit);
  void SetObjectRadiance(std::vector<glm::vec3> radiance);
  void ClearObject();
  bool HasObject() const { return this->ObjectSet; }
  const ObjectMesh& Object() const { return this->ObjectModel; }
  const glm::mat4& ObjectPlacement() const { return this->Placement; }
  // Radiance leaving the object at a hit on it (hit.ObjectTriangle set).
  glm::vec3 ObjectRadiance(const SceneHit& hit) const;
  ///@}

  ///@{
  // The object's shadows on the diffuse surfaces seen in mirrors (not owned; nullptr: none).
  // Not thread-safe against shading running at the same time, like SetObject.
  void SetShadows(const ObjectShadows* shadows) { this->ShadowsRef = shadows; }
  const ObjectShadows* Shadows() const { return this->ShadowsRef; }
  // The total diffuse radiance of surface s at p, darkened by the object's shadow when set.
  glm::vec3 ShadedDiffuse(std::uint32_t s, const glm::vec3& p) const;
  ///@}

  ///@{
  // Reliefs on the scene's surfaces, shown where mirror rays land on them (shared; nullptr:
  // none). Not thread-safe against shading running at the same time, like SetObject.
  void SetReliefs(std::shared_ptr<const TracedReliefs> reliefs)
  {
    this->ReliefsRef = std::move(reliefs);
  }
  const TracedReliefs* Reliefs() const { return this->ReliefsRef.get(); }
  ///@}

  // Class of a primary hit; surface is set for the front/back of a surface.
  PixelClass Classify(const SceneRay& ray, const SceneHit& hit, std::uint32_t& surface) const;

  // Radiance arriving along the ray (toward its origin) for each quality.
  glm::vec3 RaytraceRadiance(const SceneRay& ray) const;
  glm::vec3 TracedRadiance(const SceneRay& ray, const TraceOptions& options) const;
  // The same for up to 16 rays traced as packets (coherent mode).
  void TracedRadiance16(
    const SceneRay* rays, int count, const TraceOptions& options, glm::vec3* out) const;
  // Mirror pixel at p on surface s seen along ray direction d.
  glm::vec3 MirrorRadiance(std::uint32_t s, const glm::vec3& p, const glm::vec3& d,
    SpecularQuality quality, const TraceOptions& options) const;

  // Screen-space pass: rows [rowBegin, rowEnd) of rect (absolute rows). out holds rect.Pixels()
  // RGBA floats, row-major from rect's lower-left corner. With allSurfaces (raytrace mode)
  // every front hit gets its field radiance; else only mirror pixels, with `quality`. Pixels
  // without a value get alpha 0. Returns the pixels given a value.
  std::size_t ShadeRows(const ViewFrame& view, const PixelRect& rect, bool allSurfaces,
    SpecularQuality quality, const TraceOptions& options, int rowBegin, int rowEnd,
    float* out) const;
  // The same over 4 x 4 pixel tiles [tileBegin, tileEnd) of rect, primary rays as 16-ray
  // packets; Traced reflections are packets too (the coherent mode, Wither 2005 §2.4.2.2.4).
  std::size_t ShadeTiles(const ViewFrame& view, const PixelRect& rect, bool allSurfaces,
    SpecularQuality quality, const TraceOptions& options, std::size_t tileBegin,
    std::size_t tileEnd, float* out) const;
  static std::size_t TileCount(const PixelRect& rect);
  // Gives alpha-0 pixels next to valued ones their neighbour's value: rasterised mirror edge
  // fragments whose pixel-centre ray just missed the mirror still find a reflection.
  static void DilateEdges(const PixelRect& rect, float* rgba);

  // Screen rectangle holding every mirror triangle (clipped to the view; the whole view when a
  // mirror vertex lies behind the eye). Empty without mirrors in view.
  PixelRect MirrorRect(const ViewFrame& view) const;

  // Per-pixel class of the whole view (tests, masks), row-major, row 0 at the bottom.
  std::vector<PixelClass> ClassifyView(const ViewFrame& view) const;

private:
  const LightField& LightFieldRef;
  std::unique_ptr<EmbreeScene> Scene;
  Lookup FieldLookup;
  std::vector<std::uint8_t> Mirror; // per surface
  std::size_t MirrorCount = 0;
  float Epsilon = 1e-4f; // ray offset off a mirror (unit sphere)
  bool IgnoreDeeperObjectForTesting = false;

public:
  // Negative tests only: the field-lookup qualities look for the object at the first mirror
  // bounce only (what they did before the mirror chain was followed).
  void SetFirstBounceObjectOnlyForTesting(bool on) { this->IgnoreDeeperObjectForTesting = on; }

private:
  bool ObjectSet = false;
  ObjectMesh ObjectModel;
  std::vector<glm::vec3> ObjectRadianceValues;
  glm::mat4 Placement{ 1.0f };
  glm::vec3 ObjectCentre{ 0.0f }; // bounding sphere in the unit sphere (cheap ray rejection)
  float ObjectRadius = 0.0f;
  const ObjectShadows* ShadowsRef = nullptr;
  std::shared_ptr<const TracedReliefs> ReliefsRef;
  // What a reflected ray shows where it lands on the diffuse or emitting surface s at p: the
  // relief's radiance where one is drawn (and hit), else ShadedDiffuse.
  glm::vec3 LandingRadiance(
    const SceneRay& ray, const SceneHit& hit, std::uint32_t s, const glm::vec3& p) const;
  std::vector<std::uint8_t> MirrorFacesMirror; // per mirror surface: another mirror in front
  // True when the ray may reach the object (its bounding sphere).
  bool MayHitObject(const SceneRay& ray) const;
  // What the field-lookup qualities must correct at mirror point p of surface s seen along d:
  // the mirror chain from p meets the object (Object: the mirror's radiance is Own + Throughput
  // x Value), on a relief (Relief: the same, Value the relief's radiance) or ends on a diffuse
  // point the object shadows (Shadow: the field's mirror value loses Throughput x Value); Field:
  // keep the field's value.
  struct MirrorChain
  {
    enum Kind
    {
      Field,
      Object,
      Relief,
      Shadow
    } End = Field;
    glm::vec3 Own{ 0.0f }, Throughput{ 1.0f }, Value{ 0.0f };
    glm::vec3 Apply(const glm::vec3& field) const;
  };
  MirrorChain FollowMirrorChain(
    std::uint32_t s, glm::vec3 p, glm::vec3 d, const TraceOptions& options) const;
};

} // namespace vlf
} // namespace mesolight

#endif
