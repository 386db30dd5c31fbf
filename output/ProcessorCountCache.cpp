// glibc 2.36 answers get_nprocs() by reading /sys/devices/system/cpu/online on every call, and
// std::thread::hardware_concurrency() calls it; VTK 9.1 asks once per data array it writes (to
// size its SMP range computation). With a file per output time that is ~40 file opens per frame,
// most of the cost of writing a small VTU. The count cannot change during a run that matters to
// us, so the executable answers it once. Linked into executables only (symbol interposition).
#include <sys/sysinfo.h>
#include <unistd.h>

extern "C" int get_nprocs() noexcept {
  // sysconf does not go through this symbol (glibc calls its internal copy).
  static const int n = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
  return n > 0 ? n : 1;
}
