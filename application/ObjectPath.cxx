// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectPath.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace mesolight
{

std::string ParsePlacement(const std::string& text, ObjectPlacement& placement)
{
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(v))
    {
      return "'" + item + "' is not a finite number";
    }
    values.push_back(v);
  }
  if (values.size() != 3 && values.size() != 6 && values.size() != 7)
  {
    return "give tx,ty,tz or tx,ty,tz,rx,ry,rz or tx,ty,tz,rx,ry,rz,s (" +
      std::to_string(values.size()) + " numbers given)";
  }
  std::copy(values.begin(), values.begin() + 3, placement.Position);
  if (values.size() >= 6)
  {
    std::copy(values.begin() + 3, values.begin() + 6, placement.Orientation);
  }
  if (values.size() == 7)
  {
    if (!(values[6] > 0.0))
    {
      return "the scale must be positive";
    }
    placement.Scale = values[6];
  }
  return {};
}

bool ReadPath(std::istream& in, const std::string& name, const ObjectPlacement& base,
  std::vector<ObjectPlacement>& path, std::string& error)
{
  std::string line;
  int number = 0;
  while (std::getline(in, line))
  {
    ++number;
    line.erase(0, line.find_first_not_of(" \t\r"));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (line.empty() || line[0] == '#' || (number == 1 && std::isalpha(line[0])))
    {
      continue;
    }
    ObjectPlacement p = base;
    const std::string why = ParsePlacement(line, p);
    if (!why.empty())
    {
      error = name + ":" + std::to_string(number) + ": " + why;
      return false;
    }
    path.push_back(p);
  }
  if (path.empty())
  {
    error = "'" + name + "' holds no placement";
    return false;
  }
  return true;
}

bool ReadPath(const std::string& file, const ObjectPlacement& base,
  std::vector<ObjectPlacement>& path, std::string& error)
{
  std::ifstream in(file);
  if (!in)
  {
    error = "cannot read '" + file + "'";
    return false;
  }
  return ReadPath(in, file, base, path, error);
}

} // namespace mesolight
