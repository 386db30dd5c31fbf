#pragma once
// The explicit step's two-node cables four at a time, each with the drag of its line set in the
// same pass (docs/formulation.md CB1): cableForceOnly's operations, its weight (F5) and
// lineDragNodeResidual's (LD1), in their order, on four cables side by side, so that each lane
// gives those functions' bits (test_cable holds them bit for bit, on every instruction set this
// machine runs). One copy is built for the baseline instruction set and one for AVX2, taken at
// run time (SimdCopies.hpp); the explicit step calls it only with AVX2 (CableTerm), as the
// membranes' lanes.
#include <Eigen/Core>
#include <cstdint>

#include "kernels/SimdCopies.hpp"
#include "kernels/UniformStrainPolyline.hpp"

namespace chute::kernels {

constexpr int kCableLanes = 4;

// Four cables' parameters, lane by lane. A lane without a cable (the last batch's) has L = 1,
// E = 0 and no drag: it gives zero forces, which are not scattered.
struct alignas(32) CableLanes {
  double L[kCableLanes], apex[kCableLanes];
  double E[kCableLanes], compressedE[kCableLanes], area[kCableLanes];
  std::int64_t tensionOnly[kCableLanes];  // all bits set for a cable (tension only)
  double weight[3][kCableLanes];          // F5's (rho A0 L / 2) g per node; zero without density
  double drag[kCableLanes];               // LD1's (1/2) rho_air Cd d; zero: no drag
  double wind[3][kCableLanes];
  int nodes[kCableLanes][2];
};

// Lane `lane` of `lanes` holds the cable (a, b) of reference length L: material mat, weight
// (rho A0 L / 2) g per node as cableGravity gives it (zero: none), drag coefficient and wind of
// its line set's drag load (coefficient zero: none).
void setCableLane(CableLanes& lanes, int lane, int a, int b, double L, const LineMaterial& mat,
                  const Eigen::Vector3d& weight, double dragCoefficient,
                  const Eigen::Vector3d& wind);
// An empty lane (see CableLanes).
void clearCableLane(CableLanes& lanes, int lane);

// The residuals of four cables: [node a, b][xyz][lane]; drag[xyz][lane], each node's drag alone
// (the energy balance's loads).
struct alignas(32) CableLaneVectors {
  double v[2][3][kCableLanes];
  double drag[3][kCableLanes];
};

// f: each lane's nodal residual at positions x and velocities v (node by node, xyz):
// cableForceOnly's force where elastic[lane] has all bits set (a cable not cut), minus
// loadFactor times its weight there, plus lineDragNodeResidual's drag with the lane's
// coefficient times dragFactor on each node (dragFactor 0: no drag). The copy useAvx2() picks.
void cableForcesAndDrag(const double* x, const double* v, const CableLanes& t, double loadFactor,
                        double dragFactor, const std::int64_t (&elastic)[kCableLanes],
                        CableLaneVectors& f);
// The two copies themselves (tests); the AVX2 one only where avx2Available() (SimdCopies.hpp).
void cableForcesAndDragBaseline(const double* x, const double* v, const CableLanes& t,
                                double loadFactor, double dragFactor,
                                const std::int64_t (&elastic)[kCableLanes], CableLaneVectors& f);
void cableForcesAndDragAvx2(const double* x, const double* v, const CableLanes& t,
                            double loadFactor, double dragFactor,
                            const std::int64_t (&elastic)[kCableLanes], CableLaneVectors& f);

}  // namespace chute::kernels
