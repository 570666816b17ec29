// SPDX-License-Identifier: BSD-3-Clause
#include "Distribution.h"

#include "Lookup.h"
#include "ParallelFor.h"
#include "Snapshot.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <numeric>

namespace mesolight
{
namespace vlf
{

namespace
{

constexpr std::size_t EnergyValues = 15; // Shot, Escaped, Absorbed, BackFaces, SpecularLost
std::atomic<bool> Agreed{ false };

template <typename T>
void PackVector(std::string& out, const std::vector<T>& v)
{
  const std::uint64_t n = v.size();
  out.append(reinterpret_cast<const char*>(&n), sizeof(n));
  if (n > 0)
  {
    out.append(reinterpret_cast<const char*>(v.data()), n * sizeof(T));
  }
}

template <typename T>
void UnpackVector(const std::string& in, std::size_t& at, std::vector<T>& v)
{
  std::uint64_t n = 0;
  if (in.size() - at < sizeof(n))
  {
    throw std::runtime_error("a subfield message is truncated");
  }
  std::memcpy(&n, in.data() + at, sizeof(n));
  at += sizeof(n);
  if (n > (in.size() - at) / sizeof(T))
  {
    throw std::runtime_error("a subfield message is truncated");
  }
  v.resize(static_cast<std::size_t>(n));
  if (n > 0)
  {
    std::memcpy(v.data(), in.data() + at, static_cast<std::size_t>(n) * sizeof(T));
  }
  at += static_cast<std::size_t>(n) * sizeof(T);
}

void FreeMaps(Subfield& f)
{
  std::vector<std::uint32_t>().swap(f.TileStart);
  std::vector<TileEntry>().swap(f.Entries);
  f.Cells.Clear();
  f.Depth.Clear();
  f.Radiance.clear();
  f.UnshotSpecular.clear();
}
} // namespace

void SerialReducer::Send(const std::string&, int)
{
  throw std::logic_error("one process has no other rank to send to");
}

std::string SerialReducer::Receive(int)
{
  throw std::logic_error("one process has no other rank to receive from");
}

std::vector<double> DirectionCosts(const LightField& field)
{
  const double lines = static_cast<double>(field.Settings().RaysPerSide) *
    static_cast<double>(field.Settings().RaysPerSide);
  const double cellArea =
    static_cast<double>(field.Settings().CellSize()) * field.Settings().CellSize();
  std::vector<double> cost(field.SubfieldCount(), lines);
  for (std::size_t k = 0; k < cost.size(); ++k)
  {
    const glm::vec3 d = field.Directions().Direction(k);
    double projected = 0.0;
    for (const Surface& s : field.Surfaces())
    {
      projected += s.Area * std::abs(static_cast<double>(glm::dot(s.Normal, d)));
    }
    cost[k] += projected / cellArea; // crossings: projected area over a line's cell
  }
  return cost;
}

std::vector<std::uint32_t> BalanceDirections(const LightField& field, int ranks)
{
  if (ranks < 1)
  {
    throw std::invalid_argument("a light field needs at least one rank");
  }
  const std::vector<double> cost = DirectionCosts(field);
  std::vector<std::size_t> order(cost.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(
    order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  std::vector<double> load(static_cast<std::size_t>(ranks), 0.0);
  std::vector<std::uint32_t> owner(cost.size(), 0);
  for (std::size_t k : order)
  {
    const std::size_t r = static_cast<std::size_t>(
      std::min_element(load.begin(), load.end()) - load.begin()); // first least loaded
    owner[k] = static_cast<std::uint32_t>(r);
    load[r] += cost[k];
  }
  return owner;
}

void AgreeOnFailure(Reducer& reducer, std::exception_ptr failure)
{
  if (reducer.Size() <= 1)
  {
    if (failure)
    {
      std::rethrow_exception(failure);
    }
    return;
  }
  std::vector<double> failed(static_cast<std::size_t>(reducer.Size()), 0.0);
  failed[static_cast<std::size_t>(reducer.Rank())] = failure ? 1.0 : 0.0;
  reducer.SumInPlace(failed.data(), failed.size());
  const auto first = std::find_if(failed.begin(), failed.end(), [](double f) { return f > 0.5; });
  if (first == failed.end())
  {
    return;
  }
  const int root = static_cast<int>(first - failed.begin());
  Agreed = true;
  // The first byte says whether it was an abort (kept as AbortedError on every rank).
  std::string message;
  if (root == reducer.Rank())
  {
    try
    {
      std::rethrow_exception(failure);
    }
    catch (const AbortedError& e)
    {
      message = std::string("A") + e.what();
    }
    catch (const DistributedError& e)
    {
      message = std::string("D") + e.what();
    }
    catch (const std::exception& e)
    {
      message = std::string("E") + e.what();
    }
    catch (...)
    {
      message = "Ean unknown error";
    }
  }
  reducer.Broadcast(message, root);
  if (!message.empty() && message[0] == 'A')
  {
    throw AbortedError();
  }
  if (!message.empty() && message[0] == 'D')
  {
    throw DistributedError(message.substr(1));
  }
  throw DistributedError("rank " + std::to_string(root) + " of " + std::to_string(reducer.Size()) +
    ": " + (message.empty() ? "failed" : message.substr(1)));
}

bool FailureWasAgreed()
{
  return Agreed;
}

void Agree(Reducer& reducer, const std::function<void()>& step)
{
  std::exception_ptr failure;
  try
  {
    step();
  }
  catch (...)
  {
    failure = std::current_exception();
  }
  AgreeOnFailure(reducer, failure);
}

void ReduceIteration(
  Reducer& reducer, std::vector<glm::vec3>& reflected, LightField::IterationEnergy& energy)
{
  if (reducer.Size() <= 1)
  {
    return;
  }
  static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "packed vec3");
  reducer.SumInPlace(reinterpret_cast<float*>(reflected.data()), 3 * reflected.size());
  std::array<std::array<double, 3>*, 5> parts = { &energy.Shot, &energy.Escaped, &energy.Absorbed,
    &energy.BackFaces, &energy.SpecularLost };
  double values[EnergyValues];
  for (std::size_t p = 0; p < parts.size(); ++p)
  {
    std::copy(parts[p]->begin(), parts[p]->end(), values + 3 * p);
  }
  reducer.SumInPlace(values, EnergyValues);
  for (std::size_t p = 0; p < parts.size(); ++p)
  {
    std::copy(values + 3 * p, values + 3 * p + 3, parts[p]->begin());
  }
}

std::uint64_t ReducedBytesPerIteration(const LightField& field)
{
  return static_cast<std::uint64_t>(field.TexelCount()) * sizeof(glm::vec3) +
    EnergyValues * sizeof(double);
}

std::vector<glm::vec3> GatherIrradiance(const LightField& field,
  const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals, Reducer& reducer)
{
  if (points.size() != normals.size())
  {
    throw std::invalid_argument("GatherIrradiance: as many normals as points are needed");
  }
  std::vector<glm::vec3> irradiance(points.size(), glm::vec3(0.0f));
  std::exception_ptr failure;
  try
  {
    const Lookup lookup(field);
    ParallelFor(0, points.size(), 0,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t i = begin; i < end; ++i)
        {
          irradiance[i] = lookup.Irradiance(points[i], glm::normalize(normals[i]));
        }
      });
  }
  catch (...)
  {
    failure = std::current_exception();
  }
  AgreeOnFailure(reducer, failure);
  reducer.SumInPlace(reinterpret_cast<float*>(irradiance.data()), 3 * irradiance.size());
  return irradiance;
}

std::vector<glm::vec3> RadianceLeaving(const LightField& field,
  const std::vector<RadianceQuery>& queries, Reducer& reducer, CellInterpolation cells,
  DirectionInterpolation directions)
{
  const Lookup lookup(field);
  const int ranks = reducer.Size(), rank = reducer.Rank();
  // Every rank's queries, in rank order (one broadcast per rank).
  std::vector<RadianceQuery> all;
  std::size_t first = 0; // this rank's first query in `all`
  if (ranks <= 1)
  {
    all = queries;
  }
  else
  {
    for (int r = 0; r < ranks; ++r)
    {
      std::string bytes;
      if (r == rank)
      {
        first = all.size();
        bytes.assign(
          reinterpret_cast<const char*>(queries.data()), queries.size() * sizeof(RadianceQuery));
      }
      reducer.Broadcast(bytes, r);
      const std::size_t count = bytes.size() / sizeof(RadianceQuery);
      const std::size_t at = all.size();
      all.resize(at + count);
      if (count > 0)
      {
        std::memcpy(
          static_cast<void*>(all.data() + at), bytes.data(), count * sizeof(RadianceQuery));
      }
    }
  }
  std::vector<glm::vec4> share(all.size(), glm::vec4(0.0f));
  std::exception_ptr failure;
  try
  {
    ParallelFor(0, all.size(), 0,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t i = begin; i < end; ++i)
        {
          if (all[i].Surface >= field.Surfaces().size())
          {
            throw std::invalid_argument("RadianceLeaving: surface " +
              std::to_string(all[i].Surface) + " is not one of the light field's");
          }
          share[i] = lookup.RadianceLeavingShare(
            all[i].Surface, all[i].Point, all[i].Toward, cells, directions);
        }
      });
  }
  catch (...)
  {
    failure = std::current_exception();
  }
  AgreeOnFailure(reducer, failure);
  static_assert(sizeof(glm::vec4) == 4 * sizeof(float), "packed vec4");
  reducer.SumInPlace(reinterpret_cast<float*>(share.data()), 4 * share.size());
  std::vector<glm::vec3> radiance(queries.size());
  for (std::size_t i = 0; i < queries.size(); ++i)
  {
    const glm::vec4& s = share[first + i];
    radiance[i] = s.w > 0.0f ? glm::vec3(s) / s.w
                             : lookup.DiffuseRadiance(queries[i].Surface, queries[i].Point);
  }
  return radiance;
}

void KeepOwnedSubfields(LightField& field, Reducer& reducer)
{
  if (reducer.Size() <= 1)
  {
    return;
  }
  const std::vector<std::uint32_t> owner = BalanceDirections(field, reducer.Size());
  field.OwnedSubfields.assign(owner.size(), 0);
  for (std::size_t k = 0; k < owner.size(); ++k)
  {
    field.OwnedSubfields[k] = owner[k] == static_cast<std::uint32_t>(reducer.Rank());
    if (!field.OwnedSubfields[k])
    {
      FreeMaps(field.GetSubfield(k));
    }
  }
}

std::unique_ptr<LightField> ReadOwnedSubfields(
  const std::string& path, std::uint64_t memoryBudget, const Reducer& reducer)
{
  if (reducer.Size() <= 1)
  {
    return ReadSnapshot(path, memoryBudget);
  }
  const int ranks = reducer.Size();
  const std::uint32_t rank = static_cast<std::uint32_t>(reducer.Rank());
  return ReadSnapshot(path, memoryBudget, static_cast<std::size_t>(ranks),
    [&](LightField& field)
    {
      if (field.HasSpecular())
      {
        throw std::invalid_argument(
          "the light field has mirror surfaces, which move light between directions held by "
          "different ranks: a distributed light field does not support them yet; run on one rank");
      }
      const std::vector<std::uint32_t> owner = BalanceDirections(field, ranks);
      field.OwnedSubfields.assign(owner.size(), 0);
      for (std::size_t k = 0; k < owner.size(); ++k)
      {
        field.OwnedSubfields[k] = owner[k] == rank;
      }
    });
}

std::string PackSubfield(const Subfield& f)
{
  std::string out;
  PackVector(out, f.TileStart);
  PackVector(out, f.Entries);
  f.Cells.Pack(out);
  f.Depth.Pack(out);
  f.Radiance.Pack(out);
  f.UnshotSpecular.Pack(out);
  return out;
}

void UnpackSubfield(const std::string& bytes, Subfield& f)
{
  std::size_t at = 0;
  UnpackVector(bytes, at, f.TileStart);
  UnpackVector(bytes, at, f.Entries);
  f.Cells.Unpack(bytes, at);
  f.Depth.Unpack(bytes, at);
  f.Radiance.Unpack(bytes, at);
  f.UnshotSpecular.Unpack(bytes, at);
}

namespace
{
// Owner of subfield k under the field's split (the field holds only its own mask).
std::vector<std::uint32_t> Owners(const LightField& field, Reducer& reducer)
{
  return BalanceDirections(field, reducer.Size());
}
} // namespace

void WriteDistributedSnapshot(
  LightField& field, const std::string& path, Reducer& reducer, std::size_t batchBytes)
{
  if (reducer.Size() <= 1)
  {
    WriteSnapshot(field, path);
    return;
  }
  const std::vector<std::uint32_t> owner = Owners(field, reducer);
  const std::uint32_t rank = static_cast<std::uint32_t>(reducer.Rank());
  // Subfields travel in batches of about this many bytes (never split): a message per subfield
  // made each one a blocking hand-over between two processes, which on a loaded machine cost a
  // scheduler time slice each (measured: 2.4 s of rank 0's 2.9 s of writes for 513 directions on
  // 2 ranks, 3 iterations). Rank 0 holds one batch per rank at most.
  if (batchBytes == 0)
  {
    batchBytes = std::max<std::size_t>(std::size_t(1) << 18,
      std::min<std::size_t>(std::size_t(8) << 20,
        (std::size_t(64) << 20) / static_cast<std::size_t>(reducer.Size() - 1)));
  }
  std::exception_ptr failure;
  if (rank == 0)
  {
    // Subfields are asked for in ascending order, and every owner sends its own in that order:
    // the next subfield in a rank's batches is always the next one wanted from it.
    struct Batch
    {
      std::string Bytes;
      std::size_t At = 0;
    };
    std::vector<Batch> batches(static_cast<std::size_t>(reducer.Size()));
    const auto next = [&](std::uint32_t from) -> std::string
    {
      Batch& b = batches[from];
      if (b.At >= b.Bytes.size())
      {
        b.Bytes = reducer.Receive(static_cast<int>(from));
        b.At = 0;
      }
      std::uint64_t n = 0;
      if (b.Bytes.size() - b.At < sizeof(n))
      {
        throw std::runtime_error("a subfield message is truncated");
      }
      std::memcpy(&n, b.Bytes.data() + b.At, sizeof(n));
      b.At += sizeof(n);
      if (n > b.Bytes.size() - b.At)
      {
        throw std::runtime_error("a subfield message is truncated");
      }
      std::string one = b.Bytes.substr(b.At, static_cast<std::size_t>(n));
      b.At += static_cast<std::size_t>(n);
      return one;
    };
    std::size_t received = 0; // subfields [0, received) dealt with
    Subfield incoming;
    try
    {
      WriteSnapshot(field, path,
        [&](std::size_t k) -> const Subfield&
        {
          for (; received < k; ++received)
          {
            if (owner[received] != 0)
            {
              next(owner[received]); // skipped: not wanted here
            }
          }
          received = k + 1;
          if (owner[k] == 0)
          {
            return field.GetSubfield(k);
          }
          UnpackSubfield(next(owner[k]), incoming);
          return incoming;
        });
    }
    catch (...)
    {
      failure = std::current_exception();
    }
    // After a failed write, take the batches still on their way (senders would wait).
    try
    {
      for (; received < owner.size(); ++received)
      {
        if (owner[received] != 0)
        {
          next(owner[received]);
        }
      }
    }
    catch (...)
    {
      failure = failure ? failure : std::current_exception();
    }
  }
  else
  {
    std::string batch;
    for (std::size_t k = 0; k < owner.size(); ++k)
    {
      if (owner[k] == rank)
      {
        const std::string one = PackSubfield(field.GetSubfield(k));
        const std::uint64_t n = one.size();
        batch.append(reinterpret_cast<const char*>(&n), sizeof(n));
        batch += one;
        if (batch.size() >= batchBytes)
        {
          reducer.Send(batch, 0);
          batch.clear();
        }
      }
    }
    if (!batch.empty())
    {
      reducer.Send(batch, 0);
    }
  }
  AgreeOnFailure(reducer, failure);
}

void GatherSubfieldsToRoot(LightField& field, Reducer& reducer)
{
  if (reducer.Size() <= 1)
  {
    return;
  }
  const std::vector<std::uint32_t> owner = Owners(field, reducer);
  const std::uint32_t rank = static_cast<std::uint32_t>(reducer.Rank());
  std::exception_ptr failure;
  for (std::size_t k = 0; k < owner.size(); ++k)
  {
    if (rank == 0 && owner[k] != 0)
    {
      const std::string bytes = reducer.Receive(static_cast<int>(owner[k]));
      try
      {
        UnpackSubfield(bytes, field.GetSubfield(k));
      }
      catch (...)
      {
        failure = std::current_exception();
      }
    }
    else if (rank != 0 && owner[k] == rank)
    {
      reducer.Send(PackSubfield(field.GetSubfield(k)), 0);
    }
  }
  if (rank == 0 && !failure)
  {
    field.OwnedSubfields.clear(); // rank 0 holds every direction now
  }
  AgreeOnFailure(reducer, failure);
}

} // namespace vlf
} // namespace mesolight
