// SPDX-License-Identifier: BSD-3-Clause
// The lights CSV that `mesolight lights` writes (vtkMedianCutLights::WriteCsv) read back: the
// header "u,v,x,y,z,r,g,b", then one light per row: map coordinates, the unit direction toward
// the light and its RGB irradiance (sum of L dOmega). Plain C++, so it fuzzes without VTK
// (fuzz/lights_csv.cxx).
#ifndef mesolight_LightSetCsv_h
#define mesolight_LightSetCsv_h

#include <istream>
#include <string>
#include <vector>

namespace mesolight
{

/** Rows longer than this are refused (a file that is not a CSV, or no line ends). */
constexpr std::size_t MaximumLightSetCsvLine = 4096;

/**
 * Parses the CSV from `in` (`name` only names it in messages): 8 finite numbers per light
 * appended to `values`, each within single precision (the renderer's), each direction of unit
 * length (within 1e-3), no negative irradiance, each channel's total irradiance within single
 * precision, at least one light. A UTF-8 byte order mark before the header is skipped. False
 * with a one-line message (file, line and field named; file bytes that are not printable ASCII
 * shown as \xNN) on any error.
 */
bool ParseLightSetCsv(
  std::istream& in, const std::string& name, std::vector<double>& values, std::string& error);

} // namespace mesolight

#endif
