#pragma once
/// @file
/// SolveResults as bytes and back: what a child process sends its parent (ocp/child_solve.h) and
/// what a saved lap holds (ocp/lap_start_file.h). Binary, this machine's byte order.

#include <string>
#include <vector>

#include "hotlap/ocp/ipopt_solve.h"

namespace hotlap::ocp {

/// Every field of each result: status, message, x, multipliers, objective, iteration counts,
/// infeasibilities, seconds, barrier parameter. (Bytes of the first version, without the
/// barrier parameter, still decode.)
std::string EncodeSolveResults(const std::vector<SolveResult>& results);

/// The results EncodeSolveResults wrote. InputError on bytes that are not a whole encoding.
std::vector<SolveResult> DecodeSolveResults(const std::string& bytes);

}  // namespace hotlap::ocp
