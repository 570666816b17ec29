// SPDX-License-Identifier: BSD-3-Clause
// Distribution: a light field propagated by several processes (MPI ranks), its directions split
// between them, in plain C++ (no VTK, no MPI: the transport is the abstract Reducer below; the
// VTK side implements it on vtkMultiProcessController, vtkLightFieldController.h).
//
// Who owns what. Every rank builds the same structure (scene, surfaces, directions, textures) but
// traces and holds the radiance maps of its own directions only (LightField::OwnsSubfield); the
// split (BalanceDirections) is computed identically on every rank from the scene alone.
// What is exchanged. A direction's subfield reads the unshot diffuse textures and writes
// reflected flux into texels of any surface, so each iteration every rank shoots its directions
// into a private reflected-flux buffer, and ONE sum-reduction per iteration (ReduceIteration:
// 3 floats per texel plus the energy record, 15 doubles) gives every rank the whole reflected
// flux; every rank then turns it into the same unshot and total diffuse textures. The texel
// capacities are likewise summed once after tracing. Bytes per iteration: 12 T + 120 for T
// texels, whatever the direction count (an allreduce moves about twice that per rank).
// The result equals the serial field up to the order of the float sums (the serial path sums
// its worker blocks in another order).
// Gathering at points (a movable object, Light Field Gather) is a sum over directions too: each
// rank sums its own, one reduction (GatherIrradiance).
// Mirrors (perfect specular) move radiance between directions: a line of one rank's direction
// that meets a mirror sends the mirrored radiance to the owner of the mirrored direction, which
// finds its cells (Propagation.cxx, one exchange between every pair of ranks per iteration, 36
// bytes per mirrored line); the unshot specular flux is summed so that every rank stops alike.
// Looking a mirror up (RadianceLeaving below) asks the owners of the directions around the view.
//
// Failures. A rank that throws while others wait in a collective call would hang them, so every
// step that can fail on one rank only (reading the scene, the memory budget, an abort) is run
// through Agree(): all ranks learn whether any failed and all throw DistributedError with the
// first failing rank's message.
#ifndef mesolight_vlf_Distribution_h
#define mesolight_vlf_Distribution_h

#include "LightField.h"
#include "Lookup.h" // CellInterpolation, DirectionInterpolation

#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

// The collective operations a distributed propagation needs. Every rank calls the same
// operations in the same order.
class Reducer
{
public:
  virtual ~Reducer() = default;
  virtual int Rank() const = 0;
  virtual int Size() const = 0;
  // Element-wise sum over all ranks, the result on every rank.
  virtual void SumInPlace(float* data, std::size_t n) = 0;
  virtual void SumInPlace(double* data, std::size_t n) = 0;
  // root's bytes onto every rank.
  virtual void Broadcast(std::string& bytes, int root) = 0;
  // Point to point (snapshots gathered on rank 0, one subfield at a time).
  virtual void Send(const std::string& bytes, int to) = 0;
  virtual std::string Receive(int from) = 0;
};

// One process: the serial path (sums and broadcasts leave the data as it is).
class SerialReducer : public Reducer
{
public:
  int Rank() const override { return 0; }
  int Size() const override { return 1; }
  void SumInPlace(float*, std::size_t) override {}
  void SumInPlace(double*, std::size_t) override {}
  void Broadcast(std::string&, int) override {}
  void Send(const std::string&, int) override;
  std::string Receive(int) override;
};

// Thrown on every rank when any rank failed in an agreed step (the message names the rank).
class DistributedError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// Owner rank of each direction, balancing the estimated cost: a direction costs its lines (N^2)
// plus its crossings, about N^2 / (pi/4) times the scene's area projected across it
// (sum over surfaces of area |n . d|). Greedy: most expensive direction first, to the least
// loaded rank (ties to the lowest rank); the same on every rank.
std::vector<std::uint32_t> BalanceDirections(const LightField& field, int ranks);
// Estimated cost of each direction (the weights BalanceDirections balances).
std::vector<double> DirectionCosts(const LightField& field);

// Runs step on every rank; if it threw on any rank, every rank throws DistributedError with the
// lowest failing rank's message ("rank 1 of 2: ..."). AbortedError on the failing rank becomes
// DistributedError elsewhere.
void Agree(Reducer& reducer, const std::function<void()>& step);
// The same for a failure already caught (nullptr = none).
void AgreeOnFailure(Reducer& reducer, std::exception_ptr failure);
// Whether an agreed failure has been thrown in this process (every rank knows it then). A
// program ending with an error no other rank knows of must abort the job (MPI_Abort), or the
// others wait for it forever.
bool FailureWasAgreed();

// The reduction of one iteration: the reflected flux per texel and the energy record summed over
// the ranks (the hook Propagation.cxx calls once per iteration).
void ReduceIteration(
  Reducer& reducer, std::vector<glm::vec3>& reflected, LightField::IterationEnergy& energy);
// Bytes one rank contributes to ReduceIteration.
std::uint64_t ReducedBytesPerIteration(const LightField& field);

// Irradiance at points with unit normals gathered from a distributed field (Lookup::Irradiance
// with default GatherOptions): each rank gathers every point from its own directions, one sum
// over the ranks (12 bytes per point) gives every rank the whole. Collective.
std::vector<glm::vec3> GatherIrradiance(const LightField& field,
  const std::vector<glm::vec3>& points, const std::vector<glm::vec3>& normals, Reducer& reducer);

// Radiance leaving a surface point toward a direction (Lookup::RadianceLeaving: the mirrors'
// lookup), asked of a distributed field. The owner of a direction answers for it: every rank's
// queries go to every rank (one broadcast per rank, 28 bytes a query), each rank answers all of
// them from its own directions (Lookup::RadianceLeavingShare: a weighted sum and its weight), and
// one sum over the ranks (16 bytes a query) completes every answer; each rank gets the answers to
// its own queries, which may differ from the other ranks' (a split image) or be none. Collective.
struct RadianceQuery
{
  std::uint32_t Surface = 0;
  glm::vec3 Point{ 0.0f };  // on the surface, unit-sphere coordinates
  glm::vec3 Toward{ 0.0f }; // unit direction the radiance leaves in
};
std::vector<glm::vec3> RadianceLeaving(const LightField& field,
  const std::vector<RadianceQuery>& queries, Reducer& reducer,
  CellInterpolation cells = CellInterpolation::Bilinear,
  DirectionInterpolation directions = DirectionInterpolation::Spherical);

// A field read whole (a snapshot) split among the ranks: keeps this rank's maps, frees the others.
void KeepOwnedSubfields(LightField& field, Reducer& reducer);
// A snapshot read by one rank of a distributed field (written by any number of ranks): only this
// rank's maps are kept, the others read, checked and dropped one at a time (ReadSnapshot), so
// that a resuming rank's memory is its share, not the whole field. Not collective (no message),
// but a failure must be agreed (Agree) by the caller like any step that can fail on one rank.
std::unique_ptr<LightField> ReadOwnedSubfields(
  const std::string& path, std::uint64_t memoryBudget, const Reducer& reducer);

// Subfield k's maps as bytes and back (snapshots and gathers of a distributed field).
std::string PackSubfield(const Subfield& f);
void UnpackSubfield(const std::string& bytes, Subfield& f);

// Writes the snapshot of a distributed field: rank 0 writes, taking each subfield it does not
// own from its owner just when the file needs it; the others send theirs in batches of a few MiB
// (rank 0 holds at most one batch per rank, 64 MiB in all, and the subfield being written).
// Collective; failures agreed (every rank throws when the write failed). batchBytes: 0 = that
// default; any other value the batch size (tests).
void WriteDistributedSnapshot(
  LightField& field, const std::string& path, Reducer& reducer, std::size_t batchBytes = 0);
// Gives rank 0 every subfield's maps (rank 0 then holds the complete field, as a serial one; the
// others keep their share). Collective.
void GatherSubfieldsToRoot(LightField& field, Reducer& reducer);

} // namespace vlf
} // namespace mesolight

#endif
