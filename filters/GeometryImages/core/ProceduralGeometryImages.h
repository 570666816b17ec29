// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ProceduralGeometryImages.h
 * @brief Analytic surfaces written as geometry images (for tests, benchmarks and demos), and the
 *        dense displaced mesh of a geometry image and a depth map (the reference a relief on the
 *        coarse mesh is measured against).
 *
 * Every surface S(u, v), u, v in [0, 1], is framed like Mesolight's relief wall: it spans about
 * [0, 1] x [0, 1] in x, y, faces +z with its highest point at z = 0, and |dS/du| = |dS/dv| = 1
 * along its centre lines, so a relief texture's DepthScale means the same as on the wall. Pixel
 * (i, j) of a W x H image is S((i + 0.5) / W, (j + 0.5) / H) (texel centres).
 */
#ifndef mesolight_ProceduralGeometryImages_h
#define mesolight_ProceduralGeometryImages_h

#include "GeometryImageMesh.h"

#include <string>
#include <vector>

namespace mesolight
{

enum class GeometrySurface
{
  Plane,       // the unit square
  Cylinder,    // a 120-degree patch of a cylinder about the y axis
  SpherePatch, // 90 x 90 degrees of a sphere
  Wave,        // a plane rippled by two periods of a cosine along x
  Bump         // a plane with one Gaussian bump: flat almost everywhere, bent in the middle
};

/** "plane", "cylinder", "sphere", "wave", "bump"; std::invalid_argument naming the accepted
 *  names for any other. */
MESOLIGHTGEOMETRYIMAGES_EXPORT GeometrySurface GeometrySurfaceFromName(const std::string& name);
MESOLIGHTGEOMETRYIMAGES_EXPORT const char* GeometrySurfaceName(GeometrySurface surface);
/** The names GeometrySurfaceFromName accepts, separated by '|'. */
MESOLIGHTGEOMETRYIMAGES_EXPORT const char* GeometrySurfaceNames();

/** S(u, v) and, when normal is given, its unit outward normal (dS/du x dS/dv). */
MESOLIGHTGEOMETRYIMAGES_EXPORT glm::dvec3 SurfacePoint(
  GeometrySurface surface, double u, double v, glm::dvec3* normal = nullptr);

/** The surface as a W x H geometry image with its analytic normals. */
MESOLIGHTGEOMETRYIMAGES_EXPORT GeometryImage MakeGeometryImage(
  GeometrySurface surface, int width, int height);

/**
 * The dense displaced surface: every pixel moved along -N by depth * depthScale * |dP/du|, the
 * world depth vtkReliefMapper gives depth 1 at that point (DepthScale is the world depth of
 * depth 1 over the world length of one u unit; |dP/du| by central differences at full
 * resolution). depth holds W x H values in [0, 1] in the image's pixel order (a depth map of the
 * same size: texel for texel). N: the image's normals, else the geometry's. Empty pixels stay
 * empty. Its stride-1 mesh (SampleRegular) is the reference mesh. Throws GeometryImageMeshError
 * for an image smaller than 2 x 2 or a depth map of another size.
 */
MESOLIGHTGEOMETRYIMAGES_EXPORT GeometryImage DisplaceGeometryImage(
  const GeometryImage& surface, const std::vector<float>& depth, double depthScale);

} // namespace mesolight

#endif
