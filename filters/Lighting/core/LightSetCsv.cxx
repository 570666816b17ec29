// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetCsv.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace mesolight
{
namespace
{
std::string Trim(const std::string& s)
{
  const char* space = " \t\r\n";
  const size_t first = s.find_first_not_of(space);
  if (first == std::string::npos)
  {
    return std::string();
  }
  const size_t last = s.find_last_not_of(space);
  return s.substr(first, last - first + 1);
}

// Text from the file as it may be shown on a terminal: bytes that are not printable ASCII
// (a binary file, a stray control character) as \xNN, so a message never echoes them raw.
std::string Printable(const std::string& text, std::size_t limit)
{
  std::string shown;
  for (std::size_t i = 0; i < text.size() && i < limit; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f)
    {
      shown.push_back(static_cast<char>(c));
    }
    else
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02X", static_cast<unsigned>(c));
      shown += escaped;
    }
  }
  if (text.size() > limit)
  {
    shown += "...";
  }
  return shown;
}

// The whole field as a finite double, or false.
bool ParseNumber(const std::string& field, double& value)
{
  const std::string text = Trim(field);
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}
} // namespace

std::vector<double> ParseLightSetCsv(std::istream& in, const std::string& name)
{
  std::vector<double> values;
  std::string line;
  // getline with a bound: a file with no line ends (a device, a binary file) must not be read
  // into memory whole.
  const auto readLine = [&in, &line]() -> bool
  {
    line.clear();
    char c = 0;
    bool any = false;
    while (in.get(c))
    {
      any = true;
      if (c == '\n')
      {
        return true;
      }
      if (line.size() >= MaximumLightSetCsvLine)
      {
        line.push_back(c); // one more than the limit: refused below
        return true;
      }
      line.push_back(c);
    }
    return any;
  };
  if (!readLine() || Trim(line).empty())
  {
    throw LightSetCsvError(
      name + " is empty (expected the header \"u,v,x,y,z,r,g,b\" and one row per light)");
  }
  // A UTF-8 byte order mark (spreadsheets write one) is not part of the header.
  static const std::string byteOrderMark = "\xEF\xBB\xBF";
  if (line.compare(0, byteOrderMark.size(), byteOrderMark) == 0)
  {
    line.erase(0, byteOrderMark.size());
  }
  if (Trim(line) != "u,v,x,y,z,r,g,b")
  {
    throw LightSetCsvError(name + ", line 1: the header is \"" + Printable(Trim(line), 80) +
      "\", expected \"u,v,x,y,z,r,g,b\" (a light set written by mesolight lights)");
  }
  static const char* names[8] = { "u", "v", "x", "y", "z", "r", "g", "b" };
  long lineNumber = 1;
  double total[3] = { 0.0, 0.0, 0.0 };
  while (readLine())
  {
    ++lineNumber;
    const std::string where = name + ", line " + std::to_string(lineNumber) + ": ";
    if (line.size() > MaximumLightSetCsvLine)
    {
      throw LightSetCsvError(where + "longer than " + std::to_string(MaximumLightSetCsvLine) +
        " characters (not a lights CSV?)");
    }
    if (Trim(line).empty())
    {
      continue;
    }
    std::vector<std::string> fields;
    std::stringstream row(line);
    std::string field;
    while (std::getline(row, field, ','))
    {
      fields.push_back(field);
    }
    if (!line.empty() && line.back() == ',')
    {
      fields.emplace_back();
    }
    if (fields.size() != 8)
    {
      throw LightSetCsvError(
        where + std::to_string(fields.size()) + " fields, expected 8 (u,v,x,y,z,r,g,b)");
    }
    double v[8];
    for (int k = 0; k < 8; ++k)
    {
      if (!ParseNumber(fields[k], v[k]))
      {
        throw LightSetCsvError(where + "the " + names[k] + " field \"" +
          Printable(Trim(fields[k]), 40) + "\" is not a finite number");
      }
      // The lights are single precision from here on (point data, the light texture, the
      // shaders): a larger value becomes infinity there and the whole relief goes black.
      if (std::abs(v[k]) > static_cast<double>(std::numeric_limits<float>::max()))
      {
        throw LightSetCsvError(where + "the " + names[k] + " field \"" +
          Printable(Trim(fields[k]), 40) +
          "\" is outside single precision (magnitude at most 3.4e38)");
      }
    }
    const double length = std::sqrt(v[2] * v[2] + v[3] * v[3] + v[4] * v[4]);
    if (std::abs(length - 1.0) > 1e-3)
    {
      throw LightSetCsvError(where + "the direction (x, y, z) has length " +
        std::to_string(length) + ", expected a unit vector");
    }
    if (v[5] < 0.0 || v[6] < 0.0 || v[7] < 0.0)
    {
      throw LightSetCsvError(where + "negative irradiance (r, g, b)");
    }
    // The renderer sums the lights in single precision: the total of each channel must stay
    // finite too.
    for (int c = 5; c < 8; ++c)
    {
      total[c - 5] += v[c];
      if (total[c - 5] > static_cast<double>(std::numeric_limits<float>::max()))
      {
        throw LightSetCsvError(where + "the total " + names[c] +
          " irradiance of the lights so far exceeds single precision (3.4e38)");
      }
    }
    values.insert(values.end(), v, v + 8);
  }
  if (in.bad())
  {
    throw LightSetCsvError("error while reading " + name);
  }
  if (values.empty())
  {
    throw LightSetCsvError(name + " has a header but no lights");
  }
  return values;
}

} // namespace mesolight
