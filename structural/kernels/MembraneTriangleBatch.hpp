#pragma once
// The explicit step's membrane triangles four at a time (docs/formulation.md M1-M3, WR1-WR3):
// membraneTriangleForce's operations, in its order, on four triangles side by side, so that each
// lane gives that function's bits (a test holds them bit for bit, on every instruction set this
// machine runs). One copy is built for the baseline instruction set and one for AVX2, taken at run
// time (SimdCopies.hpp; docs/performance.md, "Four at a time").
#include <array>
#include <cstddef>
#include <cstdint>

#include "kernels/MembraneTriangleForce.hpp"
#include "kernels/SimdCopies.hpp"
#include "kernels/TriangleFaceLoads.hpp"
#include "kernels/TriangleFlowLoads.hpp"

namespace chute::kernels {

constexpr int kTriangleLanes = 4;

// Four triangles' records (MembraneTriangleRecord), lane by lane.
struct alignas(32) MembraneTriangleLanes {
  double dN[3][2][kTriangleLanes];
  double weight[kTriangleLanes], d00[kTriangleLanes], d01[kTriangleLanes], d22[kTriangleLanes];
  double E[kTriangleLanes], nu[kTriangleLanes];
  std::int64_t noWrinkling[kTriangleLanes];  // all bits set where the set has no wrinkling
  int nodes[kTriangleLanes][3];              // each lane's nodes
};

// Lane `lane` of `lanes` holds record t of the triangle on these nodes.
void setLane(MembraneTriangleLanes& lanes, int lane, const MembraneTriangleRecord& t,
             const std::array<int, 3>& nodes);

// The forces of four triangles: [node][xyz][lane].
struct alignas(32) TriangleLaneVectors {
  double v[3][3][kTriangleLanes];
};

// f: each lane's nodal forces at the positions x (node by node, xyz), as membraneTriangleForce
// gives them; state (unless nullptr): each lane's wrinkling state. The copy useAvx2() picks. The
// explicit step calls it only with AVX2 (MembraneTerm): the baseline copy, two SSE2 operations
// for each of these, is slower than the triangles one at a time, and stays as the lanes'
// definition the tests check on any processor. The positions are read straight into the lanes:
// staged through memory by single stores, each four-lane load waited for the stores to drain
// (13 % of the copy's time, perf).
void membraneTriangleForces(const double* x, const MembraneTriangleLanes& t, TriangleLaneVectors& f,
                            WrinkleState* state);
// The two copies themselves (tests); the AVX2 one only where avx2Available() (SimdCopies.hpp).
void membraneTriangleForcesBaseline(const double* x, const MembraneTriangleLanes& t,
                                    TriangleLaneVectors& f, WrinkleState* state);
void membraneTriangleForcesAvx2(const double* x, const MembraneTriangleLanes& t,
                                TriangleLaneVectors& f, WrinkleState* state);

// Each lane's strain energy at the positions x, as membraneTriangleEnergy gives it (the energy
// balance's membranes, four at a time); the copy useAvx2() picks.
void membraneTriangleEnergies(const double* x, const MembraneTriangleLanes& t,
                              double (&energy)[kTriangleLanes]);
void membraneTriangleEnergiesBaseline(const double* x, const MembraneTriangleLanes& t,
                                      double (&energy)[kTriangleLanes]);
void membraneTriangleEnergiesAvx2(const double* x, const MembraneTriangleLanes& t,
                                  double (&energy)[kTriangleLanes]);

// Four triangles' face loads (TriangleFaceLoadParameters, P2), lane by lane.
struct alignas(32) TriangleFaceLoadLanes {
  double pressure[kTriangleLanes], drag[kTriangleLanes];
  double wind[3][kTriangleLanes];
  double steady[kTriangleLanes];
};

// membraneTriangleForces with the face loads of P2 at the velocities v in the same pass (the
// positions gathered once): f, each lane's nodal forces plus its face load, membraneTriangleForce
// then triangleFaceLoad added (their bits); loads[xyz][lane], the face load alone.
void membraneTriangleForcesAndLoads(const double* x, const double* v,
                                    const MembraneTriangleLanes& t, const TriangleFaceLoadLanes& q,
                                    TriangleLaneVectors& f, double (&loads)[3][kTriangleLanes]);
void membraneTriangleForcesAndLoadsBaseline(const double* x, const double* v,
                                            const MembraneTriangleLanes& t,
                                            const TriangleFaceLoadLanes& q, TriangleLaneVectors& f,
                                            double (&loads)[3][kTriangleLanes]);
void membraneTriangleForcesAndLoadsAvx2(const double* x, const double* v,
                                        const MembraneTriangleLanes& t,
                                        const TriangleFaceLoadLanes& q, TriangleLaneVectors& f,
                                        double (&loads)[3][kTriangleLanes]);

// FL13: which lanes of a batch are the canopy's (all bits set; a missing lane of the last batch
// is not).
struct alignas(32) TriangleFlowBatch {
  std::int64_t inFlow[kTriangleLanes];
};
// The canopy's sums over the faces lane by lane (triangle k's in lane k mod 4).
struct alignas(32) TriangleFlowAccumulators {
  double volume[kTriangleLanes] = {}, area[kTriangleLanes] = {};
  double cloth[kTriangleLanes] = {}, dCloth[kTriangleLanes] = {};
};

// membraneTriangleForces with the airflow's loads of FL13 at the velocities v in the same pass: in
// the canopy's lanes f gets each lane's nodal forces plus its load (membraneTriangleForce then
// triangleFlowLoad added: their bits) and its sums are added to acc; elsewhere the forces alone.
// loads[xyz][lane]: each lane's load alone. records[4 l .. 4 l + 3]: lane l's A / 3 then |A| / 3
// (TriangleFlowSums' nodeArea, share), written for every lane (the canopy's or not).
void membraneTriangleForcesAndFlow(const double* x, const double* v, const MembraneTriangleLanes& t,
                                   const TriangleFlowBatch& batch, const TriangleFlowParameters& q,
                                   TriangleLaneVectors& f, double (&loads)[3][kTriangleLanes],
                                   TriangleFlowAccumulators& acc, double* records);
void membraneTriangleForcesAndFlowBaseline(const double* x, const double* v,
                                           const MembraneTriangleLanes& t,
                                           const TriangleFlowBatch& batch,
                                           const TriangleFlowParameters& q, TriangleLaneVectors& f,
                                           double (&loads)[3][kTriangleLanes],
                                           TriangleFlowAccumulators& acc, double* records);
void membraneTriangleForcesAndFlowAvx2(const double* x, const double* v,
                                       const MembraneTriangleLanes& t,
                                       const TriangleFlowBatch& batch,
                                       const TriangleFlowParameters& q, TriangleLaneVectors& f,
                                       double (&loads)[3][kTriangleLanes],
                                       TriangleFlowAccumulators& acc, double* records);

// FL13's per-node shares after the pass: for each node i in [begin, end), the sum of the records
// (four doubles each) at records + at[k], k from start[i] to start[i + 1], in that order, with its
// fourth entry times perArea, written to out + stride i. One four-double addition a record
// (dispatched: the AVX2 copy where the processor has it; each copy the same bits).
void gatherTriangleRecords(const double* records, const int* start, const int* at, size_t begin,
                           size_t end, double perArea, double* out, size_t stride);
void gatherTriangleRecordsBaseline(const double* records, const int* start, const int* at,
                                   size_t begin, size_t end, double perArea, double* out,
                                   size_t stride);
void gatherTriangleRecordsAvx2(const double* records, const int* start, const int* at, size_t begin,
                               size_t end, double perArea, double* out, size_t stride);

}  // namespace chute::kernels
