// SPDX-License-Identifier: BSD-3-Clause
// A relief on a planar surface of a scene as real geometry: the surface's triangles replaced by a
// dense mesh displaced into the surface by a depth map, the brute-force reference that relief
// mapping approximates (Policarpo, Oliveira and Comba, "Real-Time Relief Mapping on Arbitrary
// Polygonal Surfaces"), here for the path tracer, so that a relief lit by the light field can be
// measured against the same relief lit by every path of the scene.
//
// Conventions are the relief mapper's (vtkReliefProperty, "Units: DepthScale";
// vtkHeightFieldMeshFilter): depth in [0, 1], 0 the surface itself, 1 the deepest; texel (i, j)
// of a W x H map sits at texture coordinate ((i + 0.5) / W, (j + 0.5) / H), row 0 at v = 0 (VTK's
// bottom row first); between texel centres the depth is bilinear, beyond the outer centres it is
// clamped to the edge (the mapper's default ClampToEdge); a point of texture coordinate (u, v) is
// moved along -N by depth(u, v) * DepthScale * |dP/du|, where N is the side the surface faces and
// |dP/du| the world length of one unit of u (the texture's width on the surface).
//
// The edge rule: the relief is recessed into its surface, and beyond the surface the solid
// reaches the surface level, so side walls from the undisplaced boundary down to the relief close
// it. A ray below the surface that reaches the border meets a wall, as the relief mapper's march
// (vtkReliefHeightFieldFS.glsl, mlOutsideWalledRelief) and the CPU intersector
// (HeightField::Edge::Walled) meet it; the texture's clamp-to-edge continuation is never seen.
#ifndef mesolight_SurfaceRelief_h
#define mesolight_SurfaceRelief_h

#include "TriangleScene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{

/** A surface that cannot carry a relief (unknown, empty, not planar) or a bad depth map. */
class SurfaceReliefError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/** A depth map: Width x Height depths in [0, 1], row by row, row 0 at v = 0. */
struct DepthMap
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Depth;

  float At(int i, int j) const
  {
    return this->Depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(this->Width) +
      static_cast<std::size_t>(i)];
  }
  /** Bilinear between texel centres, clamped to the edge outside them. */
  float Sample(double u, double v) const;
};

/**
 * The plane of a planar surface and the texture frame of the rule used when the surface has no
 * texture coordinates of its own: the depth image stretched once over the surface's bounding
 * rectangle in its plane, upright. V points along world +y projected into the plane (along +z
 * when |N.y| >= 0.9, a surface within about 25 degrees of horizontal), U = V x N, so that
 * (U, V, N) is right-handed and the image is seen unmirrored from the side the surface faces.
 * The one derivation of the rule: `trace --relief` (DisplaceSurface) and the reliefs lit by a
 * light field (`vlf render --relief`, the walkthrough: vlf::FindReliefSurface) both call
 * SurfacePlaneOf.
 */
struct SurfacePlane
{
  glm::vec3 Origin{ 0.0f };             // texture coordinate (0, 0)
  glm::vec3 AxisU{ 1.0f, 0.0f, 0.0f };  // world vector from u = 0 to u = 1
  glm::vec3 AxisV{ 0.0f, 1.0f, 0.0f };  // world vector from v = 0 to v = 1
  glm::vec3 Normal{ 0.0f, 0.0f, 1.0f }; // unit; the side the surface's triangles face

  /** The plane-rule texture coordinate of a point of the plane. */
  glm::vec2 TextureCoordinate(const glm::vec3& point) const;
};

/**
 * How far a planar surface's vertices may lie off its plane, as a fraction of the surface's
 * bounding-box diagonal: the published Cornell box's red wall, 0.2% off, is taken; a relief's
 * depth is far larger than what is left.
 */
constexpr double SurfacePlanarTolerance = 0.01;

/**
 * The plane of the given triangles of a mesh, through their area-weighted centroid, and its
 * plane-rule texture frame. Throws SurfaceReliefError when the list is empty or an index is out
 * of range, when the triangles have no area, or when they are not planar: a vertex farther from
 * the plane than SurfacePlanarTolerance times the surface's bounding-box diagonal, or a triangle
 * facing more than 60 degrees away. The displaced mesh follows a nearly planar surface's own
 * triangles. `name` is only for the messages ("surface 'back'").
 */
SurfacePlane SurfacePlaneOf(
  const TriangleMesh& mesh, const std::vector<std::size_t>& triangles, const std::string& name);

/** The plane-rule texture coordinates (SurfacePlane) of every vertex of the triangles. */
std::vector<glm::vec2> PlaneTextureCoordinates(
  const TriangleMesh& mesh, const std::vector<std::size_t>& triangles, const SurfacePlane& plane);

struct SurfaceReliefSettings
{
  float DepthScale = 0.05f; // world depth of depth 1 / world width of one unit of u
  int Subdivision = 1;      // grid lines per texel pitch (1: one vertex per texel centre)
};

/** What DisplaceSurface did. */
struct SurfaceReliefResult
{
  TriangleScene Scene;
  std::size_t SurfaceTriangles = 0; // displaced triangles (they replace the surface's)
  std::size_t SideTriangles = 0;    // walls closing the relief along the surface's boundary
  SurfacePlane Plane;
};

/**
 * The scene with the given triangles (a planar surface) replaced by the displaced dense mesh:
 * grid lines through every texel centre (Subdivision per texel pitch) and along the surface's
 * texture-space bounding box, each grid cell clipped to the surface's triangles in texture space
 * and triangulated, each vertex moved into the surface by its depth (see the file comment). The
 * surface's own texture coordinates are used when the mesh has them (one per position), else the
 * plane rule (SurfacePlane). Vertices are shared, and the boundary is closed by side walls from
 * the undisplaced boundary down to the displaced one, facing into the relief, so that no light
 * passes between the relief and the neighbouring surfaces. The new triangles keep the material of
 * the triangle they come from (and its SurfaceIds entry); the other triangles keep their order
 * and the new ones come after them. Throws SurfaceReliefError for a surface SurfacePlaneOf refuses
 * or a depth map that is empty, not Width x Height, or has depths outside [0, 1].
 */
SurfaceReliefResult DisplaceSurface(const TriangleScene& scene,
  const std::vector<std::size_t>& triangles, const DepthMap& depth,
  const SurfaceReliefSettings& settings, const std::string& name = "the surface");

/** DisplaceSurface on the named surface (SurfaceTriangles); an unknown name throws
 * SurfaceReliefError listing the scene's surfaces. */
SurfaceReliefResult DisplaceSurface(const TriangleScene& scene, const std::string& surface,
  const DepthMap& depth, const SurfaceReliefSettings& settings);

} // namespace mesolight

#endif
