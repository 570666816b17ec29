// SPDX-License-Identifier: BSD-3-Clause
#include "RadianceStorage.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{

std::uint32_t EncodeRgb9e5(const glm::vec3& rgb)
{
  float c[3];
  for (int i = 0; i < 3; ++i)
  {
    c[i] = rgb[i] > 0.0f ? std::min(rgb[i], MaxRgb9e5) : 0.0f; // NaN and negatives: 0
  }
  const float largest = std::max({ c[0], c[1], c[2] });
  if (!(largest > 0.0f))
  {
    return 0;
  }
  int e = 0;
  std::frexp(largest, &e); // largest < 2^e
  // Shared exponent (bias 15): the largest channel's mantissa below 2^9.
  int shared = std::max(-15, e) + 15;
  float step = std::ldexp(1.0f, shared - 24);
  if (std::floor(largest / step + 0.5f) >= 512.0f)
  {
    ++shared; // rounding carried into the exponent
    step *= 2.0f;
  }
  std::uint32_t q[3];
  for (int i = 0; i < 3; ++i)
  {
    q[i] = std::min(511u, static_cast<std::uint32_t>(std::floor(c[i] / step + 0.5f)));
  }
  return q[0] | (q[1] << 9) | (q[2] << 18) | (static_cast<std::uint32_t>(shared) << 27);
}

namespace
{
template <typename T>
void PackValue(std::string& out, const T& value)
{
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

template <typename T>
T UnpackValue(const std::string& in, std::size_t& at)
{
  if (in.size() - std::min(in.size(), at) < sizeof(T))
  {
    throw std::runtime_error("a subfield message is truncated");
  }
  T value;
  std::memcpy(&value, in.data() + at, sizeof(T));
  at += sizeof(T);
  return value;
}

template <typename T>
void PackArray(std::string& out, const std::vector<T>& values)
{
  PackValue(out, static_cast<std::uint64_t>(values.size()));
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

template <typename T>
std::vector<T> UnpackArray(const std::string& in, std::size_t& at)
{
  const std::uint64_t n = UnpackValue<std::uint64_t>(in, at);
  if (n > (in.size() - std::min(in.size(), at)) / sizeof(T))
  {
    throw std::runtime_error("a subfield message is truncated");
  }
  std::vector<T> values(static_cast<std::size_t>(n));
  if (n > 0)
  {
    std::memcpy(values.data(), in.data() + at, static_cast<std::size_t>(n) * sizeof(T));
  }
  at += static_cast<std::size_t>(n) * sizeof(T);
  return values;
}
} // namespace

void CellIndex::Build(
  std::size_t maps, std::size_t cellsPerMap, const std::vector<std::size_t>& occupied)
{
  this->MapCount = maps;
  this->Cells = cellsPerMap;
  this->PerMap = WordsPerMap(cellsPerMap);
  this->Mask.assign(maps * this->PerMap, 0);
  for (const std::size_t cell : occupied)
  {
    const std::size_t map = cell / cellsPerMap, local = cell % cellsPerMap;
    this->Mask[map * this->PerMap + (local >> 6)] |= std::uint64_t(1) << (local & 63);
  }
  this->BlockedBits.clear();
  this->Count();
}

bool CellIndex::Assign(std::size_t maps, std::size_t cellsPerMap, std::vector<std::uint64_t> words)
{
  const std::size_t perMap = WordsPerMap(cellsPerMap);
  if (cellsPerMap == 0 || words.size() != maps * perMap)
  {
    return false;
  }
  const std::size_t tail = cellsPerMap & 63;
  if (tail != 0)
  {
    const std::uint64_t beyond = ~((std::uint64_t(1) << tail) - 1);
    for (std::size_t m = 0; m < maps; ++m)
    {
      if (words[m * perMap + perMap - 1] & beyond)
      {
        return false;
      }
    }
  }
  std::uint64_t total = 0;
  for (const std::uint64_t w : words)
  {
    total += static_cast<std::uint64_t>(__builtin_popcountll(w));
  }
  if (total > std::numeric_limits<std::uint32_t>::max())
  {
    return false;
  }
  this->MapCount = maps;
  this->Cells = cellsPerMap;
  this->PerMap = perMap;
  this->Mask = std::move(words);
  this->BlockedBits.clear();
  this->Count();
  return true;
}

void CellIndex::Clear()
{
  *this = CellIndex();
}

void CellIndex::Count()
{
  this->Rank.resize(this->Mask.size());
  std::uint64_t total = 0;
  for (std::size_t w = 0; w < this->Mask.size(); ++w)
  {
    this->Rank[w] = static_cast<std::uint32_t>(total);
    total += static_cast<std::uint64_t>(__builtin_popcountll(this->Mask[w]));
  }
  if (total > std::numeric_limits<std::uint32_t>::max())
  {
    throw std::length_error("a subfield holds more than 2^32 crossings");
  }
  this->Occupied = static_cast<std::size_t>(total);
}

std::uint64_t CellIndex::Bytes() const
{
  return (this->Mask.capacity() + this->BlockedBits.capacity()) * sizeof(std::uint64_t) +
    this->Rank.capacity() * sizeof(std::uint32_t);
}

void CellIndex::Pack(std::string& out) const
{
  PackValue(out, static_cast<std::uint64_t>(this->MapCount));
  PackValue(out, static_cast<std::uint64_t>(this->Cells));
  PackArray(out, this->Mask);
}

void CellIndex::Unpack(const std::string& in, std::size_t& at)
{
  const std::uint64_t maps = UnpackValue<std::uint64_t>(in, at);
  const std::uint64_t cells = UnpackValue<std::uint64_t>(in, at);
  std::vector<std::uint64_t> words = UnpackArray<std::uint64_t>(in, at);
  if (maps == 0 && words.empty())
  {
    this->Clear();
    return;
  }
  if (!this->Assign(
        static_cast<std::size_t>(maps), static_cast<std::size_t>(cells), std::move(words)))
  {
    throw std::runtime_error("a subfield message holds an inconsistent cell index");
  }
}

void CrossingDepths::Clear()
{
  std::vector<std::uint32_t>().swap(this->Start);
  std::vector<float>().swap(this->Values);
}

std::uint64_t CrossingDepths::Bytes() const
{
  return this->Start.capacity() * sizeof(std::uint32_t) + this->Values.capacity() * sizeof(float);
}

void CrossingDepths::Pack(std::string& out) const
{
  PackArray(out, this->Start);
  PackArray(out, this->Values);
}

void CrossingDepths::Unpack(const std::string& in, std::size_t& at)
{
  this->Start = UnpackArray<std::uint32_t>(in, at);
  this->Values = UnpackArray<float>(in, at);
  for (const std::uint32_t start : this->Start)
  {
    if (start != FromPlane && start > this->Values.size())
    {
      throw std::runtime_error("a subfield message holds inconsistent depths");
    }
  }
}

void RadianceArray::assign(std::size_t n, const glm::vec3& value)
{
  std::vector<std::uint32_t>().swap(this->Packed);
  this->Values.assign(n, value);
  this->Compact = false;
  this->Scale = 1.0f;
  this->Exponent = 0;
}

void RadianceArray::clear()
{
  std::vector<glm::vec3>().swap(this->Values);
  std::vector<std::uint32_t>().swap(this->Packed);
  this->Compact = false;
  this->Scale = 1.0f;
  this->Exponent = 0;
}

RadianceArray::CompactForm RadianceArray::Compacted() const
{
  CompactForm form;
  if (this->Compact)
  {
    form.Exponent = this->Exponent;
    form.Words = this->Packed;
    return form;
  }
  float largest = 0.0f;
  for (const glm::vec3& v : this->Values)
  {
    for (int c = 0; c < 3; ++c)
    {
      if (v[c] > largest && std::isfinite(v[c]))
      {
        largest = v[c];
      }
    }
  }
  // The largest value into [2^14, 2^15): the top of RGB9E5's range, clear of its clamp.
  form.Exponent = largest > 0.0f ? std::clamp(std::ilogb(largest) - 14, -100, 100) : 0;
  const float toStored = std::ldexp(1.0f, -form.Exponent);
  form.Words.resize(this->Values.size());
  for (std::size_t i = 0; i < this->Values.size(); ++i)
  {
    form.Words[i] = EncodeRgb9e5(this->Values[i] * toStored);
  }
  return form;
}

bool RadianceArray::AssignCompact(std::int32_t exponent, std::vector<std::uint32_t> words)
{
  if (exponent < -100 || exponent > 100)
  {
    return false;
  }
  std::vector<glm::vec3>().swap(this->Values);
  this->Packed = std::move(words);
  this->Exponent = exponent;
  this->Scale = std::ldexp(1.0f, exponent);
  this->Compact = true;
  return true;
}

void RadianceArray::MakeCompact()
{
  if (this->Compact)
  {
    return;
  }
  CompactForm form = this->Compacted();
  this->AssignCompact(form.Exponent, std::move(form.Words));
}

std::vector<glm::vec3>& RadianceArray::Floats()
{
  if (this->Compact)
  {
    std::vector<glm::vec3> values(this->Packed.size());
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      values[i] = DecodeRgb9e5(this->Packed[i]) * this->Scale;
    }
    std::vector<std::uint32_t>().swap(this->Packed);
    this->Values = std::move(values);
    this->Compact = false;
    this->Scale = 1.0f;
    this->Exponent = 0;
  }
  return this->Values;
}

std::uint64_t RadianceArray::Bytes() const
{
  return this->Values.capacity() * sizeof(glm::vec3) +
    this->Packed.capacity() * sizeof(std::uint32_t);
}

bool RadianceArray::operator==(const RadianceArray& other) const
{
  if (this->size() != other.size())
  {
    return false;
  }
  for (std::size_t i = 0; i < this->size(); ++i)
  {
    if ((*this)[i] != other[i])
    {
      return false;
    }
  }
  return true;
}

std::vector<glm::vec3> RadianceArray::ToVector() const
{
  std::vector<glm::vec3> values(this->size());
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    values[i] = (*this)[i];
  }
  return values;
}

void RadianceArray::Pack(std::string& out) const
{
  PackValue(out, static_cast<std::uint8_t>(this->Compact ? 1 : 0));
  PackValue(out, this->Exponent);
  if (this->Compact)
  {
    PackArray(out, this->Packed);
  }
  else
  {
    PackArray(out, this->Values);
  }
}

void RadianceArray::Unpack(const std::string& in, std::size_t& at)
{
  const bool compact = UnpackValue<std::uint8_t>(in, at) != 0;
  const std::int32_t exponent = UnpackValue<std::int32_t>(in, at);
  if (compact)
  {
    if (!this->AssignCompact(exponent, UnpackArray<std::uint32_t>(in, at)))
    {
      throw std::runtime_error("a subfield message holds an unusable radiance exponent");
    }
  }
  else
  {
    this->clear();
    this->Values = UnpackArray<glm::vec3>(in, at);
  }
}

} // namespace vlf
} // namespace mesolight
