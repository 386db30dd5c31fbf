#include "app/StopSignals.hpp"

#include <signal.h>

#include <csignal>

namespace chute {

namespace {
volatile std::sig_atomic_t gStopRequested = 0;
extern "C" void requestStop(int) {
  gStopRequested = 1;
}
}  // namespace

void installStopHandlers() {
  struct sigaction sa {};
  sa.sa_handler = requestStop;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

bool stopRequested() {
  return gStopRequested != 0;
}

void clearStopRequest() {
  gStopRequested = 0;
}

void endAtOnceOnStop() {
  struct sigaction sa {};
  sa.sa_handler = SIG_DFL;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  if (gStopRequested) ::raise(SIGTERM);
}

}  // namespace chute
