#pragma once
// chute as the structural participant of a partitioned fluid-structure simulation, over a case
// file's model and the integrator it names (any of them: solver/TimeIntegrator.hpp). Shaped after
// preCICE's participant API so that a preCICE adapter is a thin file; each method names the preCICE
// call it sits next to:
//
//   preCICE (adapter)                          chute::coupling::CouplingInterface
//   setMeshVertices(mesh, coords, ids)         referenceCoordinates(), numVertices()
//   setMeshTriangles / setMeshQuads            surface().faceVertices, faceSize
//   initialize()                               (the constructor: initial acceleration, commit)
//   getMaxTimeStepSize()                       min with preferredTimeStep()
//   requiresWritingCheckpoint()                saveCheckpoint()
//   readData(mesh, "Pressure"|"Force", ...)    setFacePressures / setVertexPressures /
//                                              setVertexForces
//   (solve the time step)                      advance(dt) -> step taken
//   writeData(mesh, "Displacement", ...)       displacements(), velocities(), faceNormals(),
//                                              faceAreas()
//   advance(dt)                                (after advance(dt) here)
//   requiresReadingCheckpoint()                restoreCheckpoint()
//   isCouplingOngoing()                        time() < end of the run
//
// Pressure on the wet surface belongs to the flow solver: the case file's pressure loads on the
// wet membrane sets are dropped (those on other sets, and all other loads, stay). Without a
// coupling interface nothing changes: `chute run` uses the case file's pressure.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "case/CaseSpec.hpp"
#include "coupling/ExternalLoadTerm.hpp"
#include "coupling/WetSurface.hpp"
#include "solver/TimeIntegrator.hpp"
#include "solver/TimeStepper.hpp"
#include "terms/MembraneTerm.hpp"

namespace chute::coupling {

// The structure could not advance (a step fell below dt_min) or was used wrongly.
class CouplingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
class NoCheckpointError : public CouplingError {
 public:
  using CouplingError::CouplingError;
};
// A call made when it cannot be (initializeWithLoads after the first advance).
class CallOrderError : public CouplingError {
 public:
  using CouplingError::CouplingError;
};

// Everything a time window changes, kept in memory: the structure's state and step control with
// every term's history (StructuralSystem::saveState, the snapshot checkpoints and step
// rejection use too).
using WindowCheckpoint = SystemSnapshot;

// Counters of a coupled run so far (structural side).
struct StructuralCounters {
  long steps = 0, rejectedSteps = 0, eventRetries = 0, newtonIterations = 0;
};

class CouplingInterface {
 public:
  // spec: a dynamic case. surfaceSets: the membrane sets that are wet (empty: all membranes).
  // Throws std::invalid_argument on a static case or an unknown set.
  explicit CouplingInterface(CaseSpec spec, const std::vector<std::string>& surfaceSets = {});
  CouplingInterface(const CouplingInterface&) = delete;
  CouplingInterface& operator=(const CouplingInterface&) = delete;

  // ---- mesh (setMeshVertices, setMeshTriangles, setMeshQuads) ----
  const WetSurface& surface() const { return surface_; }
  int numVertices() const { return surface_.numVertices(); }
  int numFaces() const { return surface_.numFaces(); }
  Eigen::VectorXd referenceCoordinates() const;  // 3 per vertex: X + u0 (where the run starts)

  // ---- write data (writeData) ----
  Eigen::VectorXd currentCoordinates() const;  // 3 per vertex
  Eigen::VectorXd displacements() const;       // 3 per vertex, from referenceCoordinates()
  Eigen::VectorXd velocities() const;          // 3 per vertex
  Eigen::VectorXd accelerations() const;       // 3 per vertex
  Eigen::VectorXd faceNormals() const;         // 3 per face, unit, the direction pressure pushes
  Eigen::VectorXd faceAreas() const;           // 1 per face, current
  Eigen::VectorXd faceAreaVectors() const;     // 3 per face, |A| n
  Eigen::VectorXd faceCentres() const;         // 3 per face, mean of its vertices

  // ---- read data (readData), held for the window ----
  void setFacePressures(const Eigen::VectorXd& p) { loads_->setFacePressures(p); }
  void setVertexPressures(const Eigen::VectorXd& p) { loads_->setVertexPressures(p); }
  void setVertexForces(const Eigen::VectorXd& f) { loads_->setVertexForces(f); }
  const ExternalLoadTerm& loads() const { return *loads_; }

  // preCICE's initial data: before the first advance, the loads set now act at t = 0, and the
  // start's acceleration is recomputed under them (the constructor's is without any). Without
  // it an integrator that carries the acceleration (Bossak, generalized-alpha, central
  // differences) starts its first step from the unloaded one. Throws CouplingError after the
  // first advance.
  void initializeWithLoads();

  // ---- time (getMaxTimeStepSize, advance) ----
  double time() const { return state_.t; }
  double endTime() const { return spec_.solver.tEnd; }
  double preferredTimeStep() const { return spec_.solver.dt; }  // the case's solver.dt
  // Advances the structure over [t, t + dt] in steps of at most the case's dt (cut on rejection
  // and at slider events as `chute run` does); returns the step taken (dt). Throws
  // CouplingError if a step falls below dt_min: the state (time, positions, every term's
  // history, the step counters) is then restored to the window's start, the end of the last
  // good window, and the next advance starts from there.
  double advance(double dt);

  // ---- checkpoints (requiresWritingCheckpoint / requiresReadingCheckpoint) ----
  void saveCheckpoint();
  void restoreCheckpoint();  // throws NoCheckpointError without a saved checkpoint
  bool hasCheckpoint() const { return static_cast<bool>(checkpoint_); }
  WindowCheckpoint snapshot() const;  // the same deep copy, for comparisons

  const StructuralState& state() const { return state_; }
  const StructuralSystem& system() const { return *sys_; }
  StructuralSystem& system() { return *sys_; }
  const TimeIntegrator& integrator() const { return *integrator_; }
  const TimeStepper& stepper() const { return *stepper_; }
  // Called after every accepted step inside advance() (output of a coupled run: only the steps of
  // accepted windows are final; see CouplingDriver). Unset: nothing.
  void setStepObserver(std::function<void(const StructuralState&)> f) {
    stepObserver_ = std::move(f);
  }
  const CaseSpec& spec() const { return spec_; }
  const StructuralCounters& counters() const { return counters_; }

 private:
  CaseSpec spec_;  // owns the model the system points to
  WetSurface surface_;
  ExternalLoadTerm* loads_ = nullptr;  // owned by sys_
  std::unique_ptr<StructuralSystem> sys_;
  std::unique_ptr<TimeIntegrator> integrator_;
  std::unique_ptr<TimeStepper> stepper_;
  StructuralState state_;
  StructuralCounters counters_;
  std::unique_ptr<WindowCheckpoint> checkpoint_;
  std::function<void(const StructuralState&)> stepObserver_;
};

}  // namespace chute::coupling
