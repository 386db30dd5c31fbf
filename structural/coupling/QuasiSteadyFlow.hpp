#pragma once
// A simple flow model for the coupled demo and tests: quasi-steady pressure on each face from a
// stagnation pressure and the face's own motion,
//   p = q(t) - rho_air ( (1/2) C_n v_n |v_n| + L_a a_n ),
//   v_n = (v_f - w) . n,   a_n = a_f . n,   q(t) = q min(1, t / T_ramp),
// n the face's unit normal (the direction the pressure pushes), v_f and a_f the face's mean
// vertex velocity and acceleration, w the air velocity. The v_n |v_n| term is the drag of the
// air opposing the fabric's normal motion; L_a a_n is an added mass (the air a canopy carries
// along, L_a a length, rho_air L_a a mass per area): when it exceeds the fabric's mass per area a
// staggered (explicit) coupling is unstable, the classic reason parachute FSI needs sub-iterations.
//
// Two implementations of the same law:
//  - QuasiSteadyFlow: a separate participant, seeing only what the structure writes through the
//    coupling interface (vertex velocities and accelerations, face area vectors, connectivity);
//  - QuasiSteadyPressureTerm: the law as a structural load term with its consistent tangent, the
//    monolithic reference that converged implicit coupling must reproduce. It uses the
//    accelerations of the integrator's evaluation point: the end-of-step ones with rho_inf = 1
//    (Bossak alpha_m = 0), a blend of both ends otherwise.
#include <Eigen/Core>

#include "assembly/Term.hpp"
#include "coupling/WetSurface.hpp"

namespace chute::coupling {

struct QuasiSteadyFlowLaw {
  double stagnationPressure = 0.0;     // q
  double rampTime = 0.0;               // T_ramp (0: q from the start)
  double airDensity = 1.2;             // rho_air
  double normalDragCoefficient = 1.0;  // C_n
  double addedMassLength = 0.0;        // L_a
  Vec3 wind = Vec3::Zero();            // w

  double stagnation(double t) const {
    return rampTime > 0.0 && t < rampTime ? stagnationPressure * t / rampTime : stagnationPressure;
  }
  // Pressure on a face with area vector A (= |A| n), mean velocity and acceleration.
  double pressure(const Vec3& areaVector, const Vec3& faceVelocity, const Vec3& faceAcceleration,
                  double t) const;
};

// What the structure writes for the flow solver at the end of a window.
struct InterfaceData {
  double t = 0.0;
  Eigen::VectorXd velocities;       // 3 per vertex
  Eigen::VectorXd accelerations;    // 3 per vertex
  Eigen::VectorXd faceAreaVectors;  // 3 per face
};

class QuasiSteadyFlow {
 public:
  QuasiSteadyFlow(const WetSurface& surface, QuasiSteadyFlowLaw law)
      : surface_(&surface), law_(law) {}
  // Face pressures (1 per face) for the structure's state in `data`.
  Eigen::VectorXd facePressures(const InterfaceData& data) const;
  const QuasiSteadyFlowLaw& law() const { return law_; }

 private:
  const WetSurface* surface_;
  QuasiSteadyFlowLaw law_;
};

class QuasiSteadyPressureTerm final : public Term {
 public:
  QuasiSteadyPressureTerm(const WetSurface& surface, QuasiSteadyFlowLaw law)
      : surface_(&surface), law_(law) {}
  const char* name() const override { return "quasi_steady_pressure"; }
  void addCouplings(std::vector<std::vector<int>>& cliques) const override;
  void assemble(const EvalPoint& p, SystemAssembler& out) override;
  void addEnergy(const Eigen::VectorXd&, const Eigen::VectorXd&, double,
                 EnergyBreakdown&) const override {}
  bool symmetricJacobian() const override { return false; }

 private:
  template <int N>
  void assembleFace(int f, const EvalPoint& p, SystemAssembler& out) const;
  const WetSurface* surface_;
  QuasiSteadyFlowLaw law_;
};

}  // namespace chute::coupling
