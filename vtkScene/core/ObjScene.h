// SPDX-License-Identifier: BSD-3-Clause
// Wavefront OBJ + MTL scenes, the scene files of the light field and the ray tracer (Wither 2005
// §2.4.2.1: the propagator reads a scene as *.obj with a *.mtl of surface properties). Reads into
// the shared TriangleScene and writes one back (the built-in Cornell box as an example of the
// format).
//
// Read: v, vt, vn, f (n-gons ear-clipped, TriangulatePolygon; negative indices count back from the
// last definition), usemtl, mtllib; MTL newmtl, Kd (diffuse), Ks (perfect specular, Wither 2005
// §2.1), Ke (emission), Ka, Ns, and the names of map_* textures (recorded, not loaded); o and g
// name the faces that follow (TriangleScene::SurfaceNames; the statement's names joined by a space,
// a bare g ends the named group). Other statements (s, illum, d, ...) are ignored. Errors throw
// ObjSceneError with "file:line: what"; a missing MTL file or material is a warning and gets a
// default grey material.
#ifndef mesolight_ObjScene_h
#define mesolight_ObjScene_h

#include "TriangleScene.h"

#include <iosfwd>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{

class ObjSceneError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct ObjReadOptions
{
  bool RequireEmitter = false;           // no material with Ke > 0 is an error
  bool RemoveDegenerateTriangles = true; // drop zero-area triangles (counted either way)
};

struct ObjSceneRead
{
  TriangleScene Scene;
  // Per material (same order as Scene.Materials): map_* statement -> file name as written.
  std::vector<std::map<std::string, std::string>> TextureMaps;
  // Usable, but probably not what the user meant ("scene.obj:3: mtllib 'room.mtl' not found ...").
  std::vector<std::string> Warnings;
  std::size_t ObjVertices = 0;         // v statements
  std::size_t ObjFaces = 0;            // f statements (before triangulation)
  std::size_t DegenerateTriangles = 0; // zero-area triangles found (removed if so asked)
  std::size_t NonManifoldEdges = 0;    // edges (by OBJ vertex) shared by more than two triangles
};

// The default material for faces without a (known) material: grey, Kd 0.5.
SceneMaterial DefaultGreyMaterial();

// Reads an OBJ file and the MTL files it names (relative to the OBJ's folder).
ObjSceneRead ReadObjScene(const std::string& objPath, const ObjReadOptions& options = {});
// The same from a stream; `name` prefixes messages, `directory` is where mtllib files are looked
// up.
ObjSceneRead ParseObjScene(std::istream& obj, const std::string& name, const std::string& directory,
  const ObjReadOptions& options = {});

// Undirected edges, by vertex index, used by more than two triangles.
std::size_t CountNonManifoldEdges(const std::vector<glm::uvec3>& triangles);

// The .mtl WriteObjScene writes beside objPath: the same path with its extension replaced.
std::string MaterialFileOf(const std::string& objPath);

// Writes `scene` as OBJ + MTL: objPath and the .mtl beside it (same stem), each through a
// temporary file renamed into place. Existing files are not overwritten unless `overwrite`;
// throws ObjSceneError. Named surfaces are written as g statements. Numbers are written as the
// shortest text that reads back as the same float.
void WriteObjScene(const TriangleScene& scene, const std::string& objPath, bool overwrite = false,
  const std::string& comment = "");

} // namespace mesolight

#endif
