// SPDX-License-Identifier: BSD-3-Clause
// The movable object's placement ("tx,ty,tz[,rx,ry,rz[,s]]", --object-transform) and its path
// file (--path of `mesolight vlf view`): plain C++ parsing, no VTK, so the fuzz target
// (fuzz/object_path.cxx) builds without it.
#ifndef mesolight_ObjectPath_h
#define mesolight_ObjectPath_h

#include <iosfwd>
#include <string>
#include <vector>

namespace mesolight
{

struct ObjectPlacement
{
  double Position[3] = { 0.0, 0.0, 0.0 };
  double Orientation[3] = { 0.0, 0.0, 0.0 };
  double Scale = 1.0;
};

// "tx,ty,tz[,rx,ry,rz[,s]]" over the defaults in `placement`; "" or why not.
std::string ParsePlacement(const std::string& text, ObjectPlacement& placement);

// --path FILE: one placement per line ("tx,ty,tz[,rx,ry,rz[,s]]"; '#' comments and a header
// line of names are skipped); rows without a scale keep `base`'s.
bool ReadPath(const std::string& file, const ObjectPlacement& base,
  std::vector<ObjectPlacement>& path, std::string& error);
// The same from a stream; `name` prefixes messages.
bool ReadPath(std::istream& in, const std::string& name, const ObjectPlacement& base,
  std::vector<ObjectPlacement>& path, std::string& error);

} // namespace mesolight

#endif
