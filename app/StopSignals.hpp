#pragma once
// SIGINT / SIGTERM for `chute run`: installed first thing in main (a signal while the case and
// its mesh load is not lost), and read by the run after every step: it stops there, writes a
// checkpoint and leaves valid output (app/RunCase.cpp).
namespace chute {

void installStopHandlers();  // async-signal-safe handlers that only set a flag
bool stopRequested();
void clearStopRequest();  // a run that does not handle signals (tests) clears a stale one

}  // namespace chute
