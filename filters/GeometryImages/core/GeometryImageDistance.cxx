// SPDX-License-Identifier: BSD-3-Clause
// The Hausdorff distance between a sampled mesh and the full-resolution geometry image.
#include "GeometryImageMesh.h"

#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mesolight
{
namespace
{
// Triangles binned in a uniform grid over their bounding boxes; nearest-distance queries search
// rings of cells outwards until no closer triangle can remain.
class TriangleGrid
{
public:
  TriangleGrid(const std::vector<glm::dvec3>& points, const std::vector<glm::ivec3>& triangles)
    : Points(points)
    , Triangles(triangles)
  {
    this->Lo = glm::dvec3(std::numeric_limits<double>::infinity());
    glm::dvec3 hi(-std::numeric_limits<double>::infinity());
    for (const glm::ivec3& t : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        this->Lo = glm::min(this->Lo, points[t[k]]);
        hi = glm::max(hi, points[t[k]]);
      }
    }
    const glm::dvec3 extent = hi - this->Lo;
    const double largest = std::max({ extent.x, extent.y, extent.z, 1e-12 });
    // About one cell per triangle over a surface: cells of the triangles' typical size.
    double cell = largest / std::max(1.0, std::sqrt(static_cast<double>(triangles.size()) / 2.0));
    // A surface filling its box (a closed model) would ask for far more cells than triangles:
    // at most about four cells per triangle.
    const double budget = 4.0 * std::max<size_t>(1, triangles.size());
    const auto cells = [&](double c)
    {
      double n = 1.0;
      for (int a = 0; a < 3; ++a)
      {
        n *= std::max(1.0, std::ceil(extent[a] / c));
      }
      return n;
    };
    if (cells(cell) > budget)
    {
      cell *= std::cbrt(cells(cell) / budget);
    }
    for (int a = 0; a < 3; ++a)
    {
      this->Dims[a] = std::clamp(static_cast<int>(std::ceil(extent[a] / cell)), 1, 256);
      this->Size[a] = std::max(extent[a] / this->Dims[a], 1e-12);
    }
    this->MinSize = std::min({ this->Size.x, this->Size.y, this->Size.z });
    this->Cells.resize(static_cast<size_t>(this->Dims[0]) * this->Dims[1] * this->Dims[2]);
    for (size_t t = 0; t < triangles.size(); ++t)
    {
      glm::dvec3 lo = points[triangles[t][0]], up = lo;
      for (int k = 1; k < 3; ++k)
      {
        lo = glm::min(lo, points[triangles[t][k]]);
        up = glm::max(up, points[triangles[t][k]]);
      }
      const glm::ivec3 a = this->CellOf(lo), b = this->CellOf(up);
      for (int z = a.z; z <= b.z; ++z)
      {
        for (int y = a.y; y <= b.y; ++y)
        {
          for (int x = a.x; x <= b.x; ++x)
          {
            this->Cells[this->Flat(x, y, z)].push_back(static_cast<int>(t));
          }
        }
      }
    }
  }

  double Distance(const glm::dvec3& p) const
  {
    const glm::ivec3 c = this->CellOf(p);
    double best = std::numeric_limits<double>::infinity();
    const int maxRing = std::max({ this->Dims[0], this->Dims[1], this->Dims[2] });
    for (int r = 0; r <= maxRing; ++r)
    {
      for (int z = c.z - r; z <= c.z + r; ++z)
      {
        for (int y = c.y - r; y <= c.y + r; ++y)
        {
          for (int x = c.x - r; x <= c.x + r; ++x)
          {
            const bool shell =
              std::abs(z - c.z) == r || std::abs(y - c.y) == r || std::abs(x - c.x) == r;
            if (!shell || x < 0 || y < 0 || z < 0 || x >= this->Dims[0] || y >= this->Dims[1] ||
              z >= this->Dims[2])
            {
              continue;
            }
            for (int t : this->Cells[this->Flat(x, y, z)])
            {
              const glm::ivec3& tri = this->Triangles[t];
              best = std::min(best,
                PointTriangleDistance(
                  p, this->Points[tri[0]], this->Points[tri[1]], this->Points[tri[2]]));
            }
          }
        }
      }
      // Cells of the next rings are at least r cell sizes away.
      if (best <= r * this->MinSize)
      {
        break;
      }
    }
    return best;
  }

private:
  glm::ivec3 CellOf(const glm::dvec3& p) const
  {
    glm::ivec3 c;
    for (int a = 0; a < 3; ++a)
    {
      c[a] = std::clamp(
        static_cast<int>(std::floor((p[a] - this->Lo[a]) / this->Size[a])), 0, this->Dims[a] - 1);
    }
    return c;
  }
  size_t Flat(int x, int y, int z) const
  {
    return (static_cast<size_t>(z) * this->Dims[1] + y) * this->Dims[0] + x;
  }

  const std::vector<glm::dvec3>& Points;
  const std::vector<glm::ivec3>& Triangles;
  glm::dvec3 Lo;
  glm::dvec3 Size;
  double MinSize = 1.0;
  glm::ivec3 Dims;
  std::vector<std::vector<int>> Cells;
};

// Max (and sum) of f(k) over [0, n), in blocks fixed by n alone (same result however the
// parallel-for splits the range).
template <typename F>
void ParallelMax(
  size_t n, const F& f, double& maximum, double& sum, const ProgressCallback& progress)
{
  const size_t block = 1024;
  const size_t blocks = (n + block - 1) / block;
  std::vector<double> maxima(blocks, 0.0), sums(blocks, 0.0);
  const size_t chunks = std::max<size_t>(1, std::min<size_t>(blocks, 16));
  for (size_t c = 0; c < chunks; ++c)
  {
    ParallelFor(blocks * c / chunks, blocks * (c + 1) / chunks, 1,
      [&](size_t b0, size_t b1)
      {
        for (size_t b = b0; b < b1; ++b)
        {
          for (size_t k = b * block; k < std::min(n, (b + 1) * block); ++k)
          {
            const double d = f(k);
            maxima[b] = std::max(maxima[b], d);
            sums[b] += d;
          }
        }
      });
    if (!ReportProgress(progress, static_cast<double>(c + 1) / chunks))
    {
      break;
    }
  }
  maximum = 0.0;
  sum = 0.0;
  for (size_t b = 0; b < blocks; ++b)
  {
    maximum = std::max(maximum, maxima[b]);
    sum += sums[b];
  }
}
} // namespace

//------------------------------------------------------------------------------
HausdorffDistance MeasureHausdorff(const GeometryImage& image, const GeometryImageMesh& mesh,
  int samplesPerEdge, const ProgressCallback& progress)
{
  HausdorffDistance result;
  GeometryImageMesh full;
  try
  {
    if (!mesh.Triangles.empty())
    {
      full = SampleRegular(image, 1);
    }
  }
  catch (const GeometryImageMeshError&)
  {
    // No reference mesh: the distance is infinite (below).
  }
  if (full.Triangles.empty())
  {
    result.ImageToMesh = result.MeshToImage = result.Hausdorff =
      std::numeric_limits<double>::infinity();
    return result;
  }
  // Image to mesh: every non-empty pixel.
  std::vector<size_t> pixels;
  for (size_t k = 0; k < image.Positions.size(); ++k)
  {
    if (image.Valid(static_cast<int>(k % image.Width), static_cast<int>(k / image.Width)))
    {
      pixels.push_back(k);
    }
  }
  const TriangleGrid coarse(mesh.Points, mesh.Triangles);
  double sum = 0.0;
  ParallelMax(
    pixels.size(), [&](size_t k) { return coarse.Distance(image.Positions[pixels[k]]); },
    result.ImageToMesh, sum, SubProgress(progress, 0.0, 0.5));
  result.MeanImageToMesh = pixels.empty() ? 0.0 : sum / pixels.size();

  // Mesh to image: a barycentric grid on every triangle against the stride-1 mesh.
  const int n = std::max(1, samplesPerEdge);
  std::vector<glm::dvec3> bary;
  for (int a = 0; a <= n; ++a)
  {
    for (int b = 0; a + b <= n; ++b)
    {
      bary.emplace_back(
        static_cast<double>(a) / n, static_cast<double>(b) / n, static_cast<double>(n - a - b) / n);
    }
  }
  const TriangleGrid fine(full.Points, full.Triangles);
  double unused = 0.0;
  ParallelMax(
    mesh.Triangles.size() * bary.size(),
    [&](size_t k)
    {
      const glm::ivec3& t = mesh.Triangles[k / bary.size()];
      const glm::dvec3& w = bary[k % bary.size()];
      return fine.Distance(
        w.x * mesh.Points[t[0]] + w.y * mesh.Points[t[1]] + w.z * mesh.Points[t[2]]);
    },
    result.MeshToImage, unused, SubProgress(progress, 0.5, 1.0));
  result.Hausdorff = std::max(result.ImageToMesh, result.MeshToImage);
  return result;
}

} // namespace mesolight
