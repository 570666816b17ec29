// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceRelief.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace mesolight
{

float DepthMap::Sample(double u, double v) const
{
  // Texel centres at (i + 0.5) / W: x = u W - 0.5 in texel index units, clamped to the outer ones.
  const double x = std::min(std::max(u * this->Width - 0.5, 0.0), this->Width - 1.0);
  const double y = std::min(std::max(v * this->Height - 0.5, 0.0), this->Height - 1.0);
  const int i0 = std::min(static_cast<int>(x), this->Width - 1);
  const int j0 = std::min(static_cast<int>(y), this->Height - 1);
  const int i1 = std::min(i0 + 1, this->Width - 1);
  const int j1 = std::min(j0 + 1, this->Height - 1);
  const double fx = x - i0;
  const double fy = y - j0;
  const double bottom = (1.0 - fx) * this->At(i0, j0) + fx * this->At(i1, j0);
  const double top = (1.0 - fx) * this->At(i0, j1) + fx * this->At(i1, j1);
  return static_cast<float>((1.0 - fy) * bottom + fy * top);
}

namespace
{
// The fix a refusal for a non-planar surface suggests.
constexpr const char* Split =
  ": split the surface into planar ones with their own `g` names in the OBJ file";
} // namespace

glm::vec2 SurfacePlane::TextureCoordinate(const glm::vec3& point) const
{
  const glm::vec3 d = point - this->Origin;
  return glm::vec2(glm::dot(d, this->AxisU) / glm::dot(this->AxisU, this->AxisU),
    glm::dot(d, this->AxisV) / glm::dot(this->AxisV, this->AxisV));
}

SurfacePlane SurfacePlaneOf(
  const TriangleMesh& mesh, const std::vector<std::size_t>& triangles, const std::string& name)
{
  if (triangles.empty())
  {
    throw SurfaceReliefError(name + " has no triangles");
  }
  glm::dvec3 normalSum(0.0);
  glm::dvec3 lower(std::numeric_limits<double>::max());
  glm::dvec3 upper(-std::numeric_limits<double>::max());
  for (std::size_t t : triangles)
  {
    if (t >= mesh.TriangleCount())
    {
      throw SurfaceReliefError(name + " names triangle " + std::to_string(t) + " of a mesh of " +
        std::to_string(mesh.TriangleCount()));
    }
    normalSum += glm::dvec3(mesh.FaceNormal(t));
    for (int c = 0; c < 3; ++c)
    {
      const glm::dvec3 p(mesh.Vertex(t, c));
      lower = glm::min(lower, p);
      upper = glm::max(upper, p);
    }
  }
  const double diagonal = glm::length(upper - lower);
  const double normalLength = glm::length(normalSum);
  if (!(diagonal > 0.0))
  {
    throw SurfaceReliefError(name + " has no area");
  }
  // Faces that cancel out (a closed object: a box, a bracket, a sphere) have area but no one
  // side: not "no area", which a user looking at the object knows to be wrong.
  if (!(normalLength > 1e-6 * diagonal * diagonal))
  {
    throw SurfaceReliefError(
      name + " is not planar: its faces turn every way (a closed or " + "curved object)");
  }
  const glm::dvec3 n = normalSum / normalLength;
  // The plane through the area-weighted centroid.
  glm::dvec3 centroid(0.0);
  double area = 0.0;
  for (std::size_t t : triangles)
  {
    const double a = 0.5 * glm::length(glm::dvec3(mesh.FaceNormal(t)));
    centroid += a / 3.0 *
      (glm::dvec3(mesh.Vertex(t, 0)) + glm::dvec3(mesh.Vertex(t, 1)) +
        glm::dvec3(mesh.Vertex(t, 2)));
    area += a;
  }
  centroid /= area;
  for (std::size_t t : triangles)
  {
    const glm::dvec3 face(mesh.FaceNormal(t));
    const double faceLength = glm::length(face);
    if (faceLength > 0.0 && glm::dot(face / faceLength, n) < 0.5)
    {
      std::ostringstream message;
      message << name << " is not planar: triangle " << t
              << " faces another way than the surface; a relief needs one plane" << Split;
      throw SurfaceReliefError(message.str());
    }
    for (int c = 0; c < 3; ++c)
    {
      const double distance = std::abs(glm::dot(glm::dvec3(mesh.Vertex(t, c)) - centroid, n));
      if (distance > SurfacePlanarTolerance * diagonal)
      {
        std::ostringstream message;
        message << name << " is not planar: a vertex of triangle " << t << " lies " << distance
                << " from the surface's plane (more than " << SurfacePlanarTolerance * diagonal
                << "); a relief needs one plane" << Split;
        throw SurfaceReliefError(message.str());
      }
    }
  }
  // V: world up projected into the plane (world +z for a surface within about 25 degrees of
  // horizontal), U = V x N.
  const glm::dvec3 up = std::abs(n.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
  glm::dvec3 v = up - glm::dot(up, n) * n;
  v = glm::normalize(v);
  const glm::dvec3 u = glm::cross(v, n);
  double uMin = std::numeric_limits<double>::max(), vMin = uMin;
  double uMax = -uMin, vMax = -uMin;
  for (std::size_t t : triangles)
  {
    for (int c = 0; c < 3; ++c)
    {
      const glm::dvec3 d = glm::dvec3(mesh.Vertex(t, c)) - centroid;
      uMin = std::min(uMin, glm::dot(d, u));
      uMax = std::max(uMax, glm::dot(d, u));
      vMin = std::min(vMin, glm::dot(d, v));
      vMax = std::max(vMax, glm::dot(d, v));
    }
  }
  if (!(uMax - uMin > 0.0) || !(vMax - vMin > 0.0))
  {
    throw SurfaceReliefError(name + " has no area");
  }
  SurfacePlane plane;
  plane.Origin = glm::vec3(centroid + uMin * u + vMin * v);
  plane.AxisU = glm::vec3((uMax - uMin) * u);
  plane.AxisV = glm::vec3((vMax - vMin) * v);
  plane.Normal = glm::vec3(n);
  return plane;
}

std::vector<glm::vec2> PlaneTextureCoordinates(
  const TriangleMesh& mesh, const std::vector<std::size_t>& triangles, const SurfacePlane& plane)
{
  std::vector<glm::vec2> coordinates;
  coordinates.reserve(3 * triangles.size());
  for (std::size_t t : triangles)
  {
    for (int c = 0; c < 3; ++c)
    {
      coordinates.push_back(plane.TextureCoordinate(mesh.Vertex(t, c)));
    }
  }
  return coordinates;
}

namespace
{
using Point2 = glm::dvec2;

// A half-plane of a triangle's edge line in texture space. The line is set up from its end
// points in a fixed (lexicographic) order, so the two triangles sharing an edge compute bit for
// bit the same distances (of opposite sign) and so the same crossing points: the shared vertices
// weld and the mesh stays watertight.
struct EdgeLine
{
  Point2 A, B;
  double Sign = 1.0;
  double Distance(const Point2& p) const
  {
    return this->Sign *
      ((this->B.x - this->A.x) * (p.y - this->A.y) - (this->B.y - this->A.y) * (p.x - this->A.x));
  }
};

bool LexLess(const Point2& a, const Point2& b)
{
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

EdgeLine MakeEdgeLine(const Point2& from, const Point2& to, const Point2& inside)
{
  EdgeLine line;
  line.A = LexLess(from, to) ? from : to;
  line.B = LexLess(from, to) ? to : from;
  line.Sign = 1.0;
  if (line.Distance(inside) < 0.0)
  {
    line.Sign = -1.0;
  }
  return line;
}

// The crossing of segment p-q with a line, computed from the lexicographically smaller end so
// that it does not depend on the direction the segment is walked.
Point2 Crossing(Point2 p, Point2 q, double dp, double dq)
{
  if (LexLess(q, p))
  {
    std::swap(p, q);
    std::swap(dp, dq);
  }
  const double t = dp / (dp - dq);
  return p + t * (q - p);
}

// Sutherland-Hodgman: keeps the part of a convex polygon on the inside (distance >= 0) of a line.
std::vector<Point2> ClipPolygon(const std::vector<Point2>& polygon, const EdgeLine& line)
{
  std::vector<Point2> out;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < n; ++k)
  {
    const Point2& p = polygon[k];
    const Point2& q = polygon[(k + 1) % n];
    const double dp = line.Distance(p);
    const double dq = line.Distance(q);
    if (dp >= 0.0)
    {
      out.push_back(p);
    }
    if ((dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0))
    {
      out.push_back(Crossing(p, q, dp, dq));
    }
  }
  return out;
}

struct PointHash
{
  std::size_t operator()(const Point2& p) const
  {
    std::uint64_t a = 0, b = 0;
    std::memcpy(&a, &p.x, sizeof a);
    std::memcpy(&b, &p.y, sizeof b);
    return static_cast<std::size_t>(a * 0x9E3779B97F4A7C15ull ^ (b + 0x632BE59BD9B4E019ull));
  }
};

// Grid lines: the texel centres (Subdivision lines per texel pitch) inside (lo, hi), and lo, hi.
std::vector<double> GridLines(double lo, double hi, int texels, int subdivision)
{
  std::vector<double> lines{ lo };
  const double pitch = 1.0 / (static_cast<double>(texels) * subdivision);
  // Lines at (0.5 + k / subdivision) / texels = (k + subdivision / 2) * pitch.
  const double offset = 0.5 / texels;
  const double first = std::ceil((lo - offset) / pitch);
  for (double k = first;; k += 1.0)
  {
    const double x = offset + k * pitch;
    if (x >= hi)
    {
      break;
    }
    if (x > lo)
    {
      lines.push_back(x);
    }
  }
  lines.push_back(hi);
  return lines;
}

std::size_t FindCell(const std::vector<double>& lines, double x)
{
  // The cell [lines[k], lines[k + 1]] holding x, clamped to the valid cells.
  const auto it = std::upper_bound(lines.begin(), lines.end(), x);
  const std::size_t k =
    static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - lines.begin() - 1));
  return std::min(k, lines.size() - 2);
}
} // namespace

SurfaceReliefResult DisplaceSurface(const TriangleScene& scene,
  const std::vector<std::size_t>& triangles, const DepthMap& depth,
  const SurfaceReliefSettings& settings, const std::string& name)
{
  if (depth.Width < 1 || depth.Height < 1 ||
    depth.Depth.size() != static_cast<std::size_t>(depth.Width) * depth.Height)
  {
    throw SurfaceReliefError("the depth map of " + name + " is empty or not Width x Height");
  }
  for (float d : depth.Depth)
  {
    if (!(d >= 0.0f && d <= 1.0f))
    {
      throw SurfaceReliefError("the depth map of " + name + " has a depth outside [0, 1]");
    }
  }
  if (!(settings.DepthScale >= 0.0f) || !std::isfinite(settings.DepthScale))
  {
    throw SurfaceReliefError("the depth scale of " + name + " must be finite and >= 0");
  }
  if (settings.Subdivision < 1 || settings.Subdivision > 64)
  {
    throw SurfaceReliefError("the relief subdivision must be in [1, 64]");
  }
  SurfaceReliefResult result;
  result.Plane = SurfacePlaneOf(scene, triangles, name);
  const glm::dvec3 normal(result.Plane.Normal);
  const bool named = scene.SurfaceIds.size() == scene.TriangleCount() && !scene.SurfaceIds.empty();
  const bool ownCoordinates =
    !scene.TextureCoordinates.empty() && scene.TextureCoordinates.size() == scene.Positions.size();

  // Texture coordinates of the surface's corners, and its texture-space bounds.
  struct SourceTriangle
  {
    Point2 Uv[3];
    glm::dvec3 P[3];
    std::uint32_t Material = 0;
    std::uint32_t Surface = TriangleScene::NoSurface;
    // World position = P0 + a (u - u0) + b (v - v0): the affine map of texture space.
    glm::dvec3 DPdU, DPdV;
    EdgeLine Lines[3];
    Point2 Lower, Upper;
  };
  std::vector<SourceTriangle> sources;
  sources.reserve(triangles.size());
  Point2 lower(std::numeric_limits<double>::max());
  Point2 upper(-std::numeric_limits<double>::max());
  for (std::size_t t : triangles)
  {
    SourceTriangle s;
    s.Material = scene.MaterialIds[t];
    s.Surface = named ? scene.SurfaceIds[t] : TriangleScene::NoSurface;
    for (int c = 0; c < 3; ++c)
    {
      s.P[c] = glm::dvec3(scene.Vertex(t, c));
      s.Uv[c] = ownCoordinates ? Point2(scene.TextureCoordinates[scene.Triangles[t][c]])
                               : Point2(result.Plane.TextureCoordinate(scene.Vertex(t, c)));
    }
    const Point2 e1 = s.Uv[1] - s.Uv[0];
    const Point2 e2 = s.Uv[2] - s.Uv[0];
    const double det = e1.x * e2.y - e1.y * e2.x;
    if (std::abs(det) <= 1e-14)
    {
      if (glm::length(glm::dvec3(scene.FaceNormal(t))) > 0.0)
      {
        throw SurfaceReliefError(name + ": triangle " + std::to_string(t) +
          " has degenerate texture coordinates (a relief needs them to span the triangle)");
      }
      continue; // a degenerate triangle: nothing to displace
    }
    const glm::dvec3 q1 = s.P[1] - s.P[0];
    const glm::dvec3 q2 = s.P[2] - s.P[0];
    s.DPdU = (e2.y * q1 - e1.y * q2) / det;
    s.DPdV = (-e2.x * q1 + e1.x * q2) / det;
    for (int c = 0; c < 3; ++c)
    {
      s.Lines[c] = MakeEdgeLine(s.Uv[c], s.Uv[(c + 1) % 3], s.Uv[(c + 2) % 3]);
    }
    s.Lower = glm::min(s.Uv[0], glm::min(s.Uv[1], s.Uv[2]));
    s.Upper = glm::max(s.Uv[0], glm::max(s.Uv[1], s.Uv[2]));
    lower = glm::min(lower, s.Lower);
    upper = glm::max(upper, s.Upper);
    sources.push_back(s);
  }
  if (sources.empty())
  {
    throw SurfaceReliefError(name + " has no area");
  }
  const std::vector<double> linesU = GridLines(lower.x, upper.x, depth.Width, settings.Subdivision);
  const std::vector<double> linesV =
    GridLines(lower.y, upper.y, depth.Height, settings.Subdivision);

  // The scene without the surface's triangles.
  TriangleScene& out = result.Scene;
  out.Materials = scene.Materials;
  out.SurfaceNames = scene.SurfaceNames;
  out.Positions = scene.Positions;
  out.Normals = scene.Normals;
  out.TextureCoordinates = scene.TextureCoordinates;
  {
    std::vector<bool> replaced(scene.TriangleCount(), false);
    for (std::size_t t : triangles)
    {
      replaced[t] = true;
    }
    for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
    {
      if (!replaced[t])
      {
        out.Triangles.push_back(scene.Triangles[t]);
        out.MaterialIds.push_back(scene.MaterialIds[t]);
        if (named)
        {
          out.SurfaceIds.push_back(scene.SurfaceIds[t]);
        }
      }
    }
  }
  const bool withNormals = !scene.Normals.empty() && scene.Normals.size() == scene.Positions.size();
  const bool withCoordinates = ownCoordinates;
  const std::size_t firstNew = out.Positions.size();
  const std::size_t firstSurfaceTriangle = out.Triangles.size();

  // Welded vertices of the displaced surface, keyed by texture coordinate (per source triangle's
  // affine map; the maps agree on shared edges up to rounding, which the key does not see).
  std::unordered_map<Point2, std::uint32_t, PointHash> welded;
  std::vector<Point2> vertexUv;
  std::vector<double> vertexDepth; // world displacement
  const auto vertexOf = [&](const Point2& uv, const SourceTriangle& s) -> std::uint32_t
  {
    const auto found = welded.find(uv);
    if (found != welded.end())
    {
      return found->second;
    }
    const double displacement =
      static_cast<double>(depth.Sample(uv.x, uv.y)) * settings.DepthScale * glm::length(s.DPdU);
    const glm::dvec3 p = s.P[0] + (uv.x - s.Uv[0].x) * s.DPdU + (uv.y - s.Uv[0].y) * s.DPdV;
    const auto index = static_cast<std::uint32_t>(out.Positions.size());
    out.Positions.emplace_back(p - displacement * normal);
    if (withNormals)
    {
      out.Normals.emplace_back(result.Plane.Normal); // replaced by the mesh's below
    }
    if (withCoordinates)
    {
      out.TextureCoordinates.emplace_back(uv);
    }
    vertexUv.push_back(uv);
    vertexDepth.push_back(displacement);
    welded.emplace(uv, index);
    return index;
  };
  const bool uvMirrored = [&]
  {
    // Texture space mirrored relative to the surface's front: triangles are wound the other way.
    const SourceTriangle& s = sources.front();
    return glm::dot(glm::cross(s.DPdU, s.DPdV), normal) < 0.0;
  }();
  const auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t material,
                      std::uint32_t surface)
  {
    if (a == b || b == c || a == c)
    {
      return;
    }
    out.Triangles.push_back(uvMirrored ? glm::uvec3(a, c, b) : glm::uvec3(a, b, c));
    out.MaterialIds.push_back(material);
    if (named)
    {
      out.SurfaceIds.push_back(surface);
    }
  };
  std::vector<std::uint32_t> fan;
  for (const SourceTriangle& s : sources)
  {
    const std::size_t i0 = FindCell(linesU, s.Lower.x), i1 = FindCell(linesU, s.Upper.x);
    const std::size_t j0 = FindCell(linesV, s.Lower.y), j1 = FindCell(linesV, s.Upper.y);
    for (std::size_t j = j0; j <= j1; ++j)
    {
      for (std::size_t i = i0; i <= i1; ++i)
      {
        // The cell counter-clockwise in texture space.
        const std::vector<Point2> cell{ { linesU[i], linesV[j] }, { linesU[i + 1], linesV[j] },
          { linesU[i + 1], linesV[j + 1] }, { linesU[i], linesV[j + 1] } };
        bool inside = true;
        for (const Point2& p : cell)
        {
          for (const EdgeLine& line : s.Lines)
          {
            inside = inside && line.Distance(p) >= 0.0;
          }
        }
        std::vector<Point2> polygon = cell;
        if (!inside)
        {
          for (const EdgeLine& line : s.Lines)
          {
            polygon = ClipPolygon(polygon, line);
            if (polygon.size() < 3)
            {
              break;
            }
          }
        }
        if (polygon.size() < 3)
        {
          continue;
        }
        fan.clear();
        for (const Point2& p : polygon)
        {
          const std::uint32_t index = vertexOf(p, s);
          if (fan.empty() || fan.back() != index)
          {
            fan.push_back(index);
          }
        }
        while (fan.size() > 1 && fan.back() == fan.front())
        {
          fan.pop_back();
        }
        if (fan.size() == 4 && polygon.size() == 4 && inside)
        {
          // A whole cell: split along the diagonal as vtkHeightFieldMeshFilter does.
          emit(fan[0], fan[1], fan[2], s.Material, s.Surface);
          emit(fan[0], fan[2], fan[3], s.Material, s.Surface);
          continue;
        }
        for (std::size_t k = 1; k + 1 < fan.size(); ++k)
        {
          emit(fan[0], fan[k], fan[k + 1], s.Material, s.Surface);
        }
      }
    }
  }
  result.SurfaceTriangles = out.Triangles.size() - firstSurfaceTriangle;

  // Side walls along the boundary: edges of the displaced surface used by one triangle only.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edgeUse;
  for (std::size_t t = firstSurfaceTriangle; t < out.Triangles.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      std::uint32_t a = out.Triangles[t][c], b = out.Triangles[t][(c + 1) % 3];
      ++edgeUse[{ std::min(a, b), std::max(a, b) }];
    }
  }
  std::unordered_map<std::uint32_t, std::uint32_t> topOf;
  const auto top = [&](std::uint32_t v) -> std::uint32_t
  {
    const auto found = topOf.find(v);
    if (found != topOf.end())
    {
      return found->second;
    }
    const auto index = static_cast<std::uint32_t>(out.Positions.size());
    out.Positions.emplace_back(glm::dvec3(out.Positions[v]) + vertexDepth[v - firstNew] * normal);
    if (withNormals)
    {
      out.Normals.emplace_back(result.Plane.Normal);
    }
    if (withCoordinates)
    {
      out.TextureCoordinates.emplace_back(vertexUv[v - firstNew]);
    }
    topOf.emplace(v, index);
    return index;
  };
  const std::size_t surfaceEnd = out.Triangles.size();
  for (std::size_t t = firstSurfaceTriangle; t < surfaceEnd; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::uint32_t a = out.Triangles[t][c], b = out.Triangles[t][(c + 1) % 3];
      if (edgeUse[{ std::min(a, b), std::max(a, b) }] != 1)
      {
        continue;
      }
      const double da = vertexDepth[a - firstNew], db = vertexDepth[b - firstNew];
      if (da <= 0.0 && db <= 0.0)
      {
        continue; // flush with the surface here: nothing to close
      }
      // The triangle runs a -> b counter-clockwise seen from the front: its inside, where the
      // side wall must face, is N x (b - a).
      const std::uint32_t material = out.MaterialIds[t];
      const std::uint32_t surface = named ? out.SurfaceIds[t] : TriangleScene::NoSurface;
      const std::uint32_t ta = top(a), tb = top(b);
      const auto side = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r)
      {
        const glm::dvec3 pp(out.Positions[p]), pq(out.Positions[q]), pr(out.Positions[r]);
        const glm::dvec3 face = glm::cross(pq - pp, pr - pp);
        const glm::dvec3 inward =
          glm::cross(normal, glm::dvec3(out.Positions[b]) - glm::dvec3(out.Positions[a]));
        if (glm::length(face) <= 0.0)
        {
          return;
        }
        out.Triangles.push_back(
          glm::dot(face, inward) >= 0.0 ? glm::uvec3(p, q, r) : glm::uvec3(p, r, q));
        out.MaterialIds.push_back(material);
        if (named)
        {
          out.SurfaceIds.push_back(surface);
        }
        ++result.SideTriangles;
      };
      if (da > 0.0)
      {
        side(ta, tb, a);
      }
      if (db > 0.0)
      {
        side(tb, b, a);
      }
    }
  }
  if (withNormals)
  {
    // Area-weighted vertex normals of the new geometry.
    for (std::size_t v = firstNew; v < out.Normals.size(); ++v)
    {
      out.Normals[v] = glm::vec3(0.0f);
    }
    for (std::size_t t = firstSurfaceTriangle; t < out.Triangles.size(); ++t)
    {
      const glm::vec3 face = out.FaceNormal(t);
      for (int c = 0; c < 3; ++c)
      {
        out.Normals[out.Triangles[t][c]] += face;
      }
    }
    for (std::size_t v = firstNew; v < out.Normals.size(); ++v)
    {
      const float length = glm::length(out.Normals[v]);
      out.Normals[v] = length > 0.0f ? out.Normals[v] / length : result.Plane.Normal;
    }
  }
  return result;
}

SurfaceReliefResult DisplaceSurface(const TriangleScene& scene, const std::string& surface,
  const DepthMap& depth, const SurfaceReliefSettings& settings)
{
  std::vector<std::size_t> triangles;
  try
  {
    triangles = SurfaceTriangles(scene, surface);
  }
  catch (const SceneSurfaceError& e)
  {
    throw SurfaceReliefError(e.what());
  }
  return DisplaceSurface(scene, triangles, depth, settings, "surface '" + surface + "'");
}

} // namespace mesolight
