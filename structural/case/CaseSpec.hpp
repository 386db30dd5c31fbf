#pragma once
// Everything a case file describes: the model, solver and output settings, probes and the
// reference the run is compared with.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "case/CaseSettings.hpp"
#include "model/Model.hpp"
#include "model/SliderSearch.hpp"
#include "solver/IntegratorKind.hpp"

namespace chute {

// The kinds of probe ([[output.probes]] kind), parsed once by the reader.
enum class ProbeKind {
  NodePosition,
  NodeVelocity,
  Slider,
  Energy,
  EnergyBalance,
  LineForce,
  MembraneStress,
  Wrinkling,
  SliderFriction,
  SkirtRadius,
  EdgeAngle,
  SupportForce,  // the force the supports put on a node set
  LinePull,      // the resultant pull of line sets' elements on a node
  LineForceMax,  // the largest axial force over line sets
  Canopy,        // a canopy's flow figures (docs/flight.md)
};
// Each kind's case-file name and the quantities its columns carry ("<probe>.<quantity>"), in
// the order the reader lists them.
struct ProbeKindInfo {
  ProbeKind kind;
  const char* name;
  std::vector<const char*> quantities;
};
const std::vector<ProbeKindInfo>& probeKinds();
const ProbeKindInfo& probeKindInfo(ProbeKind k);

struct ProbeSpec {
  std::string name;
  ProbeKind kind = ProbeKind::NodePosition;
  int node = -1;
  int node2 = -1;                  // edge_angle: the edge runs node -> node2
  int group = -1, slider = -1;     // slider probes
  int lineSet = -1, element = -1;  // line_force probes: set index and element within it
  std::vector<int> lineSets;       // line_pull, line_force_max: the line sets (all when empty)
  int membraneSet = -1;            // canopy: the membrane set with loads from the airflow
  // skirt_radius: distance of `nodes` from the axis through the centroids of axisFrom and axisTo.
  std::vector<int> nodes, axisFrom, axisTo;
  std::vector<std::string> columns() const;  // "<name>.<quantity>"
};

// The analytical solutions a run may be compared with ([reference] kind).
enum class ReferenceKind { Pulley, BeadEllipse, FreeFall, Hencky };
std::string_view referenceKindName(ReferenceKind k);

struct ReferenceSpec {
  ReferenceKind kind = ReferenceKind::Pulley;  // pulley (F13), bead_ellipse, free_fall, hencky
  int probe = -1;                              // index of the node_position probe compared
  int pulley = -1;                             // pulley: the fixed slider node
  double ropeLength = 0.0;
  int anchor1 = -1, anchor2 = -1;  // bead_ellipse: the rope's fixed ends
  // hencky: the disk's material, thickness, pressure, radius and the pressure's direction
  double E = 0.0, nu = 0.0, thickness = 0.0, pressure = 0.0, radius = 0.0;
  Vec3 direction = Vec3::UnitZ();
};

struct SolverSpec {
  AnalysisType type = AnalysisType::Dynamic;
  double dt = 1e-3, tEnd = 1.0, dtMin = 0.0, rhoInf = 0.9;
  int maxNewton = 25;
  // Most equations a run may have before it starts (docs/limits.md): a model within the node
  // limit can still take minutes per step and gigabytes in the factorisation.
  long maxEquations = 300000;
  double tolDisplacement = 0.0;  // 0: 1e-10 x model size
  bool slackTautEvents = true;   // cut steps at cable slack / taut switches
  bool sliderEvents = true;      // cut steps where a slider reaches a node (false: Bossak only)
  SliderSearch search = SliderSearch::MaterialCoordinate;
  bool reuseTangent = false;         // modified Newton within a step (NewtonSettings)
  bool symmetricPartSolver = false;  // linear_solver = "symmetric_part" (LinearSolver)
  IntegratorKind integrator = IntegratorKind::Bossak;
  double emDissipation = 0.0;  // energy_momentum's energy-decaying parameter chi (EM8)
  int emOrder = 2;             // energy_momentum: 2, or 4 by a symmetric composition (EM14)
  // central_difference only: fraction of the stable step taken, mass scaling to a target step
  // (0: off), stiffness-proportional damping beta (0: off).
  double safetyFactor = 0.9, targetDt = 0.0, stiffnessDamping = 0.0;
  double massScalingQuantile = 0.0;  // > 0: target_dt from this quantile of the nodal steps (EX8)
  int loadSteps = 1;
  // Static: load factors grow geometrically from this to 1 over loadSteps (1: equal steps).
  double initialLoadFactor = 1.0;
  // Dynamic: the largest energy gain, relative to the run's energy scale, that the energy
  // balance allows before it stops the run as unstable (solver/EnergyMonitor.hpp); 0: off.
  double energyTolerance = 0.05;
};

// Point fields a VTU frame can carry (cell fields are always written).
inline const std::vector<std::string>& vtuPointFieldNames() {
  static const std::vector<std::string> n = {"displacement", "velocity", "acceleration", "reaction",
                                             "applied_load"};
  return n;
}

// The VTU time series ([output.vtu]); written only when a case asks for it.
struct VtuSpec {
  bool write = false;
  int everySteps = 1;
  double interval = 0.0;  // > 0: output times at multiples of this instead of every N steps
  std::vector<std::string> fields;  // point fields (empty: all)
  long maxFrames = 10000;           // most frames a run writes (docs/limits.md)
};

struct OutputSpec {
  int everySteps = 1;
  double interval = 0.0;   // > 0: output times at multiples of this instead of every N steps
  long maxRows = 1000000;  // most probe rows a run writes (docs/limits.md)
  std::vector<ProbeSpec> probes;
  VtuSpec vtu;
};

struct CaseSpec {
  std::string file, name, description, units;
  // Every key the case gives (after --set), with its text and origin (case/CaseSettings.hpp).
  CaseSettings settings;
  Model model;
  SolverSpec solver;
  OutputSpec output;
  std::optional<ReferenceSpec> reference;
};

// Reads and validates a case file; overrides are "dotted.key=value" strings (--set).
// Throws CaseError naming file, line and key.
CaseSpec readCase(const std::string& file, const std::vector<std::string>& overrides = {});
// The same from the file's text; `file` names it in messages (tests, the fuzz target).
CaseSpec readCaseFromString(const std::string& text, const std::string& file,
                            const std::vector<std::string>& overrides = {});

}  // namespace chute
