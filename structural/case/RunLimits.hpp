#pragma once
// How much a run may do, known before it starts and held while it runs (docs/limits.md): the
// steps (t_end over the step), the probe rows and the VTU frames. The case reader refuses what it
// can judge from the case alone (an implicit run's steps, interval-driven rows and frames:
// case/sections/Solver.cpp, Output.cpp); an explicit run's step is the stable step, known once
// the model is built: checkRunSize estimates it at the state the run starts from and refuses,
// before anything is written, a run beyond the limits, naming the key that makes it so. While
// the run goes, stopReason stops it cleanly (as diverged) where the limits would be passed: a
// stable step that shrank, rows of `every` at such steps.
#include <string>

#include "case/CaseSpec.hpp"
#include "solver/StructuralState.hpp"
#include "solver/TimeIntegrator.hpp"

namespace chute {

// Most steps a run may take (solver.t_end / step), rows and frames it may write by default
// (raised by output.max_rows, output.vtu.max_frames).
inline constexpr double kMaxRunSteps = 1e9;

// Throws CaseError ("file:line: key: reason") when the run that starts at `from` (its start, or
// a restart's state after stepsSoFar steps) would go beyond the limits. limitingNode (if given)
// receives the node whose stable step is the least, once estimated (explicit runs).
void checkRunSize(const CaseSpec& spec, TimeIntegrator& integrator, const StructuralState& from,
                  long stepsSoFar, int* limitingNode = nullptr);

// What `chute run` judges of a case before its run starts, beyond the reader: an explicit run's
// steps, rows and frames at its stable step from the case's start (checkRunSize). Throws
// CaseError naming the key; limitingNode (if given) receives the node whose stable step is the
// least (-1: none). `chute mesh parachute --case` asks it of the case it writes.
void checkRunCanStart(const CaseSpec& spec, int* limitingNode = nullptr);

// Why the run must stop after a step to s (steps taken so far, rows and frames written), or "":
// the steps left at the current step beyond the limit (explicit), or the rows or frames at
// their limits.
std::string stopReason(const CaseSpec& spec, const TimeIntegrator& integrator,
                       const StructuralState& s, long steps, long rows, long frames);

}  // namespace chute
