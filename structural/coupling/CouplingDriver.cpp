#include "coupling/CouplingDriver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace chute::coupling {

long CouplingReport::iterations() const {
  long n = 0;
  for (const auto& w : windows) n += w.iterations;
  return n;
}
double CouplingReport::iterationsPerWindow() const {
  return windows.empty() ? 0.0 : double(iterations()) / double(windows.size());
}

InterfaceData writeInterfaceData(const CouplingInterface& s) {
  return InterfaceData{s.time(), s.velocities(), s.accelerations(), s.faceAreaVectors()};
}

namespace {
double relativeNorm(const Eigen::VectorXd& r, const Eigen::VectorXd& ref) {
  const double n = ref.norm();
  return n > 0.0 ? r.norm() / n : r.norm();
}

// The flow's answer at the structure's state at time t: loads that are not finite (a flow law
// overflowing at a huge wind, a flow solver gone wrong) end the coupled run as diverged, with
// the last good window's state, rather than reach the structure.
Eigen::VectorXd finiteAnswer(Eigen::VectorXd p, double t) {
  if (!p.allFinite())
    throw CouplingError("the flow's pressures are not finite at t = " + std::to_string(t));
  return p;
}
}  // namespace

CouplingReport runCoupled(CouplingInterface& s, const FlowParticipant& flow,
                          const CouplingSettings& cs,
                          const std::function<void(const WindowReport&)>& onWindow) {
  CouplingReport rep;
  const double window = cs.window > 0.0 ? cs.window : s.preferredTimeStep();
  const double tEnd = cs.tEnd > 0.0 ? cs.tEnd : s.endTime();
  // The first window's loads: the flow's answer to the initial state.
  Eigen::VectorXd p;
  try {
    p = finiteAnswer(flow(writeInterfaceData(s)), s.time());
  } catch (const CouplingError& e) {
    rep.converged = false;
    rep.failure = e.what();
    return rep;
  }
  // They act from t = 0: the start's acceleration is taken under them (initial data).
  if (s.time() == 0.0 && s.counters().steps == 0) {
    s.setFacePressures(p);
    s.initializeWithLoads();
  }
  // Round-off of summed windows: an end within 1e-9 of the last window (or of the time to the end,
  // for a window longer than the run) counts as reached.
  while (s.time() < tEnd - 1e-9 * std::min(window, tEnd)) {
    const double dt = std::min(window, tEnd - s.time());
    WindowReport w;
    try {
      if (cs.scheme == CouplingScheme::Explicit) {
        // Serial-explicit: loads from the state at the window's start, one structural solve.
        s.setFacePressures(p);
        s.advance(dt);
        const Eigen::VectorXd next = finiteAnswer(flow(writeInterfaceData(s)), s.time());
        w.iterations = 1;
        w.residual = relativeNorm(next - p, next);
        p = next;
      } else {
        // Serial-implicit: p_0 = the last window's converged loads (constant extrapolation);
        // p~_k = flow(structure(p_k)), r_k = p~_k - p_k, p_{k+1} = p_k + omega_k r_k.
        s.saveCheckpoint();  // requiresWritingCheckpoint
        Eigen::VectorXd rPrev;
        double omega = cs.omega;
        for (int k = 0;; ++k) {
          s.setFacePressures(p);  // readData
          s.advance(dt);
          const Eigen::VectorXd pt =
              finiteAnswer(flow(writeInterfaceData(s)), s.time());  // writeData -> flow solve
          const Eigen::VectorXd r = pt - p;
          w.iterations = k + 1;
          w.residual = relativeNorm(r, pt);
          if (w.residual <= cs.tolerance) break;  // the state stays: the window is done
          if (k + 1 >= cs.maxIterations) {
            rep.converged = false;
            rep.failure = "window ending at t = " + std::to_string(s.time()) +
                          " did not converge in " + std::to_string(cs.maxIterations) +
                          " iterations (residual " + std::to_string(w.residual) + ")";
            break;
          }
          if (cs.relaxation == Relaxation::Aitken && k > 0) {
            // Aitken's Delta^2 (Irons & Tuck; Kuettler & Wall 2008, eq. 44), vector form.
            const Eigen::VectorXd dr = r - rPrev;
            const double d2 = dr.squaredNorm();
            if (d2 > 0.0) omega = -omega * rPrev.dot(dr) / d2;
          }
          w.omegas.push_back(omega);
          p += omega * r;
          rPrev = r;
          s.restoreCheckpoint();  // requiresReadingCheckpoint
        }
      }
    } catch (const CouplingError& e) {
      rep.converged = false;
      rep.failure = e.what();
    }
    w.t = s.time();
    w.accepted = rep.converged;
    rep.windows.push_back(w);
    if (onWindow) onWindow(w);
    if (!rep.converged) break;
  }
  return rep;
}

}  // namespace chute::coupling
