// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench vlf-storage`: what the light field's radiance maps take in memory and on disk,
// sparse and shared-exponent (RadianceStorage.h) against the dense float layout of snapshot
// version 1, and the error the compact form adds to lookups (VlfStorageBenchmark.cxx).
#ifndef mesolight_VlfStorageBenchmark_h
#define mesolight_VlfStorageBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{
int RunVlfStorageBenchmark(const std::vector<std::string>& args);
}

#endif
