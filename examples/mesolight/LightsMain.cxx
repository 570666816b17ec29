// mesolight-lights: a stand-alone driver for the image-based lighting commands until they are
// wired into `mesolight` ("mesolight lights ..." and "mesolight bench lights ...").
//   mesolight-lights lights ENV_IMAGE --out lights.csv [--count N] [--variance]
//   mesolight-lights bench [options]
#include "LightsCommand.h"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char* argv[])
{
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && args[0] == "lights")
  {
    return mesolight::RunLightsCommand(std::vector<std::string>(args.begin() + 1, args.end()));
  }
  if (!args.empty() && args[0] == "bench")
  {
    const size_t skip = args.size() > 1 && args[1] == "lights" ? 2 : 1;
    return mesolight::RunLightsBenchmark(std::vector<std::string>(args.begin() + skip, args.end()));
  }
  std::cerr << "usage: mesolight-lights lights ENV_IMAGE --out lights.csv [--count N] "
               "[--variance]\n       mesolight-lights bench [options]\n";
  return 2;
}
