#pragma once
// What a restart may change (docs/cli.md, "Checkpoints and restarts"): nothing of the physics or
// the output but the end time. Every key of the case is written into the checkpoint
// (CaseSpec::settings); a restart whose case gives another value for any of them, adds one or
// drops one, is refused before anything is written, naming the first key that differs.
#include <map>
#include <string>

#include "case/CaseSpec.hpp"

namespace chute {

// The keys a restart may change: the end time (the run goes on to it), the description and the
// limits (output.max_rows, output.vtu.max_frames, solver.max_equations, mesh.max_nodes,
// mesh.max_elements).
bool restartMayChange(const std::string& key);

// The settings a checkpoint holds of a case: every key's value as text.
std::map<std::string, std::string> restartFingerprint(const CaseSpec& spec);

// Throws std::runtime_error naming the first key whose value differs between the case and the
// checkpoint's (file: the checkpoint, for the message).
void checkRestartSettings(const CaseSpec& spec, const std::map<std::string, std::string>& saved,
                          const std::string& file);

}  // namespace chute
