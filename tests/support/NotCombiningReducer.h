// SPDX-License-Identifier: BSD-3-Clause
// The negative case of the tests run under `mpiexec -n N`: a reducer that leaves the float sums
// out (the agreements, in doubles, still run), so that a distributed computation through it keeps
// each rank's share uncombined, which must then differ from the combined result.
#ifndef MesolightNotCombiningReducer_h
#define MesolightNotCombiningReducer_h

#include "Distribution.h" // vtkVLF/LightField/core

#include <cstddef>
#include <string>

namespace mesolight_test
{

class NotCombiningReducer : public mesolight::vlf::Reducer
{
public:
  explicit NotCombiningReducer(mesolight::vlf::Reducer& inner)
    : Inner(inner)
  {
  }
  int Rank() const override { return this->Inner.Rank(); }
  int Size() const override { return this->Inner.Size(); }
  void SumInPlace(float*, std::size_t) override {}
  void SumInPlace(double* data, std::size_t n) override { this->Inner.SumInPlace(data, n); }
  void Broadcast(std::string& bytes, int root) override { this->Inner.Broadcast(bytes, root); }
  void Send(const std::string& bytes, int to) override { this->Inner.Send(bytes, to); }
  std::string Receive(int from) override { return this->Inner.Receive(from); }

private:
  mesolight::vlf::Reducer& Inner;
};

} // namespace mesolight_test

#endif
