// Lets valgrind run anything linked with Debian's Highway (libhwy 1.0.3).
//
// libhwy.so measures its timer's resolution while it is loaded (a static initializer), with RDTSCP. On
// a machine whose CPUID hides RDTSCP (this project's VMs: the instruction runs, but the flag is not
// shown), valgrind follows CPUID, takes RDTSCP for an illegal instruction, and the program dies of
// SIGILL before main. Preloaded (LD_PRELOAD), this definition takes the place of libhwy's exported one,
// so the initializer never executes RDTSCP. Only Highway's nanobenchmark reads the value; rast does not.
// Built and preloaded by scripts/ab-bench; the version script gives the symbol libhwy's version, HWY_0.
#include <cstdint>

namespace hwy::platform {

std::uint64_t TimerResolution() { return 1; }

}  // namespace hwy::platform
