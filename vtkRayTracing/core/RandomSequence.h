// SPDX-License-Identifier: BSD-3-Clause
// RandomSequence: a small counter-based random number generator (PCG32, O'Neill 2014) seeded
// by hashing (seed, pixel, sample), so every pixel sample draws the same numbers whatever the
// thread or tile order: images are reproducible bit for bit.
#ifndef mesolight_RandomSequence_h
#define mesolight_RandomSequence_h

#include <cstdint>

namespace mesolight
{

// SplitMix64 finaliser: a bijective 64-bit mix, used to turn counters into seeds.
inline std::uint64_t MixBits(std::uint64_t x)
{
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

// Seed of one sample of one pixel (or of any other indexed estimate).
inline std::uint64_t SampleSeed(std::uint64_t seed, std::uint64_t index, std::uint64_t sample)
{
  return MixBits(MixBits(MixBits(seed) ^ index) ^ sample);
}

class RandomSequence
{
public:
  explicit RandomSequence(std::uint64_t seed, std::uint64_t stream = 0)
    : State(0)
    , Increment((MixBits(stream) << 1u) | 1u)
  {
    this->NextUInt();
    this->State += MixBits(seed);
    this->NextUInt();
  }

  std::uint32_t NextUInt()
  {
    const std::uint64_t old = this->State;
    this->State = old * 6364136223846793005ull + this->Increment;
    const auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rotation = static_cast<std::uint32_t>(old >> 59u);
    return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
  }

  // Uniform in [0, 1): the top 24 bits, so the result is exactly representable and never 1.
  float NextFloat() { return static_cast<float>(this->NextUInt() >> 8) * (1.0f / 16777216.0f); }

private:
  std::uint64_t State;
  std::uint64_t Increment;
};

} // namespace mesolight

#endif
