#pragma once
// Probe quantities of a run (docs/output.md: probes.csv, one column per "<probe>.<quantity>");
// the file they go to is ProbeCsv.hpp.
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "OutputError.hpp"
#include "ProbeCsv.hpp"
#include "case/CaseSpec.hpp"
#include "solver/EquilibriumPoint.hpp"
#include "solver/StructuralSystem.hpp"

namespace chute {

// The energy balance's figures a row writes (solver/EnergyMonitor.hpp; NaN without one).
struct ProbeBalance {
  double work = std::numeric_limits<double>::quiet_NaN();
  double balance = std::numeric_limits<double>::quiet_NaN();
};

class ProbeSet {
 public:
  ProbeSet(const Model& model, std::vector<ProbeSpec> probes);
  std::vector<std::string> columns() const;
  // The motion (positions, velocities, sliders) at s, the forces and strains at eq, where the
  // step's equations hold (solver/EquilibriumPoint.hpp); energy: the system's energy at eq (the
  // run needs it anyway for its drift: evaluated once).
  // balance: the energy balance's work and balance (solver/EnergyMonitor.hpp; NaN without one).
  // The supports' forces are evaluated (one more assembly) only when a probe asks for them.
  std::vector<double> evaluate(StructuralSystem& sys, const StructuralState& s,
                               const EquilibriumPoint& eq, const EnergyBreakdown& energy,
                               const ProbeBalance& balance = {}) const;
  const std::vector<ProbeSpec>& probes() const { return probes_; }
  // Offset of probe p's first column in an evaluate() row.
  int columnOffset(int p) const { return offset_[p]; }

 private:
  const Model* model_;
  std::vector<ProbeSpec> probes_;
  std::vector<int> offset_;
};

}  // namespace chute
