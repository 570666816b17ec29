// SPDX-License-Identifier: BSD-3-Clause
// mesolight::vlf::ControllerReducer: the distributed light field's collective operations
// (Distribution.h's Reducer) on VTK's vtkMultiProcessController -- vtkMPIController under
// mpiexec (the mesolight tool, pvbatch, pvserver), MPI_Allreduce, MPI_Bcast and MPI_Send below.
#ifndef vtkLightFieldReducer_h
#define vtkLightFieldReducer_h

#include "MesolightLightFieldModule.h" // For export macro

#include "Distribution.h" // mesolight::vlf::Reducer

class vtkMultiProcessController;

namespace mesolight
{
namespace vlf
{

class MESOLIGHTLIGHTFIELD_EXPORT ControllerReducer : public Reducer
{
public:
  // controller: not owned; nullptr = vtkMultiProcessController::GetGlobalController() (one
  // process when there is none).
  explicit ControllerReducer(vtkMultiProcessController* controller = nullptr);
  int Rank() const override;
  int Size() const override;
  void SumInPlace(float* data, std::size_t n) override;
  void SumInPlace(double* data, std::size_t n) override;
  void Broadcast(std::string& bytes, int root) override;
  void Send(const std::string& bytes, int to) override;
  std::string Receive(int from) override;
  // Bytes this rank passed to the reductions, broadcasts and sends so far.
  std::uint64_t BytesContributed() const { return this->Bytes; }

private:
  vtkMultiProcessController* Controller = nullptr;
  std::uint64_t Bytes = 0;
};

} // namespace vlf
} // namespace mesolight

#endif
