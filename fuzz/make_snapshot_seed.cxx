// SPDX-License-Identifier: BSD-3-Clause
// Writes a tiny valid light field (the built-in Cornell box, 3 directions, 4x4 rays, coarse
// texels, one propagation iteration; a few KB) for the snapshot fuzz corpus:
//   fuzz_snapshot_seed OUT.vlf [DIRECTIONS [RAYS_PER_SIDE [SCENE.obj]]]
// A real field is megabytes; the fuzzer mutates small files far faster.
#include "ObjScene.h"
#include "Propagation.h"
#include "Snapshot.h"

#include <cstdlib>
#include <exception>
#include <iostream>

int main(int argc, char** argv)
{
  using namespace mesolight;
  using namespace mesolight::vlf;
  if (argc < 2)
  {
    std::cerr << "usage: " << argv[0] << " OUT.vlf [DIRECTIONS [RAYS_PER_SIDE [SCENE.obj]]]\n";
    return 2;
  }
  try
  {
    LightFieldSettings settings;
    settings.Directions = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 3;
    settings.RaysPerSide = argc > 3 ? std::atoi(argv[3]) : 4;
    settings.TilesPerSide = 2;
    settings.TexelSize = 0.5f;
    std::unique_ptr<LightField> field =
      LightField::Build(argc > 4 ? ReadObjScene(argv[4]).Scene : MakeCornellBox(), settings);
    Propagate(*field, 1);
    WriteSnapshot(*field, argv[1]);
  }
  catch (const std::exception& e)
  {
    std::cerr << argv[0] << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}
