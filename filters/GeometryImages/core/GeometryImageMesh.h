// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GeometryImageMesh.h
 * @brief Geometry images (Gu, Gortler and Hoppe, "Geometry images") as the coarse macro mesh of a
 *        relief surface (Méndez Fernández, "Visualizing 3D models with fine-grain surface depth",
 *        §6): regular sampling every k-th pixel, adaptive sampling to a world-unit tolerance, and
 *        the Hausdorff distance of a mesh to the full-resolution geometry image.
 *
 * Conventions (the same as vtkHeightFieldMeshFilter's, so colour, normal and relief images in the
 * geometry image's parameterization map texel for texel):
 *  - pixel (i, j) is Positions[j * Width + i], row 0 first (VTK's bottom row);
 *  - pixel (i, j) is the surface point at texture coordinate ((i + 0.5) / W, (j + 0.5) / H),
 *    the centre of texel (i, j) of any W x H image in the same parameterization;
 *  - a pixel with a non-finite coordinate (NaN) is empty: no triangle touches it.
 * Plain C++17 with GLM; no VTK types.
 */
#ifndef mesolight_GeometryImageMesh_h
#define mesolight_GeometryImageMesh_h

#include "MesolightGeometryImagesModule.h" // for the export macro
#include "Progress.h"

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{

/** A W x H image of 3D positions, optionally with a normal per pixel. */
struct MESOLIGHTGEOMETRYIMAGES_EXPORT GeometryImage
{
  int Width = 0;
  int Height = 0;
  std::vector<glm::dvec3> Positions; // W * H; NaN marks an empty pixel
  std::vector<glm::dvec3> Normals;   // empty, or W * H (need not be unit length)

  const glm::dvec3& At(int i, int j) const { return this->Positions[Index(i, j)]; }
  size_t Index(int i, int j) const { return static_cast<size_t>(j) * this->Width + i; }
  bool Valid(int i, int j) const;
  /** Number of pixels with a finite position. */
  size_t CountValid() const;
};

/** The texture coordinate of pixel index i of n pixels (texel centre). */
inline double TexelCentre(int i, int n)
{
  return (i + 0.5) / n;
}

/** A triangle mesh sampled from a geometry image. */
struct MESOLIGHTGEOMETRYIMAGES_EXPORT GeometryImageMesh
{
  std::vector<glm::dvec3> Points;
  std::vector<glm::dvec3> Normals; // unit, one per point
  std::vector<glm::dvec2> TCoords; // texel centres of Pixels
  std::vector<glm::ivec2> Pixels;  // the pixel each point was sampled from
  std::vector<glm::ivec3> Triangles;
  size_t SkippedQuads = 0; // quads (regular) or cells (adaptive) dropped for empty pixels
};

/** A geometry image that cannot be meshed; what() is one sentence for the user. */
class MESOLIGHTGEOMETRYIMAGES_EXPORT GeometryImageMeshError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * Samples every stride-th pixel in each direction, the last row and column always included (so
 * the whole image is covered), two triangles per quad split along the shorter diagonal,
 * counter-clockwise in (i, j). A quad is dropped when any pixel of its block (corners and
 * inside) is empty, so that no triangle bridges a hole. Normals: the normal image at the sampled
 * pixel when present, else the geometry's (central differences at full resolution). Throws
 * GeometryImageMeshError for bad input (empty image, stride < 1 or larger than the image, sizes
 * that disagree, no finite pixel). When progress asks to stop, returns the mesh built so far.
 */
MESOLIGHTGEOMETRYIMAGES_EXPORT GeometryImageMesh SampleRegular(
  const GeometryImage& image, int stride, const ProgressCallback& progress = {});

/**
 * Adaptive sampling: a quadtree over the pixel grid, from square cells of maxCell pixels
 * (a power of two; 0 chooses the largest that fits the image), split while a full-resolution
 * pixel of the cell lies farther than tolerance (world units) from the cell's triangles or any
 * pixel of the cell is empty. Cells adjacent to finer ones are fanned from their centre pixel
 * through the finer cells' corners on their sides (thin cells are zipped between their long
 * sides), so the mesh has no T-junctions and no cracks; a cell's final triangulation is checked
 * against the tolerance again and split further when it misses. Every pixel is then within
 * tolerance of its own cell's triangles, an upper bound of its distance to the mesh. Throws
 * GeometryImageMeshError as SampleRegular does, and for a tolerance that is not positive.
 */
MESOLIGHTGEOMETRYIMAGES_EXPORT GeometryImageMesh SampleAdaptive(const GeometryImage& image,
  double tolerance, const ProgressCallback& progress = {}, int maxCell = 0);

/** Per-pixel unit normals of the geometry (central differences, one-sided at borders and next
 *  to empty pixels; oriented as dP/di x dP/dj). Zero where no neighbour is usable. */
MESOLIGHTGEOMETRYIMAGES_EXPORT std::vector<glm::dvec3> GeometryNormals(const GeometryImage& image);

/**
 * Distances between a mesh and the full-resolution geometry image (its stride-1 mesh).
 * ImageToMesh: max over every non-empty pixel of its distance to the mesh (the main term: the
 * full-resolution surface is its pixels). MeshToImage: max over sample points of every mesh
 * triangle (vertices, edge midpoints and a barycentric grid of `samplesPerEdge`) of their
 * distance to the stride-1 mesh. Hausdorff = max of both. Exact point-triangle distances,
 * nearest triangles found through a uniform grid.
 */
struct HausdorffDistance
{
  double ImageToMesh = 0.0;
  double MeshToImage = 0.0;
  double MeanImageToMesh = 0.0;
  double Hausdorff = 0.0;
};
MESOLIGHTGEOMETRYIMAGES_EXPORT HausdorffDistance MeasureHausdorff(const GeometryImage& image,
  const GeometryImageMesh& mesh, int samplesPerEdge = 4, const ProgressCallback& progress = {});

/** Distance from p to the triangle (a, b, c) (Ericson, "Real-Time Collision Detection" 5.1.5). */
MESOLIGHTGEOMETRYIMAGES_EXPORT double PointTriangleDistance(
  const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

} // namespace mesolight

#endif
