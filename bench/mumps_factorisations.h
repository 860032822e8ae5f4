#pragma once
// The MUMPS numerical factorisations this process has run (bench/mumps_factorisations.cc): Ipopt
// factorises its KKT system once per iteration, and again for every Hessian perturbation its
// inertia correction tries.

namespace hotlap::bench {

/// Factorisations so far (MUMPS calls with JOB 2, 4, 5 or 6).
long MumpsFactorisations();

}  // namespace hotlap::bench
