// SPDX-License-Identifier: BSD-3-Clause
// The byte streams of a light-field snapshot (Snapshot.h): header, checksum, the buffered,
// hashing writer and reader, shared by the current format (Snapshot.cxx) and the version-1
// (dense maps) layout it still reads and, for tests, writes (SnapshotVersion1.cxx). Private to
// the LightField core.
#ifndef mesolight_vlf_SnapshotStream_h
#define mesolight_vlf_SnapshotStream_h

#include "LightField.h"
#include "Snapshot.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

namespace mesolight
{
namespace vlf
{
namespace snapshot_io
{
constexpr char Magic[8] = { 'M', 'L', 'V', 'L', 'F', 'S', 'N', 'P' };
constexpr std::uint32_t ByteOrderMark = 0x01020304u;
constexpr std::size_t BufferBytes = std::size_t(1) << 20; // a multiple of 8: hashing is per word

struct Header
{
  char MagicBytes[8];
  std::uint32_t Version;
  std::uint32_t ByteOrder;
  std::uint64_t PayloadBytes;
  std::uint64_t PayloadChecksum;
  std::uint64_t Reserved;
  std::uint64_t HeaderChecksum; // over the fields above
};
static_assert(sizeof(Header) == 48, "snapshot header layout");

// 64-bit multiply-xorshift hash over little-endian 8-byte words; a short last word is padded with
// zeros and the byte count is mixed in at the end.
class Checksum
{
public:
  void Update(const unsigned char* data, std::size_t bytes)
  {
    std::size_t q = 0;
    for (; q + 8 <= bytes; q += 8)
    {
      std::uint64_t word;
      std::memcpy(&word, data + q, 8);
      this->Mix(word);
    }
    if (q < bytes)
    {
      std::uint64_t word = 0;
      std::memcpy(&word, data + q, bytes - q);
      this->Mix(word);
    }
    this->Length += bytes;
  }
  std::uint64_t Value() const
  {
    std::uint64_t h = this->State ^ (this->Length * 0xff51afd7ed558ccdULL);
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ULL;
    return h ^ (h >> 33);
  }

private:
  void Mix(std::uint64_t word)
  {
    this->State = (this->State ^ word) * 0x9E3779B97F4A7C15ULL;
    this->State ^= this->State >> 29;
  }
  std::uint64_t State = 0x243F6A8885A308D3ULL;
  std::uint64_t Length = 0;
};

inline std::uint64_t HeaderChecksum(const Header& h)
{
  Checksum c;
  c.Update(reinterpret_cast<const unsigned char*>(&h), offsetof(Header, HeaderChecksum));
  return c.Value();
}

inline std::string Quoted(const std::string& path)
{
  return "'" + path + "'";
}

class Writer
{
public:
  Writer(const std::string& path, std::FILE* file)
    : Path(path)
    , File(file)
  {
    this->Buffer.reserve(BufferBytes);
  }
  template <typename T>
  void Value(const T& value)
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain data only");
    this->Bytes(&value, sizeof(T));
  }
  template <typename T>
  void Array(const std::vector<T>& values)
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain data only");
    this->Value(static_cast<std::uint64_t>(values.size()));
    this->Bytes(values.data(), values.size() * sizeof(T));
  }
  void String(const std::string& text)
  {
    this->Value(static_cast<std::uint64_t>(text.size()));
    this->Bytes(text.data(), text.size());
  }
  void Bytes(const void* data, std::size_t bytes)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    while (bytes > 0)
    {
      const std::size_t take = std::min(bytes, BufferBytes - this->Buffer.size());
      this->Buffer.insert(this->Buffer.end(), p, p + take);
      p += take;
      bytes -= take;
      if (this->Buffer.size() == BufferBytes)
      {
        this->Flush();
      }
    }
  }
  void Flush()
  {
    if (this->Buffer.empty())
    {
      return;
    }
    this->Hash.Update(this->Buffer.data(), this->Buffer.size());
    if (std::fwrite(this->Buffer.data(), 1, this->Buffer.size(), this->File) != this->Buffer.size())
    {
      throw SnapshotError("cannot write " + Quoted(this->Path) + ": " + std::strerror(errno));
    }
    this->Written += this->Buffer.size();
    this->Buffer.clear();
  }
  std::uint64_t Written = 0;
  Checksum Hash;

private:
  std::string Path;
  std::FILE* File;
  std::vector<unsigned char> Buffer;
};

class Reader
{
public:
  Reader(const std::string& path, std::FILE* file, std::uint64_t payloadBytes)
    : Path(path)
    , File(file)
    , Remaining(payloadBytes)
  {
  }
  template <typename T>
  T Value()
  {
    static_assert(std::is_trivially_copyable<T>::value, "plain data only");
    T value;
    this->Bytes(&value, sizeof(T));
    return value;
  }
  // A count of items of `itemBytes` each, checked against the bytes left so a corrupt count
  // cannot ask for absurd memory.
  std::uint64_t Count(std::size_t itemBytes, const char* what)
  {
    const std::uint64_t count = this->Value<std::uint64_t>();
    if (itemBytes > 0 && count > this->BytesLeft() / itemBytes)
    {
      this->Fail(std::string("its ") + what + " count " + std::to_string(count) +
        " does not fit in the bytes left");
    }
    return count;
  }
  template <typename T>
  void Array(std::vector<T>& values, const char* what, std::uint64_t expected)
  {
    const std::uint64_t count = this->Count(sizeof(T), what);
    if (count != expected)
    {
      this->Fail(std::string("it holds ") + std::to_string(count) + " " + what + " where " +
        std::to_string(expected) + " were expected");
    }
    values.resize(count);
    this->Bytes(values.data(), count * sizeof(T));
  }
  std::string String(const char* what)
  {
    const std::uint64_t count = this->Count(1, what);
    if (count > 4096)
    {
      this->Fail(std::string("its ") + what + " is " + std::to_string(count) + " bytes long");
    }
    std::string text(count, '\0');
    this->Bytes(&text[0], count);
    return text;
  }
  void Bytes(void* data, std::size_t bytes)
  {
    unsigned char* p = static_cast<unsigned char*>(data);
    while (bytes > 0)
    {
      if (this->Position == this->Buffer.size())
      {
        this->Refill();
      }
      const std::size_t take = std::min(bytes, this->Buffer.size() - this->Position);
      std::memcpy(p, this->Buffer.data() + this->Position, take);
      this->Position += take;
      p += take;
      bytes -= take;
    }
  }
  std::uint64_t BytesLeft() const
  {
    return this->Remaining + (this->Buffer.size() - this->Position);
  }
  std::string QuotedPath() const { return Quoted(this->Path); }
  [[noreturn]] void Fail(const std::string& what) const
  {
    throw SnapshotError(Quoted(this->Path) + " is corrupt: " + what);
  }
  Checksum Hash;

private:
  void Refill()
  {
    if (this->Remaining == 0)
    {
      this->Fail("it ends before its contents are complete");
    }
    const std::size_t take =
      static_cast<std::size_t>(std::min<std::uint64_t>(BufferBytes, this->Remaining));
    this->Buffer.resize(take);
    if (std::fread(this->Buffer.data(), 1, take, this->File) != take)
    {
      throw SnapshotError(Quoted(this->Path) + " is truncated (read error)");
    }
    this->Hash.Update(this->Buffer.data(), take);
    this->Remaining -= take;
    this->Position = 0;
  }
  std::string Path;
  std::FILE* File;
  std::uint64_t Remaining;
  std::vector<unsigned char> Buffer;
  std::size_t Position = 0;
};

// Version 1 stored every map cell (depth < 0: no crossing) and float radiance
// (SnapshotVersion1.cxx): one subfield's maps in that layout, and read back into the compact form.
void WriteDenseMaps(Writer& w, const LightField& field, const Subfield& f, std::size_t k);
void ReadDenseMaps(Reader& r, const LightField& field, Subfield& f, std::size_t k,
  std::uint64_t entries, std::size_t cellsPerMap);
} // namespace snapshot_io
} // namespace vlf
} // namespace mesolight

#endif
