// SPDX-License-Identifier: BSD-3-Clause
#include "Snapshot.h"
#include "SnapshotStream.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <type_traits>
#include <unistd.h>

namespace mesolight
{
namespace vlf
{
using namespace snapshot_io;

namespace
{
void WriteMaterial(Writer& w, const SceneMaterial& m)
{
  w.String(m.Name);
  w.Value(m.Diffuse);
  w.Value(m.Specular);
  w.Value(m.Emission);
  w.Value(m.Ambient);
  w.Value(m.Shininess);
  w.Value(m.Roughness);
}

SceneMaterial ReadMaterial(Reader& r)
{
  SceneMaterial m;
  m.Name = r.String("material name");
  m.Diffuse = r.Value<glm::vec3>();
  m.Specular = r.Value<glm::vec3>();
  m.Emission = r.Value<glm::vec3>();
  m.Ambient = r.Value<glm::vec3>();
  m.Shininess = r.Value<float>();
  m.Roughness = r.Value<float>();
  return m;
}

// Depth of crossing `slot` of map `map` of f (subfield k of the field, its maps possibly received
// from another rank): stored or from the plane (CrossingDepths).
// "GATHERED" read as a little-endian word: the optional section of the propagated totals.
constexpr std::uint64_t GatheredTag = 0x4445524548544147ull;

void WritePayload(Writer& w, const LightField& field,
  const std::function<const Subfield&(std::size_t k)>& subfieldOf, std::uint32_t version)
{
  const LightFieldSettings& s = field.Settings();
  w.Value(static_cast<std::uint64_t>(s.Directions));
  w.Value(static_cast<std::int32_t>(s.RaysPerSide));
  w.Value(static_cast<std::int32_t>(s.TilesPerSide));
  w.Value(s.TexelSize);
  w.Value(s.MemoryBudget);
  // Bit 0 the solid-angle weights, bits 1-2 the contact texel halvings (0 in older files), bit 3:
  // the per-surface texel levels follow (never set in older files).
  const bool levels = !s.SurfaceTexelLevels.empty();
  w.Value(static_cast<std::uint8_t>((s.UseSolidAngleWeights ? 1 : 0) |
    (static_cast<unsigned>(s.ContactTexelHalvings) << 1) | (levels ? 8u : 0u)));
  if (levels)
  {
    w.Array(s.SurfaceTexelLevels);
  }
  w.Value(static_cast<std::int32_t>(field.IterationsDone));
  w.Value(field.NormalizationScale());
  w.Value(field.NormalizationCentre());

  const TriangleScene& scene = field.Scene();
  w.Array(scene.Positions);
  w.Array(scene.Triangles);
  w.Array(scene.MaterialIds);
  w.Array(scene.Normals);
  w.Array(scene.TextureCoordinates);
  w.Value(static_cast<std::uint64_t>(scene.Materials.size()));
  for (const SceneMaterial& m : scene.Materials)
  {
    WriteMaterial(w, m);
  }

  w.Array(field.TotalDiffuse);
  w.Array(field.UnshotDiffuse);
  w.Array(field.Capacity);
  w.Array(field.EnergyLog);
  for (std::size_t k = 0; k < field.SubfieldCount(); ++k)
  {
    const Subfield& f = subfieldOf ? subfieldOf(k) : field.GetSubfield(k);
    w.Array(f.TileStart);
    w.Array(f.Entries);
    if (version == DenseSnapshotVersion)
    {
      WriteDenseMaps(w, field, f, k);
      continue;
    }
    w.Array(f.Cells.Words());
    std::vector<std::uint8_t> followsPlane(f.Entries.size());
    for (std::size_t e = 0; e < followsPlane.size(); ++e)
    {
      followsPlane[e] = f.Depth.FollowsPlane(e) ? 1 : 0;
    }
    w.Array(followsPlane);
    w.Array(f.Depth.Values);
    // As held: float while propagating (resuming continues bit for bit), else compact.
    for (const RadianceArray* radiance : { &f.Radiance, &f.UnshotSpecular })
    {
      w.Value(static_cast<std::uint8_t>(radiance->IsCompact() ? 1 : 0));
      if (radiance->IsCompact())
      {
        const RadianceArray::CompactForm form = radiance->Compacted();
        w.Value(form.Exponent);
        w.Array(form.Words);
      }
      else
      {
        w.Array(radiance->ToVector());
      }
    }
  }
  if (version == DenseSnapshotVersion)
  {
    return; // version 1 had no surface names
  }
  // The surface names, last.
  w.Array(scene.SurfaceIds);
  w.Value(static_cast<std::uint64_t>(scene.SurfaceNames.size()));
  for (const std::string& name : scene.SurfaceNames)
  {
    w.String(name);
  }
  // A gathered field (FinalGather.h): the propagated totals, after everything older files hold,
  // so those still load (nothing left over there) and their fields are not gathered.
  if (!field.PropagatedDiffuse.empty())
  {
    w.Value(GatheredTag);
    w.Array(field.PropagatedDiffuse);
  }
}
} // namespace

std::string SnapshotFileWithPayload(const std::string& payload)
{
  Header header{};
  std::memcpy(header.MagicBytes, Magic, 8);
  header.Version = SnapshotVersion;
  header.ByteOrder = ByteOrderMark;
  header.PayloadBytes = payload.size();
  Checksum hash;
  hash.Update(reinterpret_cast<const unsigned char*>(payload.data()), payload.size());
  header.PayloadChecksum = hash.Value();
  header.HeaderChecksum = HeaderChecksum(header);
  return std::string(reinterpret_cast<const char*>(&header), sizeof(header)) + payload;
}

bool FileExists(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0;
}

bool IsSnapshotFile(const std::string& path)
{
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file)
  {
    return false;
  }
  char magic[8] = {};
  const bool ok = std::fread(magic, 1, 8, file) == 8 && std::memcmp(magic, Magic, 8) == 0;
  std::fclose(file);
  return ok;
}

namespace
{
// A write killed between creating PATH.tmp-PID and renaming it leaves that file behind (as large
// as the field). Remove such leftovers of processes that no longer run: only names of exactly
// that form, and only files that are empty or start with the snapshot magic.
void RemoveStaleTemporaries(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  const std::string prefix = (slash == std::string::npos ? path : path.substr(slash + 1)) + ".tmp-";
  DIR* listing = ::opendir(directory.c_str());
  if (!listing)
  {
    return;
  }
  while (const dirent* entry = ::readdir(listing))
  {
    const std::string name = entry->d_name;
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.find_first_not_of("0123456789", prefix.size()) != std::string::npos ||
      name.size() - prefix.size() > 9)
    {
      continue;
    }
    const long pid = std::stol(name.substr(prefix.size()));
    if (pid == static_cast<long>(::getpid()) ||
      (pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)))
    {
      continue; // ours, or a process that may still be writing it
    }
    const std::string file = (slash == std::string::npos ? "" : directory) + name;
    struct stat info;
    if (::lstat(file.c_str(), &info) != 0 || !S_ISREG(info.st_mode))
    {
      continue;
    }
    bool ours = info.st_size == 0;
    if (!ours)
    {
      if (std::FILE* in = std::fopen(file.c_str(), "rb"))
      {
        char magic[8] = {};
        ours = std::fread(magic, 1, 8, in) == 8 && std::memcmp(magic, Magic, 8) == 0;
        std::fclose(in);
      }
    }
    if (ours)
    {
      std::remove(file.c_str());
    }
  }
  ::closedir(listing);
}

// A subfield's cells are numbers, and its radiance is light (finite, non-negative): what
// ReadSnapshot checks of every map, here for one it reads and drops.
bool CellsUsable(const Subfield& f)
{
  const auto light = [](const glm::vec3& x)
  {
    return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) && x.x >= 0.0f &&
      x.y >= 0.0f && x.z >= 0.0f;
  };
  bool usable = std::all_of(f.Depth.Values.begin(), f.Depth.Values.end(),
    [](float d) { return std::isfinite(d) && d >= 0.0f; });
  for (const RadianceArray* radiance : { &f.Radiance, &f.UnshotSpecular })
  {
    for (std::size_t i = 0; usable && i < radiance->size(); ++i)
    {
      usable = light((*radiance)[i]);
    }
  }
  return usable;
}
} // namespace

void WriteSnapshot(const LightField& field, const std::string& path)
{
  WriteSnapshot(field, path, {});
}

void WriteSnapshot(const LightField& field, const std::string& path,
  const std::function<const Subfield&(std::size_t k)>& subfieldOf)
{
  WriteSnapshotVersion(field, path, SnapshotVersion, subfieldOf);
}

void WriteSnapshotVersion(const LightField& field, const std::string& path, std::uint32_t version,
  const std::function<const Subfield&(std::size_t k)>& subfieldOf)
{
  if (version != SnapshotVersion && version != DenseSnapshotVersion)
  {
    throw SnapshotError("cannot write snapshot version " + std::to_string(version));
  }
  if (path.empty())
  {
    throw SnapshotError("no snapshot file name given");
  }
  RemoveStaleTemporaries(path);
  const std::string temporary = path + ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file)
  {
    throw SnapshotError("cannot create " + Quoted(temporary) + ": " + std::strerror(errno));
  }
  try
  {
    Header header{};
    std::memcpy(header.MagicBytes, Magic, 8);
    header.Version = version;
    header.ByteOrder = ByteOrderMark;
    if (std::fwrite(&header, sizeof(header), 1, file) != 1)
    {
      throw SnapshotError("cannot write " + Quoted(temporary) + ": " + std::strerror(errno));
    }
    Writer writer(temporary, file);
    WritePayload(writer, field, subfieldOf, version);
    writer.Flush();
    header.PayloadBytes = writer.Written;
    header.PayloadChecksum = writer.Hash.Value();
    header.HeaderChecksum = HeaderChecksum(header);
    if (std::fseek(file, 0, SEEK_SET) != 0 || std::fwrite(&header, sizeof(header), 1, file) != 1 ||
      std::fflush(file) != 0 || ::fsync(::fileno(file)) != 0)
    {
      throw SnapshotError("cannot write " + Quoted(temporary) + ": " + std::strerror(errno));
    }
  }
  catch (...)
  {
    std::fclose(file);
    std::remove(temporary.c_str());
    throw;
  }
  if (std::fclose(file) != 0)
  {
    std::remove(temporary.c_str());
    throw SnapshotError("cannot write " + Quoted(temporary) + ": " + std::strerror(errno));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw SnapshotError(
      "cannot rename " + Quoted(temporary) + " to " + Quoted(path) + ": " + reason);
  }
}

namespace
{
void ReadCompactRadiance(
  Reader& r, RadianceArray& radiance, const char* what, std::uint64_t expected)
{
  const std::uint8_t form = r.Value<std::uint8_t>();
  if (form > 1)
  {
    r.Fail(std::string("its ") + what + " have an unknown form " + std::to_string(form));
  }
  if (form == 0)
  {
    std::vector<glm::vec3> values;
    r.Array(values, what, expected);
    for (const glm::vec3& x : values)
    {
      if (!(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)))
      {
        throw SnapshotError(
          r.QuotedPath() + " holds NaN or infinite values: it is not a usable light field");
      }
      if (x.x < 0.0f || x.y < 0.0f || x.z < 0.0f)
      {
        throw SnapshotError(
          r.QuotedPath() + " holds negative radiance: it is not a usable light field");
      }
    }
    radiance.assign(0, glm::vec3(0.0f));
    radiance.Floats() = std::move(values);
    return;
  }
  const std::int32_t exponent = r.Value<std::int32_t>();
  std::vector<std::uint32_t> words;
  r.Array(words, what, expected);
  if (!radiance.AssignCompact(exponent, std::move(words)))
  {
    r.Fail("its radiance exponent " + std::to_string(exponent) + " is out of range");
  }
}

} // namespace

std::unique_ptr<LightField> ReadSnapshot(const std::string& path, std::uint64_t memoryBudget)
{
  return ReadSnapshot(path, memoryBudget, 1, {});
}

std::unique_ptr<LightField> ReadSnapshot(const std::string& path, std::uint64_t memoryBudget,
  std::size_t shareRanks, const std::function<void(LightField&)>& share)
{
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file)
  {
    throw SnapshotError("cannot open light field " + Quoted(path) + ": " + std::strerror(errno));
  }
  struct Closer
  {
    std::FILE* File;
    ~Closer() { std::fclose(this->File); }
  } closer{ file };

  Header header{};
  const std::size_t headerRead = std::fread(&header, 1, sizeof(header), file);
  if (headerRead < 8 || std::memcmp(header.MagicBytes, Magic, 8) != 0)
  {
    throw SnapshotError(
      Quoted(path) + " is not a Mesolight light field snapshot (no MLVLFSNP header)");
  }
  if (headerRead < sizeof(header))
  {
    throw SnapshotError(Quoted(path) + " is truncated: its header is incomplete");
  }
  if (header.HeaderChecksum != HeaderChecksum(header))
  {
    throw SnapshotError(Quoted(path) + " is corrupt: its header checksum does not match");
  }
  if (header.ByteOrder != ByteOrderMark)
  {
    throw SnapshotError(Quoted(path) + " was written on a machine of the other byte order");
  }
  if (header.Version != SnapshotVersion && header.Version != DenseSnapshotVersion)
  {
    throw SnapshotError(Quoted(path) + " is snapshot version " + std::to_string(header.Version) +
      "; this build reads versions " + std::to_string(DenseSnapshotVersion) + " and " +
      std::to_string(SnapshotVersion) + ": propagate the field again with this build");
  }
  const bool dense = header.Version == DenseSnapshotVersion;
  struct stat info;
  if (::fstat(::fileno(file), &info) != 0)
  {
    throw SnapshotError("cannot read " + Quoted(path) + ": " + std::strerror(errno));
  }
  const std::uint64_t fileBytes = static_cast<std::uint64_t>(info.st_size);
  if (fileBytes < sizeof(header) + header.PayloadBytes)
  {
    throw SnapshotError(Quoted(path) + " is truncated: it has " + std::to_string(fileBytes) +
      " bytes, its header announces " + std::to_string(sizeof(header) + header.PayloadBytes));
  }
  if (fileBytes > sizeof(header) + header.PayloadBytes)
  {
    throw SnapshotError(Quoted(path) + " is corrupt: it has " +
      std::to_string(fileBytes - sizeof(header) - header.PayloadBytes) +
      " bytes after the end its header announces");
  }

  Reader r(path, file, header.PayloadBytes);
  LightFieldSettings settings;
  settings.Directions = static_cast<std::size_t>(r.Value<std::uint64_t>());
  settings.RaysPerSide = r.Value<std::int32_t>();
  settings.TilesPerSide = r.Value<std::int32_t>();
  settings.TexelSize = r.Value<float>();
  settings.MemoryBudget = r.Value<std::uint64_t>();
  const std::uint8_t flags = r.Value<std::uint8_t>();
  if ((flags & ~std::uint8_t(15)) != 0)
  {
    r.Fail("its settings are invalid: unknown flags " + std::to_string(flags));
  }
  settings.UseSolidAngleWeights = (flags & 1) != 0;
  settings.ContactTexelHalvings = (flags >> 1) & 3;
  if ((flags & 8) != 0)
  {
    // One level per surface: checked against the surfaces when the structure is set up.
    const std::uint64_t count = r.Count(sizeof(std::int8_t), "surface texel levels");
    settings.SurfaceTexelLevels.resize(count);
    r.Bytes(settings.SurfaceTexelLevels.data(), count);
  }
  // The stored budget is what the field was built with; read back, it is only a number in the
  // file: never trust more than this machine has (a corrupt one would let Setup allocate anything).
  settings.MemoryBudget = memoryBudget > 0
    ? memoryBudget
    : std::min<std::uint64_t>(settings.MemoryBudget, AvailableMemory());
  const std::string problem = settings.Validate();
  if (!problem.empty())
  {
    r.Fail("its settings are invalid: " + problem);
  }
  // Every subfield stores at least its tile offsets and five array counts: a direction count the
  // bytes left cannot hold is corrupt, refused before the directions are set up.
  const std::uint64_t subfieldBytes = 5 * sizeof(std::uint64_t) +
    (static_cast<std::uint64_t>(settings.TilesPerSide) * settings.TilesPerSide + 1) *
      sizeof(std::uint32_t);
  if (settings.Directions > r.BytesLeft() / subfieldBytes)
  {
    r.Fail("its direction count " + std::to_string(settings.Directions) +
      " does not fit in the bytes left");
  }
  const int iterations = r.Value<std::int32_t>();
  if (iterations < 0 || iterations > 1000000)
  {
    r.Fail("it claims " + std::to_string(iterations) + " iterations");
  }
  const float scale = r.Value<float>();
  const glm::vec3 centre = r.Value<glm::vec3>();
  // world = centre + unit / scale: a NaN, infinite or non-positive normalisation puts the scene
  // nowhere, and every command would blame the camera, the object or the placement instead.
  if (!(std::isfinite(scale) && scale > 0.0f))
  {
    r.Fail("its normalisation scale " + std::to_string(scale) + " is not a positive number");
  }
  if (!(std::isfinite(centre.x) && std::isfinite(centre.y) && std::isfinite(centre.z)))
  {
    r.Fail("its normalisation centre (" + std::to_string(centre.x) + ", " +
      std::to_string(centre.y) + ", " + std::to_string(centre.z) + ") is not finite");
  }

  TriangleScene scene;
  scene.Positions.resize(r.Count(sizeof(glm::vec3), "position"));
  r.Bytes(scene.Positions.data(), scene.Positions.size() * sizeof(glm::vec3));
  scene.Triangles.resize(r.Count(sizeof(glm::uvec3), "triangle"));
  r.Bytes(scene.Triangles.data(), scene.Triangles.size() * sizeof(glm::uvec3));
  r.Array(scene.MaterialIds, "material ids", scene.Triangles.size());
  scene.Normals.resize(r.Count(sizeof(glm::vec3), "normal"));
  r.Bytes(scene.Normals.data(), scene.Normals.size() * sizeof(glm::vec3));
  scene.TextureCoordinates.resize(r.Count(sizeof(glm::vec2), "texture coordinate"));
  r.Bytes(scene.TextureCoordinates.data(), scene.TextureCoordinates.size() * sizeof(glm::vec2));
  // The scene of a snapshot is the normalized one (bounding box half-diagonal 1): a vertex far
  // outside asks for absurd texture sizes (found by fuzz/snapshot.cxx).
  for (const glm::vec3& p : scene.Positions)
  {
    if (!(glm::dot(p, p) <= 1.01f))
    {
      r.Fail("its scene is not normalized to the unit sphere (a vertex at " + std::to_string(p.x) +
        ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")");
    }
  }
  const std::uint64_t materials = r.Count(48, "material");
  for (std::uint64_t q = 0; q < materials; ++q)
  {
    scene.Materials.push_back(ReadMaterial(r));
  }
  for (const glm::uvec3& t : scene.Triangles)
  {
    if (t.x >= scene.Positions.size() || t.y >= scene.Positions.size() ||
      t.z >= scene.Positions.size())
    {
      r.Fail("a triangle refers to a missing vertex");
    }
  }
  for (std::uint32_t id : scene.MaterialIds)
  {
    if (id >= scene.Materials.size())
    {
      r.Fail("a triangle refers to a missing material");
    }
  }

  std::unique_ptr<LightField> field(new LightField());
  field->BudgetShareRanks = std::max<std::size_t>(1, shareRanks);
  try
  {
    field->Setup(scene, settings, /*normalize=*/false);
  }
  catch (const MemoryBudgetError&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    r.Fail(std::string("its scene or settings are unusable: ") + e.what());
  }
  field->Scale = scale;
  field->Centre = centre;
  field->IterationsDone = iterations;
  if (share)
  {
    share(*field);
  }
  const std::size_t texels = field->TexelCount();
  r.Array(field->TotalDiffuse, "total texels", texels);
  r.Array(field->UnshotDiffuse, "unshot texels", texels);
  r.Array(field->Capacity, "capacity texels", texels);
  field->EnergyLog.resize(r.Count(sizeof(LightField::IterationEnergy), "energy record"));
  r.Bytes(field->EnergyLog.data(), field->EnergyLog.size() * sizeof(LightField::IterationEnergy));

  const std::size_t tiles = static_cast<std::size_t>(settings.TilesPerSide) * settings.TilesPerSide;
  const std::size_t cellsPerMap =
    static_cast<std::size_t>(settings.TileSide()) * settings.TileSide();
  const std::size_t surfaces = field->Surfaces().size();
  // A subfield this process does not keep is read into `dropped`, checked like the others and
  // emptied (the finite and sign checks below see only the kept ones).
  Subfield dropped;
  bool droppedOk = true;
  for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
  {
    const bool keep = field->OwnsSubfield(k);
    Subfield& f = keep ? field->GetSubfield(k) : dropped;
    r.Array(f.TileStart, "tile offsets", tiles + 1);
    const std::uint64_t entries = r.Count(sizeof(TileEntry), "tile entry");
    if (f.TileStart[0] != 0 || f.TileStart[tiles] != entries)
    {
      r.Fail("the tile lists of subfield " + std::to_string(k) + " are inconsistent");
    }
    for (std::size_t t = 0; t < tiles; ++t)
    {
      if (f.TileStart[t] > f.TileStart[t + 1])
      {
        r.Fail("the tile lists of subfield " + std::to_string(k) + " are inconsistent");
      }
    }
    f.Entries.resize(entries);
    r.Bytes(f.Entries.data(), entries * sizeof(TileEntry));
    for (std::size_t t = 0; t < tiles; ++t)
    {
      for (std::uint32_t e = f.TileStart[t]; e < f.TileStart[t + 1]; ++e)
      {
        if (f.Entries[e].Surface >= surfaces || f.Entries[e].Map >= entries ||
          (e > f.TileStart[t] && f.Entries[e - 1].Surface >= f.Entries[e].Surface))
        {
          r.Fail("a tile list of subfield " + std::to_string(k) + " is corrupt");
        }
      }
    }
    if (dense)
    {
      ReadDenseMaps(r, *field, f, k, entries, cellsPerMap);
    }
    else
    {
      std::vector<std::uint64_t> words;
      r.Array(words, "cell mask words", entries * CellIndex::WordsPerMap(cellsPerMap));
      if (!f.Cells.Assign(entries, cellsPerMap, std::move(words)))
      {
        r.Fail("the cell masks of subfield " + std::to_string(k) + " are inconsistent");
      }
      std::vector<std::uint8_t> followsPlane;
      r.Array(followsPlane, "depth flags", entries);
      f.Depth.Clear();
      f.Depth.Start.assign(entries, CrossingDepths::FromPlane);
      std::uint64_t stored = 0;
      for (std::size_t e = 0; e < entries; ++e)
      {
        if (followsPlane[e] > 1)
        {
          r.Fail("a depth flag of subfield " + std::to_string(k) + " is corrupt");
        }
        if (!followsPlane[e])
        {
          f.Depth.Start[e] = static_cast<std::uint32_t>(stored);
          stored += f.Cells.MapSlots(e);
        }
      }
      r.Array(f.Depth.Values, "crossing depths", stored);
      // The mirrors' maps are numbered first (LightField::StoresRadiance): their crossings'
      // radiance is stored, the others' follows from the textures.
      std::size_t mirrorMaps = 0;
      for (const TileEntry& e : f.Entries)
      {
        mirrorMaps += field->StoresRadiance(e.Surface) ? 1 : 0;
      }
      for (const TileEntry& e : f.Entries)
      {
        if (field->StoresRadiance(e.Surface) != (e.Map < mirrorMaps))
        {
          r.Fail("the maps of subfield " + std::to_string(k) + " are not numbered mirrors first");
        }
      }
      const std::size_t mirrorSlots = field->SpecularSlots(f);
      ReadCompactRadiance(r, f.Radiance, "radiance words", mirrorSlots);
      ReadCompactRadiance(r, f.UnshotSpecular, "unshot specular words", mirrorSlots);
    }
    if (!keep)
    {
      droppedOk = droppedOk && CellsUsable(dropped);
      dropped.TileStart.clear();
      dropped.Entries.clear();
      dropped.Depth.Clear();
      dropped.Radiance.clear();
      dropped.UnshotSpecular.clear();
    }
  }
  if (!dense) // the surface names: since version 2
  {
    TriangleScene& named = field->NormalizedScene;
    const std::uint64_t ids = r.Count(sizeof(std::uint32_t), "surface id");
    if (ids != 0 && ids != named.Triangles.size())
    {
      r.Fail("it holds " + std::to_string(ids) + " surface ids for " +
        std::to_string(named.Triangles.size()) + " triangles");
    }
    named.SurfaceIds.resize(ids);
    r.Bytes(named.SurfaceIds.data(), ids * sizeof(std::uint32_t));
    const std::uint64_t names = r.Count(8, "surface name");
    named.SurfaceNames.clear();
    for (std::uint64_t q = 0; q < names; ++q)
    {
      named.SurfaceNames.push_back(r.String("surface name"));
    }
    for (const std::uint32_t id : named.SurfaceIds)
    {
      if (id != TriangleScene::NoSurface && id >= names)
      {
        r.Fail("a triangle refers to a missing surface name");
      }
    }
  }
  if (!dense && r.BytesLeft() >= sizeof(std::uint64_t) + sizeof(std::uint64_t))
  {
    if (r.Value<std::uint64_t>() != GatheredTag)
    {
      r.Fail("its contents end in an unknown section");
    }
    r.Array(field->PropagatedDiffuse, "propagated texels", field->TotalDiffuse.size());
  }
  if (r.BytesLeft() != 0)
  {
    r.Fail(std::to_string(r.BytesLeft()) + " bytes are left over after its contents");
  }
  if (r.Hash.Value() != header.PayloadChecksum)
  {
    throw SnapshotError(Quoted(path) + " is corrupt: its checksum does not match its contents");
  }
  // A valid checksum says the bytes are what was written, not that they are numbers: a field
  // with NaN or infinite radiance would render blank, or resume as "shot nan" and be saved.
  // (Shared-exponent words are finite and non-negative whatever their bits.)
  const auto finite = [](const float* values, std::size_t count)
  { return std::all_of(values, values + count, [](float x) { return std::isfinite(x); }); };
  const auto finiteVectors = [&](const std::vector<glm::vec3>& values)
  { return values.empty() || finite(&values[0].x, 3 * values.size()); };
  bool ok = droppedOk && finiteVectors(field->TotalDiffuse) &&
    finiteVectors(field->PropagatedDiffuse) && finiteVectors(field->UnshotDiffuse) &&
    finite(field->Capacity.data(), field->Capacity.size());
  for (std::size_t k = 0; ok && k < field->SubfieldCount(); ++k)
  {
    const Subfield& f = field->GetSubfield(k);
    ok = finite(f.Depth.Values.data(), f.Depth.Values.size());
  }
  if (!ok)
  {
    throw SnapshotError(
      Quoted(path) + " holds NaN or infinite values: it is not a usable light field");
  }
  for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
  {
    const Subfield& f = field->GetSubfield(k);
    if (!std::all_of(
          f.Depth.Values.begin(), f.Depth.Values.end(), [](float d) { return d >= 0.0f; }))
    {
      throw SnapshotError(Quoted(path) + " is corrupt: a crossing of subfield " +
        std::to_string(k) + " has a negative depth");
    }
  }
  // Radiance is a sum of non-negative terms: a negative one is not light (it renders black).
  const auto nonNegative = [](const std::vector<glm::vec3>& values)
  {
    return std::all_of(values.begin(), values.end(),
      [](const glm::vec3& x) { return x.x >= 0.0f && x.y >= 0.0f && x.z >= 0.0f; });
  };
  if (!nonNegative(field->TotalDiffuse) || !nonNegative(field->UnshotDiffuse) ||
    !nonNegative(field->PropagatedDiffuse))
  {
    throw SnapshotError(Quoted(path) + " holds negative radiance: it is not a usable light field");
  }
  for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
  {
    field->MarkBlocked(k); // not stored: it follows from the geometry
  }
  return field;
}

} // namespace vlf
} // namespace mesolight
