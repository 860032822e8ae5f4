// Counts MUMPS factorisations by interposing dmumps_c: Ipopt's shared library calls dmumps_c
// through the dynamic linker, which finds this definition first when the executable exports it
// (CMakeLists.txt links ocp_bench with --export-dynamic-symbol=dmumps_c); it counts and calls
// the real one (the next definition, in Debian's libdmumps_seq). Benchmarks only.

#include "mumps_factorisations.h"

#include <dlfcn.h>
#include <dmumps_c.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace {

std::atomic<long> factorisations{0};

}  // namespace

extern "C" void dmumps_c(DMUMPS_STRUC_C* id) {
  using Fn = void (*)(DMUMPS_STRUC_C*);
  static const Fn real = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, "dmumps_c"));
  if (real == nullptr) {
    std::fprintf(stderr, "mumps_factorisations: no dmumps_c to forward to\n");
    std::abort();
  }
  const int job = id->job;
  if (job == 2 || job == 4 || job == 5 || job == 6) ++factorisations;
  real(id);
}

namespace hotlap::bench {

long MumpsFactorisations() { return factorisations.load(); }

}  // namespace hotlap::bench
