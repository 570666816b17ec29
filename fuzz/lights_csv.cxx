// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the lights CSV read back (filters/Lighting/core/LightSetCsv, behind
// vtkLightSetReader and `mesolight render --lights-csv`).
//
// Input: the file's text. A light set accepted must hold whole lights of finite numbers within
// single precision, unit directions and no negative irradiance; a refusal must say why, in
// printable ASCII (no raw file bytes echoed) in a LightSetCsvError. Anything else aborts.
#include "LightSetCsv.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream in(text);
  std::vector<double> values;
  try
  {
    values = mesolight::ParseLightSetCsv(in, "fuzz.csv");
  }
  catch (const mesolight::LightSetCsvError& e)
  {
    // The refusal expected for bad input; any other exception escapes and aborts.
    const std::string error = e.what();
    if (error.empty())
    {
      std::abort();
    }
    for (const char c : error)
    {
      const auto byte = static_cast<unsigned char>(c);
      if (byte < 0x20 || byte >= 0x7f)
      {
        std::abort();
      }
    }
    return 0;
  }
  if (values.empty() || values.size() % 8 != 0)
  {
    std::abort();
  }
  for (std::size_t k = 0; k < values.size(); k += 8)
  {
    const double* v = values.data() + k;
    for (int c = 0; c < 8; ++c)
    {
      if (!std::isfinite(v[c]) ||
        std::abs(v[c]) > static_cast<double>(std::numeric_limits<float>::max()))
      {
        std::abort();
      }
    }
    const double length = std::sqrt(v[2] * v[2] + v[3] * v[3] + v[4] * v[4]);
    if (std::abs(length - 1.0) > 1e-3 || v[5] < 0.0 || v[6] < 0.0 || v[7] < 0.0)
    {
      std::abort();
    }
  }
  return 0;
}
