// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReducer.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace mesolight
{
namespace vlf
{

namespace
{
constexpr int MessageTag = 58311;
// MPI counts are ints: longer arrays go in pieces.
constexpr std::size_t Piece = std::size_t(1) << 28;

template <typename T>
void Sum(vtkMultiProcessController* controller, T* data, std::size_t n)
{
  std::vector<T> sent;
  for (std::size_t first = 0; first < n; first += Piece)
  {
    const std::size_t count = std::min(Piece, n - first);
    sent.assign(data + first, data + first + count);
    if (!controller->AllReduce(
          sent.data(), data + first, static_cast<vtkIdType>(count), vtkCommunicator::SUM_OP))
    {
      throw std::runtime_error("the sum over the MPI ranks failed");
    }
  }
}
} // namespace

ControllerReducer::ControllerReducer(vtkMultiProcessController* controller)
  : Controller(controller ? controller : vtkMultiProcessController::GetGlobalController())
{
}

int ControllerReducer::Rank() const
{
  return this->Controller ? this->Controller->GetLocalProcessId() : 0;
}

int ControllerReducer::Size() const
{
  return this->Controller ? this->Controller->GetNumberOfProcesses() : 1;
}

void ControllerReducer::SumInPlace(float* data, std::size_t n)
{
  if (this->Size() > 1)
  {
    Sum(this->Controller, data, n);
    this->Bytes += n * sizeof(float);
  }
}

void ControllerReducer::SumInPlace(double* data, std::size_t n)
{
  if (this->Size() > 1)
  {
    Sum(this->Controller, data, n);
    this->Bytes += n * sizeof(double);
  }
}

void ControllerReducer::Broadcast(std::string& bytes, int root)
{
  if (this->Size() <= 1)
  {
    return;
  }
  vtkIdType length = static_cast<vtkIdType>(bytes.size());
  this->Controller->Broadcast(&length, 1, root);
  bytes.resize(static_cast<std::size_t>(length));
  if (length > 0)
  {
    this->Controller->Broadcast(&bytes[0], length, root);
  }
  if (this->Rank() == root)
  {
    this->Bytes += bytes.size() + sizeof(length);
  }
}

void ControllerReducer::Send(const std::string& bytes, int to)
{
  vtkIdType length = static_cast<vtkIdType>(bytes.size());
  if (!this->Controller || !this->Controller->Send(&length, 1, to, MessageTag) ||
    (length > 0 && !this->Controller->Send(bytes.data(), length, to, MessageTag)))
  {
    throw std::runtime_error("sending to MPI rank " + std::to_string(to) + " failed");
  }
  this->Bytes += bytes.size() + sizeof(length);
}

std::string ControllerReducer::Receive(int from)
{
  vtkIdType length = 0;
  if (!this->Controller || !this->Controller->Receive(&length, 1, from, MessageTag) || length < 0)
  {
    throw std::runtime_error("receiving from MPI rank " + std::to_string(from) + " failed");
  }
  std::string bytes(static_cast<std::size_t>(length), '\0');
  if (length > 0 && !this->Controller->Receive(&bytes[0], length, from, MessageTag))
  {
    throw std::runtime_error("receiving from MPI rank " + std::to_string(from) + " failed");
  }
  return bytes;
}

} // namespace vlf
} // namespace mesolight
