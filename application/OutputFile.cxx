// SPDX-License-Identifier: BSD-3-Clause
#include "OutputFile.h"

#include "CommandLine.h"

#include <algorithm>
#include <cctype>

#include <sys/stat.h>
#include <unistd.h>

namespace mesolight
{

bool SameFile(const std::string& a, const std::string& b)
{
  struct stat sa, sb;
  if (stat(a.c_str(), &sa) != 0 || stat(b.c_str(), &sb) != 0)
  {
    return false;
  }
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::string CheckOutputFile(const std::string& out, const std::vector<std::string>& inputs)
{
  if (out.empty())
  {
    return "the output file name is empty";
  }
  for (const std::string& in : inputs)
  {
    if (!in.empty() && (in == out || SameFile(in, out)))
    {
      return "'" + out + "' would overwrite '" + in + "', which this command reads or writes";
    }
  }
  // A dangling symbolic link would be written through to its target: refuse to guess.
  struct stat link;
  if (lstat(out.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
  {
    struct stat target;
    if (stat(out.c_str(), &target) != 0)
    {
      return "'" + out + "' is a dangling symbolic link";
    }
  }
  struct stat existing;
  if (stat(out.c_str(), &existing) == 0)
  {
    if (!S_ISREG(existing.st_mode))
    {
      return "'" + out + "' exists and is not a regular file";
    }
    if (access(out.c_str(), W_OK) != 0)
    {
      return "'" + out + "' is not writable";
    }
    return "";
  }
  const size_t slash = out.find_last_of('/');
  const std::string directory =
    slash == std::string::npos ? "." : (slash == 0 ? "/" : out.substr(0, slash));
  struct stat dir;
  if (stat(directory.c_str(), &dir) != 0 || !S_ISDIR(dir.st_mode))
  {
    return "the directory '" + directory + "' of '" + out + "' does not exist";
  }
  if (access(directory.c_str(), W_OK | X_OK) != 0)
  {
    return "the directory '" + directory + "' of '" + out + "' is not writable";
  }
  return "";
}

std::string CheckOutputOptions(
  const CommandLine& cl, const std::vector<std::string>& names, std::vector<std::string> inputs)
{
  for (const std::string& name : names)
  {
    if (!cl.Has(name))
    {
      continue;
    }
    std::vector<std::string> others = inputs; // what it may not overwrite: inputs, other outputs
    for (const std::string& other : names)
    {
      if (other != name && cl.Has(other))
      {
        others.push_back(cl.Get(other));
      }
    }
    const std::string problem = CheckOutputFile(cl.Get(name), others);
    if (!problem.empty())
    {
      return name + ": " + problem;
    }
  }
  return "";
}

bool HasExtension(const std::string& file, const std::string& extension)
{
  if (file.size() <= extension.size())
  {
    return false;
  }
  std::string tail = file.substr(file.size() - extension.size());
  std::transform(tail.begin(), tail.end(), tail.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return tail == extension;
}

std::string CheckOutputExtension(const CommandLine& cl, const std::vector<std::string>& names,
  const std::vector<std::string>& extensions, const std::string& advice)
{
  for (const std::string& name : names)
  {
    if (!cl.Has(name))
    {
      continue;
    }
    const std::string file = cl.Get(name);
    const bool known = std::any_of(extensions.begin(), extensions.end(),
      [&](const std::string& e) { return HasExtension(file, e); });
    if (!known)
    {
      std::string list;
      for (const std::string& e : extensions)
      {
        list += (list.empty() ? "" : (&e == &extensions.back() ? " or " : ", ")) + e;
      }
      return name + ": '" + cl.Get(name) + "' does not end in " + list + ": " + advice;
    }
  }
  return "";
}

std::string CheckImageOutputNames(const CommandLine& cl)
{
  const std::string png = CheckOutputExtension(cl, { "--out" }, { ".png" },
    "the image is written as a PNG (--exr FILE.exr for the linear radiance)");
  return !png.empty() ? png
                      : CheckOutputExtension(cl, { "--exr", "--relief-mask" }, { ".exr" },
                          "the linear images are written as OpenEXR");
}

} // namespace mesolight
