// SPDX-License-Identifier: BSD-3-Clause
// Lookup: reading a propagated LightField (Wither 2005 §2.4.1.3, §3.6). All points and directions
// are in the light field's unit-sphere coordinates (LightField::Scene()).
//
// Radiance leaving a surface point p in direction w: the subfield of the nearest direction to w
// (DirectionSet::Nearest), the cell p projects to, the surface's radiance map there -- either
// that one cell, or bilinear over the 2 x 2 cells of p's 8-neighbourhood that surround it (the
// 8-neighbour interpolation of Wither 2005; cells whose line misses the surface are left out and
// the weights renormalised). DirectionInterpolation::Spherical does this for the three directions
// of the subdivision triangle around w and blends them with DirectionSet::Interpolate's
// spherical weights (Wither's RENDER_RAYTRACE mode).
//
// Irradiance at any point p with normal n (a static surface point, or a point of an object
// that is not part of the field: the movable-object query of Wither 2005 §3.6): for every direction
// d_k, the radiance arriving at p from the side of n along the line of subfield k through p
// (the nearest crossing beyond p that faces p; a back side or nothing gives 0; neighbouring
// lines whose segment at p's depth is not open space -- behind a wall near p -- are left out
// of the bilinear blend), weighted by the
// direction's solid angle w_k (§3.6.2) and the cosine |d_k . n| (the projected cell area,
// §3.6.3); the sum is normalised by the discrete total pi / sum_k w_k |d_k . n| so that a
// uniform radiance L gives exactly pi L. The cost is one pass over the directions, with no
// per-normal tables: the object gather built on it (ObjectGatherer) measured 90-120 microseconds
// per point at 2049 directions on one core here (`mesolight bench gather`, docs/vlf.md).
#ifndef mesolight_vlf_Lookup_h
#define mesolight_vlf_Lookup_h

#include "LightField.h"

#include <glm/vec4.hpp>

namespace mesolight
{
namespace vlf
{

enum class CellInterpolation
{
  Nearest, // the cell p projects to
  Bilinear // the 2 x 2 cells of p's 8-neighbourhood around p
};

enum class DirectionInterpolation
{
  Nearest,  // the nearest direction only
  Spherical // the three directions around w, spherical interpolation weights
};

// Crossings closer than this to a point along a line count as the point's own surface.
constexpr float SelfDepth = 1e-4f;

// The cells around continuous cell coordinates c (LightField::CellCoordinates) and their
// weights: one cell (Nearest), or the bilinear 2 x 2 of the 3 x 3 neighbourhood surrounding c.
// Returns how many were written.
int CellsAround(
  const glm::vec2& c, CellInterpolation mode, int (&i)[4], int (&j)[4], float (&w)[4]);

// The open-segment rule of Lookup::IncidentRadiance, written once: the lookup applies it to the
// field's crossings (Crossing), the object gatherer's line cache (ObjectLineCache.h) to its own
// copy of them. One line of p's neighbourhood, its crossings [first, last) by increasing depth
// (T has a Depth; orientationOf(c) is LightField::Orientation of c's surface; skip(c) true leaves
// c out, as IncidentRadiance's `ignore` does):
template <typename T>
struct SegmentAroundPoint
{
  // The crossings just before and after p's depth (beyond SelfDepth): they bound the segment of
  // this line that p's neighbourhood lies in (nullptr: none on that side).
  const T* Before = nullptr;
  const T* After = nullptr;
  // The bound on p's side `sense` (+1: greater depth) when it faces p; nullptr when there is none
  // (light leaves the scene) or it shows p its back side: no light from this line.
  const T* Sender = nullptr;
  // A neighbouring line tells about p only when its segment is open space like p's: both bounds
  // face into it. Near a wall a neighbour may already be behind the wall at p's depth, or pass
  // beside a wall parallel to it crossing nothing at all; such a line is left out of the blend
  // and the others renormalised (counting it would darken points near walls).
  bool Open = false;
};

template <typename T, typename OrientationOf, typename Skip>
SegmentAroundPoint<T> FindSegment(
  const T* first, const T* last, float depth, int sense, OrientationOf orientationOf, Skip skip)
{
  SegmentAroundPoint<T> segment;
  for (const T* c = first; c != last; ++c)
  {
    if (skip(*c))
    {
      continue;
    }
    if (c->Depth < depth - SelfDepth)
    {
      segment.Before = c;
    }
    else if (c->Depth > depth + SelfDepth)
    {
      segment.After = c;
      break;
    }
  }
  const T* sender = sense > 0 ? segment.After : segment.Before;
  segment.Sender = sender && orientationOf(*sender) == -sense ? sender : nullptr;
  segment.Open = (!segment.Before || orientationOf(*segment.Before) > 0) &&
    (!segment.After || orientationOf(*segment.After) < 0) && first != last;
  return segment;
}

// The blend of the lines around p (IncidentRadiance's): the open lines by their weights,
// renormalised; with no open line around p (p behind a one-sided surface), the heaviest line as
// it is.
class IncidentBlend
{
public:
  void Add(float weight, const glm::vec3& radiance, bool open)
  {
    if (open)
    {
      this->Sum += weight * radiance;
      this->Weight += weight;
    }
    else if (weight > this->FallbackWeight)
    {
      this->Fallback = radiance;
      this->FallbackWeight = weight;
    }
  }
  glm::vec3 Result() const
  {
    return this->Weight > 0.0f ? this->Sum / this->Weight : this->Fallback;
  }

private:
  glm::vec3 Sum{ 0.0f }, Fallback{ 0.0f };
  float Weight = 0.0f, FallbackWeight = -1.0f;
};

struct GatherOptions
{
  CellInterpolation Cells = CellInterpolation::Bilinear;
  // Negative tests only: drop the solid-angle weights (every direction 2 pi / K) or the
  // normalisation by the discrete projected cell area (plain sum of w_k |cos| L).
  bool SolidAngleWeights = true;
  bool ProjectedAreaNormalization = true;
  // Negative tests only: false makes the scene's surfaces transparent to each other -- along
  // every line the brightest crossing beyond p that faces p sends its light, not the nearest
  // one, so emitters shine through blocks and walls that should shadow p.
  bool SceneOcclusion = true;
};

class Lookup
{
public:
  explicit Lookup(const LightField& field)
    : Field(field)
  {
  }

  // Radiance leaving surface `surface` at p (on it) toward unit direction w (front side).
  // Directions the field cannot resolve (grazing) fall back to the diffuse texture.
  glm::vec3 RadianceLeaving(std::uint32_t surface, const glm::vec3& p, const glm::vec3& w,
    CellInterpolation cells = CellInterpolation::Bilinear,
    DirectionInterpolation directions = DirectionInterpolation::Spherical) const;

  // On a distributed field (Distribution.h), this process' share of RadianceLeaving: the
  // weighted sum of the radiance of the directions it holds (xyz) and their weight (w). Summed
  // over the ranks, xyz / w is RadianceLeaving (the diffuse texture where w is 0):
  // vlf::RadianceLeaving in Distribution.h. On a whole field xyz / w is RadianceLeaving itself.
  glm::vec4 RadianceLeavingShare(std::uint32_t surface, const glm::vec3& p, const glm::vec3& w,
    CellInterpolation cells = CellInterpolation::Bilinear,
    DirectionInterpolation directions = DirectionInterpolation::Spherical) const;

  // Diffuse radiance leaving the surface at p: its total diffuse texture, bilinear (the
  // walkthrough's progressive mode, Wither 2005 §2.4.2.2.3).
  glm::vec3 DiffuseRadiance(std::uint32_t surface, const glm::vec3& p) const;

  // Radiance arriving at p along subfield k's lines from the side `sense` (+1: from greater
  // depth, i.e. from p + t d_k), ignoring crossings of `ignore` (the surface p lies on).
  // occlusion false: see GatherOptions::SceneOcclusion (negative tests only). emission false:
  // the sender's own emitted radiance (its material's Ke) is left out, so only light it reflects
  // arrives -- the indirect part, for a caller that integrates the emitters itself.
  glm::vec3 IncidentRadiance(std::size_t k, int sense, const glm::vec3& p,
    CellInterpolation cells = CellInterpolation::Bilinear, std::uint32_t ignore = NoSurface,
    bool occlusion = true, bool emission = true) const;

  // Irradiance at p with unit normal n (see above). `ignore` as for IncidentRadiance. On a
  // distributed field (Distribution.h) the sum covers this rank's directions only, normalised
  // over all directions, so the ranks' results add up to the whole (GatherIrradiance).
  glm::vec3 Irradiance(const glm::vec3& p, const glm::vec3& n, const GatherOptions& options = {},
    std::uint32_t ignore = NoSurface) const;

  // Surface and point of a world-space triangle point (for callers holding triangles).
  std::uint32_t SurfaceOfTriangle(std::size_t triangle) const
  {
    return this->Field.SurfaceOfTriangle(triangle);
  }

private:
  // Outgoing radiance of surface s in subfield k around p (shot so far plus unshot), or false
  // when no cell around p crosses s.
  bool SubfieldRadiance(std::size_t k, std::uint32_t s, const glm::vec3& p, CellInterpolation cells,
    glm::vec3& radiance) const;
  glm::vec3 CellRadiance(
    std::size_t k, int i, int j, std::uint32_t s, std::size_t cell, const glm::vec3& x) const;

  const LightField& Field;
};

} // namespace vlf
} // namespace mesolight

#endif
