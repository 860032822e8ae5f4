#pragma once
/// @file
/// Process-wide memory tuning for programs that run Ipopt with MUMPS (the optimal-lap commands,
/// the benchmarks).

namespace hotlap::ocp {

/// Keeps glibc's malloc from returning MUMPS' large work arrays to the kernel after every
/// factorisation (by default anything above 128 kB is mmap'ed and freed, and the heap trimmed
/// above 128 kB free), which makes the kernel clear fresh pages at every Ipopt iteration. For
/// commands that end after their solves; it removes most of a solve's system time.
void KeepSolverMemory();

}  // namespace hotlap::ocp
