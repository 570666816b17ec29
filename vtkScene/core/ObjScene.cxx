// SPDX-License-Identifier: BSD-3-Clause
#include "ObjScene.h"

#include "PolygonTriangulation.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace mesolight
{

namespace
{
std::string Location(const std::string& name, std::size_t line)
{
  return name + ":" + std::to_string(line) + ": ";
}

// Whitespace-separated tokens of a line (comments already stripped).
std::vector<std::string> Tokens(const std::string& line)
{
  std::vector<std::string> tokens;
  std::size_t i = 0;
  while (i < line.size())
  {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
    {
      ++i;
    }
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
    {
      ++i;
    }
    if (i > start)
    {
      tokens.push_back(line.substr(start, i - start));
    }
  }
  return tokens;
}

// Reads logical lines: strips '\r' and comments, joins lines ending in '\'. `number` is the
// physical line the logical line starts on. Rejects binary data.
class LineReader
{
public:
  LineReader(std::istream& stream, const std::string& name)
    : Stream(stream)
    , Name(name)
  {
  }
  bool Next(std::string& line, std::size_t& number)
  {
    line.clear();
    std::string physical;
    bool any = false;
    while (std::getline(this->Stream, physical))
    {
      ++this->Physical;
      if (!any)
      {
        number = this->Physical;
      }
      any = true;
      if (physical.find('\0') != std::string::npos)
      {
        throw ObjSceneError(
          Location(this->Name, this->Physical) + "binary data: this is not a text Wavefront file");
      }
      if (!physical.empty() && physical.back() == '\r')
      {
        physical.pop_back();
      }
      const std::size_t hash = physical.find('#');
      if (hash != std::string::npos)
      {
        physical.erase(hash);
      }
      if (!physical.empty() && physical.back() == '\\')
      {
        physical.back() = ' ';
        line += physical;
        continue;
      }
      line += physical;
      return true;
    }
    return any;
  }

  // The next logical line that is not blank: its tokens, "name:line: " for messages and the
  // physical line it starts on (the OBJ and MTL parsers' common loop head).
  bool NextStatement(std::vector<std::string>& tokens, std::string& where, std::size_t& number)
  {
    std::string line;
    while (this->Next(line, number))
    {
      tokens = Tokens(line);
      if (!tokens.empty())
      {
        where = Location(this->Name, number);
        return true;
      }
    }
    return false;
  }

private:
  std::istream& Stream;
  std::string Name;
  std::size_t Physical = 0;
};

float ParseFloat(const std::string& token, const std::string& where)
{
  float value = 0.0f;
  const char* begin = token.data();
  const char* end = token.data() + token.size();
  if (!token.empty() && token[0] == '+')
  {
    ++begin;
  }
  const auto result = std::from_chars(begin, end, value);
  if (result.ec != std::errc() || result.ptr != end)
  {
    throw ObjSceneError(where + "cannot read '" + token + "' as a number");
  }
  if (!std::isfinite(value))
  {
    throw ObjSceneError(where + "'" + token + "' is not a finite number");
  }
  return value;
}

// n numbers after the keyword (at least `required`, at most n).
std::vector<float> ParseFloats(const std::vector<std::string>& tokens, std::size_t required,
  std::size_t n, const std::string& where)
{
  if (tokens.size() - 1 < required)
  {
    throw ObjSceneError(where + "'" + tokens[0] + "' needs " + std::to_string(required) +
      " numbers, got " + std::to_string(tokens.size() - 1));
  }
  std::vector<float> values;
  for (std::size_t k = 1; k < tokens.size() && k <= n; ++k)
  {
    values.push_back(ParseFloat(tokens[k], where));
  }
  return values;
}

glm::vec3 ParseColour(const std::vector<std::string>& tokens, const std::string& where)
{
  if (tokens.size() >= 2 && (tokens[1] == "spectral" || tokens[1] == "xyz"))
  {
    throw ObjSceneError(
      where + "'" + tokens[0] + " " + tokens[1] + "' is not supported (give RGB)");
  }
  const std::vector<float> v = ParseFloats(tokens, 1, 3, where);
  // MTL: "Kd r" means grey r.
  return v.size() == 3 ? glm::vec3(v[0], v[1], v[2]) : glm::vec3(v[0]);
}

// Resolves a 1-based or negative OBJ index against `count` definitions so far.
std::uint32_t ResolveIndex(
  const std::string& token, std::size_t count, const char* what, const std::string& where)
{
  long long value = 0;
  const auto result = std::from_chars(token.data(), token.data() + token.size(), value);
  if (result.ec != std::errc() || result.ptr != token.data() + token.size())
  {
    throw ObjSceneError(where + "cannot read '" + token + "' as a " + what + " index");
  }
  long long index = value > 0 ? value - 1 : static_cast<long long>(count) + value;
  if (value == 0 || index < 0 || index >= static_cast<long long>(count))
  {
    throw ObjSceneError(
      where + "face refers to " + what + " " + token + " of " + std::to_string(count));
  }
  return static_cast<std::uint32_t>(index);
}

std::string Directory(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

std::string JoinPath(const std::string& directory, const std::string& file)
{
  if (!file.empty() && file[0] == '/')
  {
    return file;
  }
  return directory.empty() ? file : directory + "/" + file;
}

struct MtlMaterial
{
  SceneMaterial Material;
  std::map<std::string, std::string> Maps;
};

// Parses an MTL stream into `materials` (appended), `name` prefixes errors.
void ParseMtl(std::istream& stream, const std::string& name, std::vector<MtlMaterial>& materials)
{
  LineReader reader(stream, name);
  std::vector<std::string> tokens;
  std::string where;
  std::size_t number = 0;
  MtlMaterial* current = nullptr;
  while (reader.NextStatement(tokens, where, number))
  {
    const std::string& key = tokens[0];
    if (key == "newmtl")
    {
      if (tokens.size() < 2)
      {
        throw ObjSceneError(where + "newmtl needs a name");
      }
      materials.push_back(MtlMaterial{});
      current = &materials.back();
      current->Material = SceneMaterial{};
      current->Material.Name = tokens[1];
      continue;
    }
    const bool known = key == "Kd" || key == "Ks" || key == "Ke" || key == "Ka" || key == "Ns" ||
      key.rfind("map_", 0) == 0;
    if (!known)
    {
      continue; // illum, d, Tr, Ni, Tf, bump, ...: not used by the light field
    }
    if (current == nullptr)
    {
      throw ObjSceneError(where + "'" + key + "' before any newmtl");
    }
    SceneMaterial& m = current->Material;
    if (key == "Kd")
    {
      m.Diffuse = ParseColour(tokens, where);
    }
    else if (key == "Ks")
    {
      m.Specular = ParseColour(tokens, where);
    }
    else if (key == "Ke")
    {
      m.Emission = ParseColour(tokens, where);
    }
    else if (key == "Ka")
    {
      m.Ambient = ParseColour(tokens, where);
    }
    else if (key == "Ns")
    {
      m.Shininess = ParseFloats(tokens, 1, 1, where)[0];
    }
    else if (tokens.size() >= 2)
    {
      current->Maps[key] = tokens.back(); // options (-bm 1 ...) come before the file name
    }
  }
}

// A corner of an OBJ face: position, texture coordinate and normal indices (-1: none).
struct Corner
{
  std::uint32_t Position;
  long long TCoord;
  long long Normal;
  bool operator==(const Corner& o) const
  {
    return this->Position == o.Position && this->TCoord == o.TCoord && this->Normal == o.Normal;
  }
};
struct CornerHash
{
  std::size_t operator()(const Corner& c) const
  {
    return std::hash<long long>()(
      (static_cast<long long>(c.Position) << 40) ^ ((c.TCoord + 1) << 20) ^ (c.Normal + 1));
  }
};
} // namespace

SceneMaterial DefaultGreyMaterial()
{
  SceneMaterial grey;
  grey.Name = "default-grey";
  grey.Diffuse = glm::vec3(0.5f);
  return grey;
}

std::size_t CountNonManifoldEdges(const std::vector<glm::uvec3>& triangles)
{
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  uses.reserve(triangles.size() * 3);
  for (const glm::uvec3& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint64_t a = std::min(t[k], t[(k + 1) % 3]);
      const std::uint64_t b = std::max(t[k], t[(k + 1) % 3]);
      if (a != b)
      {
        ++uses[(a << 32) | b];
      }
    }
  }
  return static_cast<std::size_t>(
    std::count_if(uses.begin(), uses.end(), [](const auto& entry) { return entry.second > 2; }));
}

ObjSceneRead ParseObjScene(std::istream& obj, const std::string& name, const std::string& directory,
  const ObjReadOptions& options)
{
  ObjSceneRead read;
  std::vector<glm::vec3> positions;
  std::vector<glm::vec2> tcoords;
  std::vector<glm::vec3> normals;
  std::vector<MtlMaterial> library;                  // every material of every mtllib
  std::map<std::string, std::uint32_t> usedMaterial; // name -> id in the scene
  std::uint32_t currentMaterial = 0;
  bool haveMaterial = false;
  std::vector<std::array<Corner, 3>> faces; // triangles, in OBJ indices
  std::vector<std::uint32_t> faceMaterials;
  std::vector<std::uint32_t> faceSurfaces; // TriangleScene::NoSurface outside any `g`/`o`
  std::uint32_t currentSurface = TriangleScene::NoSurface;
  bool anySurface = false;
  bool warnedLines = false;
  std::size_t recognised = 0;

  const auto materialId = [&](const std::string& materialName, const std::string& where)
  {
    const auto found = usedMaterial.find(materialName);
    if (found != usedMaterial.end())
    {
      return found->second;
    }
    const auto inLibrary = std::find_if(library.begin(), library.end(),
      [&](const MtlMaterial& m) { return m.Material.Name == materialName; });
    std::uint32_t id;
    if (inLibrary != library.end())
    {
      id = read.Scene.AddMaterial(inLibrary->Material);
      read.TextureMaps.push_back(inLibrary->Maps);
    }
    else
    {
      SceneMaterial grey = DefaultGreyMaterial();
      if (!materialName.empty())
      {
        read.Warnings.push_back(
          where + "material '" + materialName + "' is not in any MTL file: default grey (Kd 0.5)");
        grey.Name = materialName;
      }
      id = read.Scene.AddMaterial(grey);
      read.TextureMaps.emplace_back();
    }
    usedMaterial[materialName] = id;
    return id;
  };

  LineReader reader(obj, name);
  std::vector<std::string> tokens;
  std::string where;
  std::size_t number = 0;
  while (reader.NextStatement(tokens, where, number))
  {
    const std::string& key = tokens[0];
    if (key == "v")
    {
      const std::vector<float> v = ParseFloats(tokens, 3, 3, where); // a 4th (w) is ignored
      positions.emplace_back(v[0], v[1], v[2]);
      ++recognised;
    }
    else if (key == "vt")
    {
      const std::vector<float> v = ParseFloats(tokens, 1, 2, where);
      tcoords.emplace_back(v[0], v.size() > 1 ? v[1] : 0.0f);
      ++recognised;
    }
    else if (key == "vn")
    {
      const std::vector<float> v = ParseFloats(tokens, 3, 3, where);
      normals.emplace_back(v[0], v[1], v[2]);
      ++recognised;
    }
    else if (key == "f")
    {
      if (tokens.size() < 4)
      {
        throw ObjSceneError(
          where + "a face needs at least 3 vertices, got " + std::to_string(tokens.size() - 1));
      }
      std::vector<Corner> corners;
      for (std::size_t k = 1; k < tokens.size(); ++k)
      {
        const std::string& token = tokens[k];
        const std::size_t slash1 = token.find('/');
        const std::size_t slash2 =
          slash1 == std::string::npos ? std::string::npos : token.find('/', slash1 + 1);
        Corner c{ 0, -1, -1 };
        c.Position = ResolveIndex(token.substr(0, slash1), positions.size(), "vertex", where);
        if (slash1 != std::string::npos)
        {
          const std::string t = token.substr(
            slash1 + 1, slash2 == std::string::npos ? std::string::npos : slash2 - slash1 - 1);
          if (!t.empty())
          {
            c.TCoord = ResolveIndex(t, tcoords.size(), "texture coordinate", where);
          }
          if (slash2 != std::string::npos)
          {
            c.Normal = ResolveIndex(token.substr(slash2 + 1), normals.size(), "normal", where);
          }
        }
        corners.push_back(c);
      }
      if (!haveMaterial)
      {
        currentMaterial = materialId("", where);
        haveMaterial = true;
      }
      std::vector<glm::vec3> polygon;
      for (const Corner& c : corners)
      {
        polygon.push_back(positions[c.Position]);
      }
      for (const glm::uvec3& t : TriangulatePolygon(polygon))
      {
        faces.push_back({ corners[t[0]], corners[t[1]], corners[t[2]] });
        faceMaterials.push_back(currentMaterial);
        faceSurfaces.push_back(currentSurface);
      }
      ++read.ObjFaces;
      ++recognised;
    }
    else if (key == "usemtl")
    {
      if (tokens.size() < 2)
      {
        throw ObjSceneError(where + "usemtl needs a material name");
      }
      currentMaterial = materialId(tokens[1], where);
      haveMaterial = true;
      ++recognised;
    }
    else if (key == "mtllib")
    {
      if (tokens.size() < 2)
      {
        throw ObjSceneError(where + "mtllib needs a file name");
      }
      for (std::size_t k = 1; k < tokens.size(); ++k)
      {
        const std::string path = JoinPath(directory, tokens[k]);
        // Only regular files: a scene naming /dev/zero (or /dev/stdin, a FIFO) would read one
        // endless line into memory (or wait forever).
        std::error_code ec;
        if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        {
          read.Warnings.push_back(where + "mtllib '" + tokens[k] +
            "' is not a regular file: ignored, its materials get the default grey (Kd 0.5)");
          continue;
        }
        std::ifstream mtl(path, std::ios::binary);
        if (!mtl)
        {
          read.Warnings.push_back(where + "mtllib '" + tokens[k] + "' not found (" + path +
            "): its materials get the default grey (Kd 0.5)");
          continue;
        }
        ParseMtl(mtl, path, library);
      }
      ++recognised;
    }
    else if (key == "l" || key == "p")
    {
      if (!warnedLines)
      {
        read.Warnings.push_back(where + "line and point elements are ignored");
        warnedLines = true;
      }
    }
    else if (key == "o" || key == "g")
    {
      // The surface's name: the statement's names joined by a space (`g` may list several
      // groups); a bare `g` returns to the unnamed default group.
      std::string surface;
      for (std::size_t k = 1; k < tokens.size(); ++k)
      {
        surface += (k > 1 ? " " : "") + tokens[k];
      }
      currentSurface = surface.empty() ? TriangleScene::NoSurface : read.Scene.AddSurface(surface);
      anySurface = anySurface || !surface.empty();
      ++recognised;
    }
    else if (key == "s" || key == "vp" || key == "mg" || key == "usemap" || key == "maplib" ||
      key == "bevel" || key == "shadow_obj" || key == "trace_obj" || key == "lod" ||
      key == "c_interp" || key == "d_interp")
    {
      ++recognised;
    }
    else if (recognised == 0 && number > 20)
    {
      throw ObjSceneError(where +
        "no Wavefront OBJ statement in the first 20 lines: this is not "
        "an OBJ file");
    }
  }
  read.ObjVertices = positions.size();
  if (faces.empty())
  {
    throw ObjSceneError(name + ": no faces" +
      (recognised == 0 ? std::string(" (not a Wavefront OBJ file?)") : std::string()));
  }

  // One scene vertex per distinct (position, texture coordinate, normal) corner; per-vertex
  // attributes are kept only when every corner has them.
  bool allTCoords = true, allNormals = true;
  std::size_t facesWithTCoords = 0;
  for (const auto& face : faces)
  {
    bool any = false;
    for (const Corner& c : face)
    {
      allTCoords = allTCoords && c.TCoord >= 0;
      allNormals = allNormals && c.Normal >= 0;
      any = any || c.TCoord >= 0;
    }
    facesWithTCoords += any ? 1 : 0;
  }
  if (!allTCoords && facesWithTCoords > 0)
  {
    // A scene keeps texture coordinates per vertex for all its triangles or for none: say that
    // the ones given were dropped (a relief on such a surface takes its plane's instead).
    read.Warnings.push_back(name + ": " + std::to_string(facesWithTCoords) + " of " +
      std::to_string(faces.size()) +
      " triangles have texture coordinates (vt), the others none: all are dropped, and reliefs "
      "take their surfaces' planes; give every face texture coordinates to keep them");
  }
  std::unordered_map<Corner, std::uint32_t, CornerHash> vertexOf;
  std::vector<glm::uvec3> objTriangles; // by OBJ position, for the manifold check
  TriangleScene& scene = read.Scene;
  for (std::size_t f = 0; f < faces.size(); ++f)
  {
    glm::uvec3 triangle;
    glm::uvec3 objTriangle;
    for (int k = 0; k < 3; ++k)
    {
      Corner c = faces[f][k];
      c.TCoord = allTCoords ? c.TCoord : -1;
      c.Normal = allNormals ? c.Normal : -1;
      const auto found = vertexOf.find(c);
      if (found != vertexOf.end())
      {
        triangle[k] = found->second;
      }
      else
      {
        const auto id = static_cast<std::uint32_t>(scene.Positions.size());
        scene.Positions.push_back(positions[c.Position]);
        if (allTCoords)
        {
          scene.TextureCoordinates.push_back(tcoords[static_cast<std::size_t>(c.TCoord)]);
        }
        if (allNormals)
        {
          const glm::vec3 n = normals[static_cast<std::size_t>(c.Normal)];
          const float length = glm::length(n);
          scene.Normals.push_back(length > 0.0f ? n / length : n);
        }
        vertexOf.emplace(c, id);
        triangle[k] = id;
      }
      objTriangle[k] = faces[f][k].Position;
    }
    scene.Triangles.push_back(triangle);
    scene.MaterialIds.push_back(faceMaterials[f]);
    if (anySurface)
    {
      scene.SurfaceIds.push_back(faceSurfaces[f]);
    }
    objTriangles.push_back(objTriangle);
  }
  // Over the triangles that are kept: a degenerate one on an edge is not the user's fold.
  std::vector<glm::uvec3> keptTriangles;
  for (std::size_t t = 0; t < objTriangles.size(); ++t)
  {
    if (!options.RemoveDegenerateTriangles || !IsDegenerateTriangle(scene, t))
    {
      keptTriangles.push_back(objTriangles[t]);
    }
  }
  read.NonManifoldEdges = CountNonManifoldEdges(keptTriangles);
  if (read.NonManifoldEdges > 0)
  {
    read.Warnings.push_back(name + ": " + std::to_string(read.NonManifoldEdges) +
      " non-manifold edges (shared by more than two triangles)");
  }

  const SceneCheck check = CheckScene(scene, options.RequireEmitter);
  read.DegenerateTriangles = check.DegenerateTriangles;
  if (!check.Ok())
  {
    std::string message = name + ": ";
    for (std::size_t k = 0; k < check.Errors.size(); ++k)
    {
      message += (k ? "; " : "") + check.Errors[k];
    }
    // The warnings are lost with the scene; the first often is the cause (a missing mtllib:
    // no material, so no emitter).
    if (!read.Warnings.empty())
    {
      message += " (after " + std::to_string(read.Warnings.size()) + " warning" +
        (read.Warnings.size() > 1 ? "s" : "") + ", the first: " + read.Warnings.front() + ")";
    }
    throw ObjSceneError(message);
  }
  for (const std::string& warning : check.Warnings)
  {
    read.Warnings.push_back(name + ": " + warning);
  }
  if (!options.RequireEmitter)
  {
    const bool emitter = std::any_of(scene.Materials.begin(), scene.Materials.end(),
      [](const SceneMaterial& m)
      { return glm::any(glm::greaterThan(m.Emission, glm::vec3(0.0f))); });
    if (!emitter)
    {
      read.Warnings.push_back(name + ": no emitter (no material with Ke > 0): the scene is dark");
    }
  }
  if (options.RemoveDegenerateTriangles && read.DegenerateTriangles > 0)
  {
    RemoveDegenerateTriangles(scene);
  }
  return read;
}

ObjSceneRead ReadObjScene(const std::string& objPath, const ObjReadOptions& options)
{
  std::ifstream obj(objPath, std::ios::binary);
  if (!obj)
  {
    throw ObjSceneError(objPath + ": cannot open the file");
  }
  return ParseObjScene(obj, objPath, Directory(objPath), options);
}

namespace
{
std::string Stem(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  return (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    ? path
    : path.substr(0, dot);
}

bool Exists(const std::string& path)
{
  return static_cast<bool>(std::ifstream(path));
}

void WriteAtomically(const std::string& path, const std::string& text)
{
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    if (!out)
    {
      std::remove(temporary.c_str());
      throw ObjSceneError(path + ": cannot write the file");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    throw ObjSceneError(path + ": cannot move the written file into place");
  }
}

std::string Numbers(std::initializer_list<float> values)
{
  std::string text;
  char buffer[32];
  for (const float v : values)
  {
    // The shortest text that reads back as the same float ("0.725", not "0.725000024").
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), v);
    text += ' ';
    text.append(buffer, result.ptr);
  }
  return text;
}
} // namespace

std::string MaterialFileOf(const std::string& objPath)
{
  return Stem(objPath) + ".mtl";
}

void WriteObjScene(const TriangleScene& scene, const std::string& objPath, bool overwrite,
  const std::string& comment)
{
  const std::string mtlPath = MaterialFileOf(objPath);
  const std::size_t slash = mtlPath.find_last_of('/');
  const std::string mtlName = slash == std::string::npos ? mtlPath : mtlPath.substr(slash + 1);
  if (!overwrite)
  {
    for (const std::string& path : { objPath, mtlPath })
    {
      if (Exists(path))
      {
        throw ObjSceneError(path + ": exists; not overwritten");
      }
    }
  }
  const SceneCheck check = CheckScene(scene, false);
  if (!check.Ok())
  {
    throw ObjSceneError(objPath + ": cannot write an invalid scene: " + check.Errors.front());
  }
  std::ostringstream mtl, out;
  std::string header;
  std::istringstream commentLines(comment);
  for (std::string c; std::getline(commentLines, c);)
  {
    header += "# " + c + "\n";
  }
  mtl << header;
  for (const SceneMaterial& m : scene.Materials)
  {
    mtl << "\nnewmtl " << (m.Name.empty() ? "unnamed" : m.Name) << "\n";
    mtl << "Kd" << Numbers({ m.Diffuse.x, m.Diffuse.y, m.Diffuse.z }) << "\n";
    mtl << "Ks" << Numbers({ m.Specular.x, m.Specular.y, m.Specular.z }) << "\n";
    mtl << "Ke" << Numbers({ m.Emission.x, m.Emission.y, m.Emission.z }) << "\n";
    if (m.Ambient != glm::vec3(0.0f))
    {
      mtl << "Ka" << Numbers({ m.Ambient.x, m.Ambient.y, m.Ambient.z }) << "\n";
    }
    if (m.Shininess != 0.0f)
    {
      mtl << "Ns" << Numbers({ m.Shininess }) << "\n";
    }
  }
  out << header << "mtllib " << mtlName << "\n";
  for (const glm::vec3& p : scene.Positions)
  {
    out << "v" << Numbers({ p.x, p.y, p.z }) << "\n";
  }
  const bool tcoords =
    scene.TextureCoordinates.size() == scene.Positions.size() && !scene.Positions.empty();
  const bool normals = scene.Normals.size() == scene.Positions.size() && !scene.Positions.empty();
  if (tcoords)
  {
    for (const glm::vec2& t : scene.TextureCoordinates)
    {
      out << "vt" << Numbers({ t.x, t.y }) << "\n";
    }
  }
  if (normals)
  {
    for (const glm::vec3& n : scene.Normals)
    {
      out << "vn" << Numbers({ n.x, n.y, n.z }) << "\n";
    }
  }
  std::uint32_t material = ~0u;
  std::string surface;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (scene.SurfaceOf(t) != surface)
    {
      surface = scene.SurfaceOf(t);
      out << "g" << (surface.empty() ? "" : " " + surface) << "\n";
    }
    if (scene.MaterialIds[t] != material)
    {
      material = scene.MaterialIds[t];
      const std::string& materialName = scene.Materials[material].Name;
      out << "usemtl " << (materialName.empty() ? "unnamed" : materialName) << "\n";
    }
    out << "f";
    for (int k = 0; k < 3; ++k)
    {
      const std::string index = std::to_string(scene.Triangles[t][k] + 1);
      out << " " << index;
      if (tcoords || normals)
      {
        out << "/" << (tcoords ? index : "") << (normals ? "/" + index : "");
      }
    }
    out << "\n";
  }
  WriteAtomically(mtlPath, mtl.str());
  WriteAtomically(objPath, out.str());
}

} // namespace mesolight
