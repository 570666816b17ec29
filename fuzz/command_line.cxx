// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the `mesolight` command-line parser (application/CommandLine): Parse and every
// typed accessor (GetInt, GetDouble, GetIntList, GetDoubleList, GetSize, GetDoubleVector,
// GetStringList) on options declared as the commands declare theirs.
//
// Input: the arguments, separated by NUL bytes. Besides crashes and sanitizer reports, an
// accessor that says yes must give what it promises (numbers finite and in range, whole where
// asked, the item count asked); anything else aborts.
#include "CommandLine.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace
{
void Check(bool ok)
{
  if (!ok)
  {
    std::abort();
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace mesolight;
  std::vector<std::string> args(1);
  for (std::size_t q = 0; q < size; ++q)
  {
    if (data[q] == 0)
    {
      args.emplace_back();
    }
    else
    {
      args.back() += static_cast<char>(data[q]);
    }
  }
  CommandLine cl("mesolight fuzz", "mesolight fuzz [options] FILE...");
  cl.AddValue("--count", "N", "a whole number", "128");
  cl.AddValue("--depth-scale", "K", "a number", "0.04");
  cl.AddValue("--sizes", "N,...", "a list of whole numbers", "512,1024");
  cl.AddValue("--angles", "A,...", "a list of numbers");
  cl.AddValue("--resolution", "WxH", "a size", "640x480");
  cl.AddValue("--camera", "X,Y,Z,FX,FY,FZ", "six numbers");
  cl.AddValue("--maps", "NAME,...", "a list of names");
  cl.AddFlag("--offscreen", "a flag");
  std::string error;
  if (!cl.Parse(args, error))
  {
    Check(!error.empty());
    return 0;
  }
  std::ostringstream help;
  cl.PrintHelp(help);
  for (const char* name :
    { "--count", "--depth-scale", "--sizes", "--angles", "--resolution", "--camera", "--maps" })
  {
    (void)cl.Has(name);
    int whole = 7;
    if (cl.GetInt(name, -1000, 1 << 26, whole, error))
    {
      Check(whole >= -1000 && whole <= (1 << 26));
    }
    double number = 0.5;
    if (cl.GetDouble(name, -1e6, 1e6, number, error))
    {
      Check(std::isfinite(number) && number >= -1e6 && number <= 1e6);
    }
    std::vector<int> wholes;
    if (cl.GetIntList(name, 1, 65536, wholes, error))
    {
      Check(!wholes.empty());
      for (const int v : wholes)
      {
        Check(v >= 1 && v <= 65536);
      }
    }
    std::vector<double> numbers;
    if (cl.GetDoubleList(name, 0.0, 90.0, numbers, error))
    {
      Check(!numbers.empty());
      for (const double v : numbers)
      {
        Check(v >= 0.0 && v <= 90.0);
      }
    }
    int width = 0, height = 0;
    if (cl.GetSize(name, 1, 16384, width, height, error))
    {
      Check(width >= 1 && width <= 16384 && height >= 1 && height <= 16384);
    }
    double camera[6];
    if (cl.GetDoubleVector(name, 6, camera))
    {
      for (const double v : camera)
      {
        Check(std::isfinite(v));
      }
    }
    for (const std::string& item : cl.GetStringList(name))
    {
      Check(!item.empty() && item.find(',') == std::string::npos);
    }
  }
  return 0;
}
