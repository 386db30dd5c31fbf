#pragma once
// SIGINT / SIGTERM for `chute run`: installed first thing in main (a signal while the case and
// its mesh load is not lost), and read by the run after every step: it stops there, writes a
// checkpoint and leaves valid output (app/RunCase.cpp).
namespace chute {

void installStopHandlers();  // async-signal-safe handlers that only set a flag
bool stopRequested();
void clearStopRequest();  // a run that does not handle signals (tests) clears a stale one
// A static solve has no step to stop after: SIGINT / SIGTERM end it at once, as they end any
// program (a stop requested before this call ends it too).
void endAtOnceOnStop();

}  // namespace chute
