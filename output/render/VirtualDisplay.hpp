#pragma once
// Off-screen rendering without a display. Debian's VTK 9.1 renders through X (no OSMesa or EGL),
// so on a machine without DISPLAY chute starts its own Xvfb server for as long as it renders: the
// user never types xvfb-run. The server never outlives chute: it is stopped when the display goes
// out of scope (errors included) and on SIGINT / SIGTERM / SIGHUP, and the kernel sends it SIGTERM
// when chute dies any other way (a crash, SIGKILL: PR_SET_PDEATHSIG).
#include <sys/types.h>

#include <string>

namespace chute::render {

class VirtualDisplay {
 public:
  // Uses the current DISPLAY if there is one; otherwise starts Xvfb (found on PATH) and points
  // DISPLAY at it. Throws std::runtime_error with the reason if neither works.
  VirtualDisplay();
  ~VirtualDisplay();
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;
  bool started() const { return pid_ > 0; }  // whether we started a server
  const std::string& display() const { return display_; }

 private:
  std::string startServer(int wanted);
  pid_t pid_ = -1;
  std::string display_;
};

}  // namespace chute::render
