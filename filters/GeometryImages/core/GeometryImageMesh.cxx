// SPDX-License-Identifier: BSD-3-Clause
#include "GeometryImageMesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace mesolight
{

//------------------------------------------------------------------------------
bool GeometryImage::Valid(int i, int j) const
{
  const glm::dvec3& p = this->At(i, j);
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

//------------------------------------------------------------------------------
size_t GeometryImage::CountValid() const
{
  size_t n = 0;
  for (int j = 0; j < this->Height; ++j)
  {
    for (int i = 0; i < this->Width; ++i)
    {
      n += this->Valid(i, j) ? 1 : 0;
    }
  }
  return n;
}

namespace
{
// Throws GeometryImageMeshError when the image cannot be meshed at all.
void CheckImage(const GeometryImage& image)
{
  if (image.Width < 2 || image.Height < 2)
  {
    std::ostringstream s;
    s << "the geometry image is " << image.Width << " x " << image.Height
      << " pixels; a mesh needs at least 2 x 2";
    throw GeometryImageMeshError(s.str());
  }
  const size_t n = static_cast<size_t>(image.Width) * image.Height;
  if (image.Positions.size() != n || (!image.Normals.empty() && image.Normals.size() != n))
  {
    throw GeometryImageMeshError(
      "the geometry image's position or normal array does not have W x H entries");
  }
  if (image.CountValid() == 0)
  {
    throw GeometryImageMeshError(
      "every pixel of the geometry image is empty (NaN): nothing to mesh");
  }
}

// Counts empty pixels in any rectangle in O(1) (summed-area table).
class EmptyPixelTable
{
public:
  explicit EmptyPixelTable(const GeometryImage& image)
    : W(image.Width + 1)
    , Sums(static_cast<size_t>(image.Width + 1) * (image.Height + 1), 0)
  {
    for (int j = 0; j < image.Height; ++j)
    {
      for (int i = 0; i < image.Width; ++i)
      {
        this->Sums[(j + 1) * this->W + i + 1] = (image.Valid(i, j) ? 0 : 1) +
          this->Sums[j * this->W + i + 1] + this->Sums[(j + 1) * this->W + i] -
          this->Sums[j * this->W + i];
      }
    }
  }
  /// Empty pixels in [x0, x1] x [y0, y1] (inclusive).
  long Count(int x0, int y0, int x1, int y1) const
  {
    return this->Sums[(y1 + 1) * this->W + x1 + 1] - this->Sums[y0 * this->W + x1 + 1] -
      this->Sums[(y1 + 1) * this->W + x0] + this->Sums[y0 * this->W + x0];
  }

private:
  size_t W;
  std::vector<long> Sums;
};

// Adds sampled pixels as mesh vertices once each.
class MeshBuilder
{
public:
  MeshBuilder(const GeometryImage& image, GeometryImageMesh& mesh)
    : Image(image)
    , Mesh(mesh)
    , Ids(static_cast<size_t>(image.Width) * image.Height, -1)
    , GeometricNormals(GeometryNormals(image))
  {
    mesh = GeometryImageMesh();
  }
  int Vertex(int i, int j)
  {
    const size_t k = this->Image.Index(i, j);
    if (this->Ids[k] >= 0)
    {
      return this->Ids[k];
    }
    glm::dvec3 n(0.0);
    if (!this->Image.Normals.empty())
    {
      n = this->Image.Normals[k];
    }
    const double len = glm::length(n);
    if (!(std::isfinite(len) && len > 0.0))
    {
      n = this->GeometricNormals[k];
    }
    n = glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0.0, 0.0, 1.0);
    this->Ids[k] = static_cast<int>(this->Mesh.Points.size());
    this->Mesh.Points.push_back(this->Image.Positions[k]);
    this->Mesh.Normals.push_back(n);
    this->Mesh.TCoords.emplace_back(
      TexelCentre(i, this->Image.Width), TexelCentre(j, this->Image.Height));
    this->Mesh.Pixels.emplace_back(i, j);
    return this->Ids[k];
  }
  void Triangle(const glm::ivec2& a, const glm::ivec2& b, const glm::ivec2& c)
  {
    this->Mesh.Triangles.emplace_back(
      this->Vertex(a.x, a.y), this->Vertex(b.x, b.y), this->Vertex(c.x, c.y));
  }

private:
  const GeometryImage& Image;
  GeometryImageMesh& Mesh;
  std::vector<int> Ids;
  std::vector<glm::dvec3> GeometricNormals;
};

using PixelTriangle = std::array<glm::ivec2, 3>;

// The two triangles of a quad (corners counter-clockwise from (x0, y0)), split along the
// shorter diagonal: the split that follows the surface's fold where it bends.
void SplitQuad(
  const GeometryImage& image, int x0, int y0, int x1, int y1, std::vector<PixelTriangle>& out)
{
  const glm::ivec2 p00(x0, y0), p10(x1, y0), p11(x1, y1), p01(x0, y1);
  const double d1 = glm::distance(image.At(x0, y0), image.At(x1, y1));
  const double d2 = glm::distance(image.At(x1, y0), image.At(x0, y1));
  if (d1 <= d2)
  {
    out.push_back({ p00, p10, p11 });
    out.push_back({ p00, p11, p01 });
  }
  else
  {
    out.push_back({ p00, p10, p01 });
    out.push_back({ p10, p11, p01 });
  }
}

// The largest distance of the full-resolution pixels of [x0, x1] x [y0, y1] to the triangles.
double CellError(const GeometryImage& image, int x0, int y0, int x1, int y1,
  const std::vector<PixelTriangle>& triangles)
{
  double worst = 0.0;
  for (int j = y0; j <= y1; ++j)
  {
    for (int i = x0; i <= x1; ++i)
    {
      const glm::dvec3& p = image.At(i, j);
      double best = std::numeric_limits<double>::infinity();
      for (const PixelTriangle& t : triangles)
      {
        best = std::min(best,
          PointTriangleDistance(
            p, image.At(t[0].x, t[0].y), image.At(t[1].x, t[1].y), image.At(t[2].x, t[2].y)));
      }
      worst = std::max(worst, best);
    }
  }
  return worst;
}

struct Cell
{
  int X0, Y0, X1, Y1; // grid corners (pixels), inclusive
  int Size;           // nominal size (a power of two); clipped at the image's last pixel
  bool Splittable() const { return this->X1 - this->X0 > 1 || this->Y1 - this->Y0 > 1; }
};

void SplitCell(const Cell& c, std::vector<Cell>& out)
{
  const int half = std::max(1, c.Size / 2);
  const int mx = c.X0 + half, my = c.Y0 + half;
  for (int cy = 0; cy < 2; ++cy)
  {
    const int y0 = cy == 0 ? c.Y0 : my;
    const int y1 = cy == 0 ? std::min(my, c.Y1) : c.Y1;
    if (y1 <= y0)
    {
      continue;
    }
    for (int cx = 0; cx < 2; ++cx)
    {
      const int x0 = cx == 0 ? c.X0 : mx;
      const int x1 = cx == 0 ? std::min(mx, c.X1) : c.X1;
      if (x1 <= x0)
      {
        continue;
      }
      out.push_back(Cell{ x0, y0, x1, y1, half });
    }
  }
}

// A leaf's triangles, through every leaf corner on its sides (no T-junctions).
void TriangulateLeaf(const GeometryImage& image, const Cell& c, const std::vector<char>& corner,
  std::vector<PixelTriangle>& out)
{
  out.clear();
  const int w = image.Width;
  const auto marked = [&](int i, int j) { return corner[static_cast<size_t>(j) * w + i] != 0; };
  // Counter-clockwise perimeter: bottom, right, top, left; corners once.
  std::vector<glm::ivec2> ring;
  bool extras = false;
  const auto add = [&](int i, int j, bool isCorner)
  {
    if (isCorner || marked(i, j))
    {
      ring.emplace_back(i, j);
      extras = extras || !isCorner;
    }
  };
  for (int i = c.X0; i < c.X1; ++i)
  {
    add(i, c.Y0, i == c.X0);
  }
  for (int j = c.Y0; j < c.Y1; ++j)
  {
    add(c.X1, j, j == c.Y0);
  }
  for (int i = c.X1; i > c.X0; --i)
  {
    add(i, c.Y1, i == c.X1);
  }
  for (int j = c.Y1; j > c.Y0; --j)
  {
    add(c.X0, j, j == c.Y1);
  }
  if (!extras)
  {
    SplitQuad(image, c.X0, c.Y0, c.X1, c.Y1, out);
    return;
  }
  const int a = c.X1 - c.X0, b = c.Y1 - c.Y0;
  if (a >= 2 && b >= 2)
  {
    // The centre pixel is strictly inside: a fan from it has no degenerate triangle.
    const glm::ivec2 centre(c.X0 + a / 2, c.Y0 + b / 2);
    for (size_t k = 0; k < ring.size(); ++k)
    {
      out.push_back({ centre, ring[k], ring[(k + 1) % ring.size()] });
    }
    return;
  }
  // A thin cell (one pixel across): zip its two long sides together.
  std::vector<glm::ivec2> first, second;
  for (const glm::ivec2& p : ring)
  {
    if (a == 1 ? p.x == c.X0 : p.y == c.Y0)
    {
      first.push_back(p);
    }
    else
    {
      second.push_back(p);
    }
  }
  const auto along = [a](const glm::ivec2& p) { return a == 1 ? p.y : p.x; };
  const auto byAlong = [&](const glm::ivec2& p, const glm::ivec2& q)
  { return along(p) < along(q); };
  std::sort(first.begin(), first.end(), byAlong);
  std::sort(second.begin(), second.end(), byAlong);
  size_t i = 0, j = 0;
  while (i + 1 < first.size() || j + 1 < second.size())
  {
    const bool advanceFirst = i + 1 < first.size() &&
      (j + 1 >= second.size() || along(first[i + 1]) <= along(second[j + 1]));
    // first = left (a == 1) or bottom (b == 1) side; keep counter-clockwise order.
    if (advanceFirst)
    {
      out.push_back(a == 1 ? PixelTriangle{ first[i], second[j], first[i + 1] }
                           : PixelTriangle{ first[i], first[i + 1], second[j] });
      ++i;
    }
    else
    {
      out.push_back(a == 1 ? PixelTriangle{ first[i], second[j], second[j + 1] }
                           : PixelTriangle{ first[i], second[j + 1], second[j] });
      ++j;
    }
  }
}
} // namespace

//------------------------------------------------------------------------------
std::vector<glm::dvec3> GeometryNormals(const GeometryImage& image)
{
  std::vector<glm::dvec3> normals(image.Positions.size(), glm::dvec3(0.0));
  const auto derivative = [&](int i, int j, int di, int dj)
  {
    const int ia = i - di, ja = j - dj, ib = i + di, jb = j + dj;
    const bool a = ia >= 0 && ja >= 0 && image.Valid(ia, ja);
    const bool b = ib < image.Width && jb < image.Height && image.Valid(ib, jb);
    if (a && b)
    {
      return (image.At(ib, jb) - image.At(ia, ja)) * 0.5;
    }
    if (b)
    {
      return image.At(ib, jb) - image.At(i, j);
    }
    if (a)
    {
      return image.At(i, j) - image.At(ia, ja);
    }
    return glm::dvec3(0.0);
  };
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      if (!image.Valid(i, j))
      {
        continue;
      }
      const glm::dvec3 n = glm::cross(derivative(i, j, 1, 0), derivative(i, j, 0, 1));
      const double len = glm::length(n);
      normals[image.Index(i, j)] = len > 0.0 ? n / len : glm::dvec3(0.0);
    }
  }
  return normals;
}

//------------------------------------------------------------------------------
GeometryImageMesh SampleRegular(
  const GeometryImage& image, int stride, const ProgressCallback& progress)
{
  CheckImage(image);
  const int limit = std::max(image.Width, image.Height) - 1;
  if (stride < 1 || stride > limit)
  {
    std::ostringstream s;
    s << "stride " << stride << " is outside 1.." << limit << " for a " << image.Width << " x "
      << image.Height << " geometry image";
    throw GeometryImageMeshError(s.str());
  }
  GeometryImageMesh mesh;
  const auto samples = [stride](int n)
  {
    std::vector<int> s;
    for (int i = 0; i < n - 1; i += stride)
    {
      s.push_back(i);
    }
    s.push_back(n - 1); // the last row / column: the whole image is covered
    return s;
  };
  const std::vector<int> xs = samples(image.Width), ys = samples(image.Height);
  const EmptyPixelTable empty(image);
  MeshBuilder builder(image, mesh);
  std::vector<PixelTriangle> triangles;
  for (size_t b = 0; b + 1 < ys.size(); ++b)
  {
    for (size_t a = 0; a + 1 < xs.size(); ++a)
    {
      if (empty.Count(xs[a], ys[b], xs[a + 1], ys[b + 1]) > 0)
      {
        ++mesh.SkippedQuads;
        continue;
      }
      triangles.clear();
      SplitQuad(image, xs[a], ys[b], xs[a + 1], ys[b + 1], triangles);
      for (const PixelTriangle& t : triangles)
      {
        builder.Triangle(t[0], t[1], t[2]);
      }
    }
    if (!ReportProgress(progress, static_cast<double>(b + 1) / (ys.size() - 1)))
    {
      return mesh;
    }
  }
  if (mesh.Triangles.empty())
  {
    throw GeometryImageMeshError(
      "no quad of the geometry image is free of empty (NaN) pixels at this stride");
  }
  return mesh;
}

//------------------------------------------------------------------------------
GeometryImageMesh SampleAdaptive(
  const GeometryImage& image, double tolerance, const ProgressCallback& progress, int maxCell)
{
  CheckImage(image);
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
  {
    throw GeometryImageMeshError("the tolerance must be a positive world distance");
  }
  GeometryImageMesh mesh;
  const int extent = std::max(image.Width, image.Height) - 1;
  int size = 1;
  while (size * 2 <= extent && (maxCell <= 0 || size * 2 <= maxCell))
  {
    size *= 2;
  }
  const EmptyPixelTable empty(image);
  // Phase 1: split every cell whose two triangles miss a pixel by more than the tolerance.
  std::vector<Cell> pending, leaves;
  for (int y = 0; y < image.Height - 1; y += size)
  {
    for (int x = 0; x < image.Width - 1; x += size)
    {
      pending.push_back(Cell{
        x, y, std::min(x + size, image.Width - 1), std::min(y + size, image.Height - 1), size });
    }
  }
  std::vector<PixelTriangle> triangles;
  size_t done = 0;
  const size_t total = static_cast<size_t>(image.Width) * image.Height;
  while (!pending.empty())
  {
    const Cell c = pending.back();
    pending.pop_back();
    bool split = false;
    if (empty.Count(c.X0, c.Y0, c.X1, c.Y1) > 0)
    {
      split = c.Splittable();
      if (!split)
      {
        ++mesh.SkippedQuads;
        continue;
      }
    }
    else if (c.Splittable())
    {
      triangles.clear();
      SplitQuad(image, c.X0, c.Y0, c.X1, c.Y1, triangles);
      split = CellError(image, c.X0, c.Y0, c.X1, c.Y1, triangles) > tolerance;
    }
    if (split)
    {
      SplitCell(c, pending);
    }
    else
    {
      leaves.push_back(c);
      done += static_cast<size_t>(c.X1 - c.X0) * (c.Y1 - c.Y0);
      if (!ReportProgress(progress, 0.8 * std::min(1.0, static_cast<double>(done) / total)))
      {
        return mesh;
      }
    }
  }
  const size_t skipped = mesh.SkippedQuads;

  // Phase 2: triangulate through the finer neighbours' corners; split leaves that then miss.
  std::vector<char> corner(total, 0);
  std::vector<std::vector<PixelTriangle>> leafTriangles;
  for (int pass = 0;; ++pass)
  {
    std::fill(corner.begin(), corner.end(), 0);
    for (const Cell& c : leaves)
    {
      for (const glm::ivec2& p : { glm::ivec2(c.X0, c.Y0), glm::ivec2(c.X1, c.Y0),
             glm::ivec2(c.X1, c.Y1), glm::ivec2(c.X0, c.Y1) })
      {
        corner[image.Index(p.x, p.y)] = 1;
      }
    }
    leafTriangles.assign(leaves.size(), {});
    std::vector<char> miss(leaves.size(), 0);
    for (size_t k = 0; k < leaves.size(); ++k)
    {
      const Cell& c = leaves[k];
      TriangulateLeaf(image, c, corner, leafTriangles[k]);
      miss[k] =
        c.Splittable() && CellError(image, c.X0, c.Y0, c.X1, c.Y1, leafTriangles[k]) > tolerance;
    }
    std::vector<Cell> next;
    bool changed = false;
    for (size_t k = 0; k < leaves.size(); ++k)
    {
      if (miss[k])
      {
        SplitCell(leaves[k], next);
        changed = true;
      }
      else
      {
        next.push_back(leaves[k]);
      }
    }
    if (!changed)
    {
      break;
    }
    leaves.swap(next);
    if (!ReportProgress(progress, 0.8 + 0.1 * std::min(1.0, (pass + 1) / 8.0)))
    {
      return mesh;
    }
  }

  MeshBuilder builder(image, mesh);
  mesh.SkippedQuads = skipped;
  for (const std::vector<PixelTriangle>& ts : leafTriangles)
  {
    for (const PixelTriangle& t : ts)
    {
      builder.Triangle(t[0], t[1], t[2]);
    }
  }
  ReportProgress(progress, 1.0);
  if (mesh.Triangles.empty())
  {
    throw GeometryImageMeshError("no cell of the geometry image is free of empty (NaN) pixels");
  }
  return mesh;
}

//------------------------------------------------------------------------------
double PointTriangleDistance(
  const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c)
{
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    return glm::length(ap);
  }
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    return glm::length(bp);
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double v = d1 / (d1 - d3);
    return glm::length(p - (a + v * ab));
  }
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    return glm::length(cp);
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double w = d2 / (d2 - d6);
    return glm::length(p - (a + w * ac));
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return glm::length(p - (b + w * (c - b)));
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return glm::length(p - (a + ab * v + ac * w));
}

} // namespace mesolight
