// SPDX-License-Identifier: BSD-3-Clause
#include "SrtmHeightFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <vector>

namespace mesolight
{

bool IsSrtmHeightFileName(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".hgt";
}

std::optional<double> SrtmTileSouthLatitude(const std::string& path)
{
  const std::string name = std::filesystem::path(path).stem().string();
  // [NS]dd[EW]ddd, as the tiles are named.
  if (name.size() < 7 || !(name[0] == 'N' || name[0] == 'S' || name[0] == 'n' || name[0] == 's') ||
    !std::isdigit(static_cast<unsigned char>(name[1])) ||
    !std::isdigit(static_cast<unsigned char>(name[2])) ||
    !(name[3] == 'E' || name[3] == 'W' || name[3] == 'e' || name[3] == 'w'))
  {
    return std::nullopt;
  }
  const int degrees = (name[1] - '0') * 10 + (name[2] - '0');
  if (degrees > 89)
  {
    return std::nullopt;
  }
  return (name[0] == 'S' || name[0] == 's') ? -degrees : degrees;
}

int SrtmTileSide(std::uint64_t bytes)
{
  if (bytes % 2 != 0 || bytes < 8 || bytes > 2ULL * 46340 * 46340)
  {
    return 0; // a side above 46340 would not fit a 32-bit texel count
  }
  const std::uint64_t samples = bytes / 2;
  auto side = static_cast<std::uint64_t>(std::llround(std::sqrt(static_cast<double>(samples))));
  return side * side == samples ? static_cast<int>(side) : 0;
}

bool ReadSrtmTile(const std::string& path, int side, std::int16_t* heights, std::string& error,
  const std::function<bool(float)>& progress)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in.is_open())
  {
    error = "the file cannot be opened";
    return false;
  }
  const std::uint64_t expected = 2ULL * static_cast<std::uint64_t>(side) * side;
  if (side < 2 || static_cast<std::uint64_t>(in.tellg()) != expected)
  {
    error = "the file changed while it was read";
    return false;
  }
  in.seekg(0);
  std::vector<unsigned char> row(static_cast<size_t>(side) * 2);
  for (int r = 0; r < side; ++r)
  {
    if (!in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size())))
    {
      error = "the file is truncated";
      return false;
    }
    // The file's first row is the northernmost, VTK's first the bottom one.
    std::int16_t* out = heights + static_cast<size_t>(side - 1 - r) * side;
    for (int i = 0; i < side; ++i)
    {
      const auto big = static_cast<std::uint16_t>((row[2 * i] << 8) | row[2 * i + 1]);
      out[i] = static_cast<std::int16_t>(big);
    }
    if (progress && (r % 64 == 63 || r == side - 1) && progress(static_cast<float>(r + 1) / side))
    {
      return false;
    }
  }
  return true;
}

} // namespace mesolight
