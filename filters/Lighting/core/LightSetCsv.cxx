// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetCsv.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
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

bool ParseLightSetCsv(
  std::istream& in, const std::string& name, std::vector<double>& values, std::string& error)
{
  values.clear();
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
    error = name + " is empty (expected the header \"u,v,x,y,z,r,g,b\" and one row per light)";
    return false;
  }
  if (Trim(line) != "u,v,x,y,z,r,g,b")
  {
    error = name + ", line 1: the header is \"" + Trim(line).substr(0, 80) +
      "\", expected \"u,v,x,y,z,r,g,b\" (a light set written by mesolight lights)";
    return false;
  }
  static const char* names[8] = { "u", "v", "x", "y", "z", "r", "g", "b" };
  long lineNumber = 1;
  while (readLine())
  {
    ++lineNumber;
    const std::string where = name + ", line " + std::to_string(lineNumber) + ": ";
    if (line.size() > MaximumLightSetCsvLine)
    {
      error = where + "longer than " + std::to_string(MaximumLightSetCsvLine) +
        " characters (not a lights CSV?)";
      return false;
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
      error = where + std::to_string(fields.size()) + " fields, expected 8 (u,v,x,y,z,r,g,b)";
      return false;
    }
    double v[8];
    for (int k = 0; k < 8; ++k)
    {
      if (!ParseNumber(fields[k], v[k]))
      {
        error = where + "the " + names[k] + " field \"" + Trim(fields[k]).substr(0, 40) +
          "\" is not a finite number";
        return false;
      }
    }
    const double length = std::sqrt(v[2] * v[2] + v[3] * v[3] + v[4] * v[4]);
    if (std::abs(length - 1.0) > 1e-3)
    {
      error = where + "the direction (x, y, z) has length " + std::to_string(length) +
        ", expected a unit vector";
      return false;
    }
    if (v[5] < 0.0 || v[6] < 0.0 || v[7] < 0.0)
    {
      error = where + "negative irradiance (r, g, b)";
      return false;
    }
    values.insert(values.end(), v, v + 8);
  }
  if (in.bad())
  {
    error = "error while reading " + name;
    return false;
  }
  if (values.empty())
  {
    error = name + " has a header but no lights";
    return false;
  }
  return true;
}

} // namespace mesolight
