// SPDX-License-Identifier: BSD-3-Clause
// ReliefShading: a relief (height field) on a planar surface, shaded per pixel under lighting
// given as data that says nothing of where it came from: spherical-harmonics radiance (SH9,
// Ramamoorthi and Hanrahan, "An efficient representation for irradiance environment maps") on a
// grid of probes over the surface's texture, for the smooth (indirect) light, and emitter samples
// (small area pieces) for the direct light, with the relief's self-shadowing toward each. Plain
// C++17 + GLM on the exact height-field intersector (HeightFieldTracer.h); the CPU evaluation the
// light-field tool renders relief surfaces with (`mesolight vlf render --relief`, docs/vlf.md).
//
// The relief's geometry is relief mapping's (Policarpo, Oliveira and Comba, "Real-time relief
// mapping on arbitrary polygonal surfaces"): the surface point at texture (u, v) and depth d is
//   P(u, v, d) = Origin + u AxisU + v AxisV - d W Normal,   W = DepthScale |AxisU|
// (vtkReliefProperty's DepthScale: world depth of d = 1 over the world length of one unit of u).
// The shading normal is the normal of that displaced surface, dP/du x dP/dv: the relief's
// PERTURBED normal, at which both the SH irradiance and the emitters' cosines are evaluated. A
// flat-normal variant (the macro surface's normal) exists for the negative tests.
#ifndef mesolight_ReliefShading_h
#define mesolight_ReliefShading_h

#include "EnvironmentMaps.h" // SH9
#include "HeightFieldTracer.h"
#include "MesolightReliefCoreModule.h" // for the export macro
#include "Progress.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace mesolight
{

/** The affine texture map of a planar surface and its relief depth (see above). */
struct MESOLIGHTRELIEFCORE_EXPORT ReliefFrame
{
  glm::dvec3 Origin{ 0.0 };
  glm::dvec3 AxisU{ 1.0, 0.0, 0.0 };
  glm::dvec3 AxisV{ 0.0, 1.0, 0.0 };
  glm::dvec3 Normal{ 0.0, 0.0, 1.0 }; // unit, the front side
  double DepthScale = 0.05;

  double WorldDepth() const; // W
  glm::dvec3 Point(double u, double v, double d) const;
  /** Texture-space (du, dv, dd) of a world vector. */
  glm::dvec3 ToTexture(const glm::dvec3& world) const;
};

/** A small piece of an emitter: position, unit normal (its front), radiance times area. */
struct ReliefEmitterSample
{
  glm::dvec3 Position{ 0.0 };
  glm::dvec3 Normal{ 0.0, 0.0, -1.0 };
  glm::dvec3 RadianceArea{ 0.0 };
};

/**
 * The geometric factor of emitter sample e's irradiance at a point of unit normal `normal`,
 * cos cos_e / r^2 (times RadianceArea, the irradiance the sample delivers unshadowed), with the
 * unit direction l towards the sample and the squared distance r2. 0 unless the point faces the
 * sample and the sample's front faces the point (both cosines positive), or where the sample is
 * at the point (l, r2 then unset).
 */
MESOLIGHTRELIEFCORE_EXPORT double EmitterSampleGeometry(const ReliefEmitterSample& e,
  const glm::dvec3& point, const glm::dvec3& normal, glm::dvec3& l, double& r2);

/** How the light the relief reflects onto itself is modelled (see ReliefLighting::Albedo). */
enum class ReliefInterReflection
{
  None,       // an occluded direction brings nothing (the relief's surface as black)
  OneBounce,  // it brings albedo E / pi, E the flat wall's irradiance at (u, v)
  MultiBounce // the same, the seen relief itself occluded and inter-reflecting (geometric series)
};

struct ReliefLighting
{
  // SH9 radiance probes on a ProbesU x ProbesV grid over the texture square [0, 1]^2 (probe (a, b)
  // at ((a + 1/2) / ProbesU, (b + 1/2) / ProbesV), row-major, b slowest); bilinear, clamped.
  int ProbesU = 1;
  int ProbesV = 1;
  std::vector<SH9> Probes;
  std::vector<ReliefEmitterSample> Emitters;
  // The relief's own occlusion of the indirect light: the SH irradiance is scaled by the visible
  // share of the SH radiance over this many fixed cosine-distributed directions around the
  // normal, each marched through the height field (a valley sees less of the room than a crest).
  // 0 leaves the indirect light unoccluded (the SH irradiance alone).
  int OcclusionDirections = 32;
  // The relief's own inter-reflection: an occluded direction sees the relief itself, a diffuse
  // surface of this albedo, not black. With OneBounce its radiance is Albedo E / pi, E the flat
  // wall's irradiance at (u, v) (the probes' SH irradiance at the macro normal plus the emitters'
  // unshadowed by the relief); with MultiBounce the seen relief is taken to be occluded like the
  // shaded point (visible share V, over the cosine-distributed directions) and to inter-reflect
  // in turn: its irradiance is Vs E / (1 - Albedo (1 - Vs)), the geometric series of the
  // ambient-occlusion multi-bounce (Stewart and Langer, "Towards accurate recovery of shape from
  // shading under diffuse lighting"; fitted by Jimenez et al., "Practical realtime strategies for
  // accurate indirect occlusion"), Vs the visible share of the relief those directions meet
  // (ReliefSeenShare: the series taken one bounce later, where a slot's bottom sees walls more
  // enclosed than itself). Either adds (1 - V) Albedo E_seen to the indirect irradiance.
  // Needs OcclusionDirections > 0; a zero Albedo (the default here) means none.
  glm::dvec3 Albedo{ 0.0 };
  ReliefInterReflection InterReflection = ReliefInterReflection::MultiBounce;
  // Optional: whether the segment from a point on the macro surface to an emitter sample is
  // free of the rest of the scene (true when not given).
  std::function<bool(const glm::dvec3& from, const glm::dvec3& to)> SceneVisible;
};

enum class ReliefNormal
{
  Perturbed, // the displaced surface's normal: the method
  Flat       // the macro surface's normal (negative tests: the relief then shades like a wall)
};

struct ReliefShade
{
  glm::dvec3 Texture{ 0.0 };    // (u, v, d) of the hit
  glm::dvec3 Point{ 0.0 };      // world
  glm::dvec3 Normal{ 0.0 };     // the shading normal (perturbed or flat)
  glm::dvec3 Indirect{ 0.0 };   // irradiance from the SH probes at Normal, clamped at 0, occluded,
                                // plus the inter-reflected light
  double IndirectVisible = 1.0; // the visible share applied to it (radiance-weighted)
  glm::dvec3 InterReflected{ 0.0 }; // the relief's own reflected light, included in Indirect
  glm::dvec3 Direct{ 0.0 };         // irradiance from the emitter samples, relief-shadowed
};

/** The perturbed unit normal of the displaced surface at (u, v) (front side). */
MESOLIGHTRELIEFCORE_EXPORT glm::dvec3 ReliefNormalAt(
  const HeightField& hf, const ReliefFrame& frame, double u, double v);

/**
 * The unit world normal of a walled relief's side wall (RayHit::wall, its normal in (u, v)): in
 * the wall's plane through the macro normal and the border, pointing back into the relief.
 */
MESOLIGHTRELIEFCORE_EXPORT glm::dvec3 ReliefWallNormal(
  const ReliefFrame& frame, const glm::dvec2& wall);

/** The SH radiance of the probes at (u, v) arriving from unit direction w, clamped at 0. */
MESOLIGHTRELIEFCORE_EXPORT glm::dvec3 ProbeRadiance(
  const ReliefLighting& lighting, double u, double v, const glm::dvec3& w);

/** The SH irradiance of the probes at (u, v) for unit normal n, clamped at 0. */
MESOLIGHTRELIEFCORE_EXPORT glm::dvec3 ProbeIrradiance(
  const ReliefLighting& lighting, double u, double v, const glm::dvec3& n);

/**
 * The relief seen along the world ray origin + t dir: its first hit (exact, IntersectFirst) and
 * the irradiance there. nullopt when the ray does not reach the front of the macro plane.
 */
MESOLIGHTRELIEFCORE_EXPORT std::optional<ReliefShade> ShadeReliefRay(const HeightField& hf,
  const ReliefFrame& frame, const ReliefLighting& lighting, const glm::dvec3& origin,
  const glm::dvec3& dir, ReliefNormal normal = ReliefNormal::Perturbed);

/**
 * The cosine-weighted share of the hemisphere around the unit world normal n at the relief point
 * hit = (u, v, d) whose directions leave the relief: the fixed cosine-distributed directions of
 * ShadeReliefRay's occlusion (`count` of them), a direction below the macro plane or blocked by
 * the height field counting as occluded. The V of the inter-reflection (ReliefLighting::Albedo).
 */
MESOLIGHTRELIEFCORE_EXPORT double ReliefVisibleShare(const HeightField& hf,
  const ReliefFrame& frame, const glm::dvec3& hit, const glm::dvec3& n, int count,
  double* abovePlane = nullptr); // abovePlane: the share of the directions above the macro plane

/**
 * The side walls' visible shares (ReliefWallVisibleShareMap's pairs) for the seen shares: a point
 * met on a walled relief's side wall reads its share from them as the relief mapper reads the
 * wall's map (mlReliefShare: bilinear along the wall between cell centres and down it between
 * levels, clamped, at its depth over the wall's foot there) instead of marching its directions.
 * Values: 2 per cell of the walls' grid (`width` cells along each wall, the visible-share map's
 * width, and 4 x Levels rows). Without them (Values null) a wall point is marched; values of
 * another size are refused by ReliefSeenShareMap and ReliefWallShareMap (std::invalid_argument)
 * and not read by ReliefSeenShare (the point marched).
 */
struct ReliefWallShares
{
  const std::vector<float>* Values = nullptr;
  int Levels = 0;
};

/**
 * The mean visible share (ReliefVisibleShare, around its own normal: the side wall's on a walled
 * relief's wall) of the relief points that the directions of ReliefVisibleShare at hit = (u, v, d)
 * around n meet, over the directions that do not leave the relief (IntersectFirst); 1 when all
 * leave it. The Vs of the multi-bounce inter-reflection (ReliefLighting::InterReflection). With
 * `shareMap` (ReliefVisibleShareMap's pairs over a mapWidth x mapHeight grid) a point of the
 * height field reads its share from the map (bilinear between cell centres, clamped), one met on
 * a side wall from `wallShares` where given (else it is marched): what the relief mapper's
 * precomputed map holds.
 */
MESOLIGHTRELIEFCORE_EXPORT double ReliefSeenShare(const HeightField& hf, const ReliefFrame& frame,
  const glm::dvec3& hit, const glm::dvec3& n, int count,
  const std::vector<float>* shareMap = nullptr, int mapWidth = 0, int mapHeight = 0,
  ReliefWallShares wallShares = {});

/**
 * The light the relief reflects onto itself at a point of visible share V (ReliefLighting's
 * InterReflection): (1 - V) Albedo E_seen, E_seen = flatIrradiance (one bounce) or
 * Vs flatIrradiance / (1 - Albedo (1 - Vs)) (multi-bounce), flatIrradiance the flat wall's
 * irradiance there and Vs the visible share of the relief the occluded directions meet
 * (ReliefSeenShare). The one formula of both relief renderers: ShadeReliefRay and the relief
 * mapper's probe shading (vtkReliefIrradianceProbesFS.glsl, mlProbeIndirect) use it.
 */
MESOLIGHTRELIEFCORE_EXPORT glm::dvec3 ReliefInterReflected(ReliefInterReflection model,
  double visibleShare, double seenShare, const glm::dvec3& albedo,
  const glm::dvec3& flatIrradiance);

/** The same with the seen relief taken to be occluded like the shaded point (Vs = V). */
MESOLIGHTRELIEFCORE_EXPORT glm::dvec3 ReliefInterReflected(ReliefInterReflection model,
  double visibleShare, const glm::dvec3& albedo, const glm::dvec3& flatIrradiance);

/**
 * The rows of a grid map one of several processes computes (MPI ranks splitting a map): rows j
 * with j % Count == Index, interleaved so that costlier regions of the relief spread over every
 * process. The others are left 0, so that one sum over the processes gives the whole map, equal
 * to the one-process map bit for bit (a value plus zeros is that value). The default: every row.
 */
struct GridRows
{
  int Index = 0;
  int Count = 1;
};

/**
 * What ReliefVisibleShareMap's march found along each of its cells' `count` directions (cell
 * after cell, row-major; a direction's entries at cell * count + k): whether it leaves the
 * relief and, if not, the point it meets, which ReliefSeenShareMap reads the share of. The march
 * that decides whether a direction leaves (Visible) stops at that point, so noting it costs
 * nothing, where the seen shares marched each occluded direction a second time (IntersectFirst;
 * the two differ only where a ray touches the surface before passing under it). Directions
 * below the macro plane are not marched for the share (they count as occluded), so their point
 * is marched here. 9 bytes per cell and direction (19 MB for 256 x 256 cells of 32 directions).
 */
struct ReliefDirectionHits
{
  enum Kind : std::uint8_t
  {
    Leaves,  // leaves the relief
    Surface, // meets the height field at (u, v) = Where
    WallU0,  // meets the side wall at u = 0 (Walled edges) at (v, depth) = Where
    WallU1,  // ... at u = 1, (v, depth)
    WallV0,  // ... at v = 0, (u, depth)
    WallV1,  // ... at v = 1, (u, depth)
    Lost     // stays in the relief but met nothing numerically: counts as dark
  };

  std::vector<std::uint8_t> Kinds; // one Kind per cell and direction; rows not computed Leaves
  std::vector<float> Where;        // two per cell and direction
};

/**
 * ReliefVisibleShare over a width x height grid of the texture square (cell (i, j) at
 * ((i + 1/2) / width, (j + 1/2) / height), row-major, j slowest), at the height field's surface
 * and perturbed normal there: what the relief mapper looks up per pixel instead of marching
 * `count` directions (vtkIrradianceProbesTexture). Two values per cell: V, and V over the share
 * of the directions above the macro plane (at most 1), the visible share of the light the
 * probes' SH irradiance holds (a probe in front of the wall sees nothing from behind it, so the
 * directions below the plane are dark in it already; ShadeReliefRay's radiance weighting
 * leaves them out for the same reason). Parallel; reports progress (over the rows computed), and
 * a stop throws std::runtime_error("aborted"). With `rows` of several processes only its rows
 * are computed, the others 0 (GridRows). With `hits`, what each of the cells' directions met
 * (ReliefDirectionHits): for ReliefSeenShareMap, which would otherwise march them again.
 */
MESOLIGHTRELIEFCORE_EXPORT std::vector<float> ReliefVisibleShareMap(const HeightField& hf,
  const ReliefFrame& frame, int width, int height, int count, const ProgressCallback& progress = {},
  GridRows rows = {}, ReliefDirectionHits* hits = nullptr);

/**
 * ReliefSeenShare over the grid of `share` (ReliefVisibleShareMap's output for the same width,
 * height and count), read from that map: one value per cell, row-major, j slowest. The relief
 * mapper's third channel of the map (vtkIrradianceProbesTexture). Parallel; progress, stop and
 * `rows` as ReliefVisibleShareMap (`share` must be whole: a cell reads the cells its occluded
 * directions meet, in any row). With `hits` (ReliefVisibleShareMap's, for the same grid, count
 * and rows) the directions are not marched again: their points are read from it. With
 * `wallShares` (ReliefWallVisibleShareMap's, whole, for this width) the directions that meet a
 * side wall read the wall's share instead of marching its directions, which was most of the
 * pass's work on a walled relief (`mesolight bench relief-field-cost` times both).
 */
MESOLIGHTRELIEFCORE_EXPORT std::vector<float> ReliefSeenShareMap(const HeightField& hf,
  const ReliefFrame& frame, const std::vector<float>& share, int width, int height, int count,
  const ProgressCallback& progress = {}, GridRows rows = {},
  const ReliefDirectionHits* hits = nullptr, ReliefWallShares wallShares = {});

/**
 * The relief's own shadow of area lights over the grid of ReliefVisibleShareMap: per cell (at the
 * height field's surface and perturbed normal there) and light group g < groups, the share of the
 * unshadowed direct irradiance of the emitter samples with group[s] == g, RadianceArea cos cos_e
 * / r^2 (luminance), that the height field lets through (Visible, the exact march ShadeReliefRay
 * shadows each sample with); 1 where the group does not light the cell. `groups` values per cell,
 * row-major, j slowest. What the relief mapper multiplies an emitter light's contribution by
 * instead of marching one shadow ray to the light's centre: a point light's hard shadow is not
 * the area light's penumbra, which is as wide as a slot's bottom where the light is near
 * (vtkIrradianceProbesTexture). Parallel; progress, stop and `rows` as ReliefVisibleShareMap.
 */
MESOLIGHTRELIEFCORE_EXPORT std::vector<float> ReliefEmitterShadowMap(const HeightField& hf,
  const ReliefFrame& frame, const std::vector<ReliefEmitterSample>& samples,
  const std::vector<int>& group, int groups, int width, int height,
  const ProgressCallback& progress = {}, GridRows rows = {});

/**
 * The side walls of a walled relief (HeightField::Edge::Walled) for the relief mapper: what
 * ReliefVisibleShareMap, ReliefSeenShareMap and ReliefEmitterShadowMap hold for the height field's
 * points, at points of the four walls, around the wall's own normal (ReliefWallNormal). A wall's
 * visible share runs from the room's at its lip to a slot bottom's at its foot, so the border
 * texel's share beside it (what the mapper read before) is right nowhere on it. Four values per
 * cell: V, V over the share above the macro plane, Vs (ReliefSeenShare with `share`, the
 * visible-share map of width x height pairs, walls met marched) and the share of the emitter
 * samples' direct irradiance the relief lets through (as ReliefEmitterShadowMap's one group; 1
 * without samples). The grid: `width` cells along every wall (cell i at s = (i + 1/2) / width
 * along it) and `levels` rows per wall, row r = wall levels + l (walls u = 0, u = 1, v = 0,
 * v = 1), level l at depth (l + 1/2) / levels of the border's depth there (DepthAt on the
 * border); where the border is at the surface (no wall) the cell is all 1. Row-major, r slowest.
 * With `probes` (ReliefLighting's SH9 probes) the second value is instead ShadeReliefRay's
 * radiance-weighted share (the probes' radiance along the directions that leave the relief over
 * that along all of them, at the wall's point): half of a wall's hemisphere lies behind the macro
 * plane, where SH9 rings (a probe's light cut off at the plane is not zero behind it in 9
 * coefficients), so V over the share above the plane overstates the wall's probe light.
 * With `wallShare` (ReliefWallVisibleShareMap's, whole, for this width and levels) the first two
 * values are copied from it (the second unless `probes` weighs it) and the third reads the walls'
 * shares from it (ReliefWallShares). Parallel; progress, stop and `rows` (of the 4 levels rows) as
 * ReliefVisibleShareMap.
 */
MESOLIGHTRELIEFCORE_EXPORT std::vector<float> ReliefWallShareMap(const HeightField& hf,
  const ReliefFrame& frame, const std::vector<float>& share, int width, int height, int levels,
  int count, const std::vector<ReliefEmitterSample>& samples = {},
  const ProgressCallback& progress = {}, GridRows rows = {}, const ReliefLighting* probes = nullptr,
  const std::vector<float>* wallShare = nullptr);

/**
 * ReliefWallShareMap's first two values alone (V and V over the share above the macro plane, on
 * the same grid of `width` cells along each wall and 4 x `levels` rows; 1 where the border is at
 * the surface): what ReliefSeenShareMap reads for the directions that meet a side wall
 * (ReliefWallShares), so it comes before the seen shares, and what ReliefWallShareMap then takes
 * as `wallShare` instead of marching the walls' directions again. Parallel; progress, stop and
 * `rows` (of the 4 levels rows) as ReliefVisibleShareMap.
 */
MESOLIGHTRELIEFCORE_EXPORT std::vector<float> ReliefWallVisibleShareMap(const HeightField& hf,
  const ReliefFrame& frame, int width, int levels, int count, const ProgressCallback& progress = {},
  GridRows rows = {});

} // namespace mesolight

#endif
