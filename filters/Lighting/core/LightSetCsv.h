// SPDX-License-Identifier: BSD-3-Clause
// The lights CSV that `mesolight lights` writes (vtkMedianCutLights::WriteCsv) read back: the
// header "u,v,x,y,z,r,g,b", then one light per row: map coordinates, the unit direction toward
// the light and its RGB irradiance (sum of L dOmega). Plain C++, so it fuzzes without VTK
// (fuzz/lights_csv.cxx).
#ifndef mesolight_LightSetCsv_h
#define mesolight_LightSetCsv_h

#include <istream>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{

/** Rows longer than this are refused (a file that is not a CSV, or no line ends). */
constexpr std::size_t MaximumLightSetCsvLine = 4096;

/** A light-set CSV that cannot be read; what() is one sentence for the user. */
class LightSetCsvError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * Parses the CSV from `in` (`name` only names it in messages) and returns 8 finite numbers per
 * light, each within single precision (the renderer's), each direction of unit length (within
 * 1e-3), no negative irradiance, each channel's total irradiance within single precision, at
 * least one light. A UTF-8 byte order mark before the header is skipped. Throws
 * LightSetCsvError with a one-line message (file, line and field named; file bytes that are not
 * printable ASCII shown as \xNN) on any error.
 */
std::vector<double> ParseLightSetCsv(std::istream& in, const std::string& name);

} // namespace mesolight

#endif
