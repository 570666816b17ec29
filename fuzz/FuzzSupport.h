// SPDX-License-Identifier: BSD-3-Clause
// What the fuzz targets share: a private scratch directory for the files a parser reads by name
// (an MTL beside an OBJ, a snapshot), removed when the process ends.
#ifndef mesolight_FuzzSupport_h
#define mesolight_FuzzSupport_h

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace mesolight
{
namespace fuzz
{

// "<tmp>/mesolight-fuzz-<pid>", created on first use and removed at exit (a crash leaves it).
inline const std::string& ScratchDirectory()
{
  struct Scratch
  {
    std::string Path;
    Scratch()
    {
      std::error_code ec;
      const std::filesystem::path path = std::filesystem::temp_directory_path(ec) /
        ("mesolight-fuzz-" + std::to_string(static_cast<long>(::getpid())));
      std::filesystem::create_directories(path, ec);
      this->Path = path.string();
    }
    ~Scratch()
    {
      std::error_code ignored;
      std::filesystem::remove_all(this->Path, ignored);
    }
  };
  static const Scratch scratch;
  return scratch.Path;
}

// Writes `size` bytes to `path` (replacing it); false when it cannot.
inline bool WriteFile(const std::string& path, const void* data, std::size_t size)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  return static_cast<bool>(out);
}

} // namespace fuzz
} // namespace mesolight

#endif
