// SPDX-License-Identifier: BSD-3-Clause
// Image commands of the `mesolight` tool: `bake` (relief texture), `cone` (cone-packed relief
// texture) and `probe` (light probe -> lat-long environment).
#ifndef mesolight_ImageCommands_h
#define mesolight_ImageCommands_h

#include <string>
#include <vector>

class vtkImageData;

namespace mesolight
{

/** Tells the user, on stdout, when the depth image `file` names its own no-data value (a GeoTIFF's
 *  GDAL_NODATA) and `applied` (no --no-data given): which value, and how to keep it as data. */
void ReportFileNoDataValue(const std::string& file, bool applied);

/// Prints, for a georeferenced elevation map (a relief texture that carries
/// "MesolightTrueDepthScale"), its true vertical scale and how exaggerated it is drawn.
void ReportTrueDepthScale(const std::string& file, vtkImageData* relief);

/** mesolight bake DEPTH_IMAGE --out RELIEF_IMAGE [options]; `args` excludes "bake". */
int RunBakeCommand(const std::vector<std::string>& args);

/** mesolight cone DEPTH_IMAGE --out FILE.exr [options]; `args` excludes "cone". */
int RunConeCommand(const std::vector<std::string>& args);

/** mesolight probe PROBE_IMAGE --out FILE.exr [options]; `args` excludes "probe". */
int RunProbeCommand(const std::vector<std::string>& args);

} // namespace mesolight

#endif
