// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the OBJ/MTL scene reader (vtkScene/core/ObjScene), as `mesolight vlf propagate
// SCENE.obj`, `vlf render --object FILE.obj` and vtkOBJSceneReader use it.
//
// Input: the OBJ text, optionally followed by a NUL byte and the text of "scene.mtl", which is
// written beside it (so `mtllib scene.mtl` reaches the MTL parser). Any outcome but a scene or
// ObjSceneError (another exception, a crash, a sanitizer report) is a bug.
#include "FuzzSupport.h"
#include "ObjScene.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using namespace mesolight;
  const char* text = reinterpret_cast<const char*>(data);
  const void* nul = std::memchr(text, '\0', size);
  const std::size_t objBytes =
    nul ? static_cast<std::size_t>(static_cast<const char*>(nul) - text) : size;
  const std::string& directory = fuzz::ScratchDirectory();
  const std::string mtlPath = directory + "/scene.mtl";
  if (nul)
  {
    fuzz::WriteFile(mtlPath, text + objBytes + 1, size - objBytes - 1);
  }
  else
  {
    std::remove(mtlPath.c_str());
  }
  std::istringstream obj(std::string(text, objBytes));
  for (const bool strict : { false, true })
  {
    mesolight::ObjReadOptions options;
    options.RequireEmitter = strict;
    options.RemoveDegenerateTriangles = !strict;
    try
    {
      obj.clear();
      obj.seekg(0);
      const mesolight::ObjSceneRead read =
        mesolight::ParseObjScene(obj, "fuzz.obj", directory, options);
      // What a reader of the result relies on: every index in range.
      const TriangleScene& scene = read.Scene;
      for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
      {
        for (int k = 0; k < 3; ++k)
        {
          if (scene.Triangles[t][k] >= scene.Positions.size())
          {
            std::abort();
          }
        }
        if (scene.MaterialIds[t] >= scene.Materials.size())
        {
          std::abort();
        }
      }
    }
    catch (const mesolight::ObjSceneError&)
    {
    }
  }
  return 0;
}
