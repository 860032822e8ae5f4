#include "hotlap/ocp/solver_memory.h"

#include <malloc.h>

namespace hotlap::ocp {

void KeepSolverMemory() {
  mallopt(M_MMAP_THRESHOLD, 512 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 64 << 20);
}

}  // namespace hotlap::ocp
