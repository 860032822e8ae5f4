#pragma once
/// @file
/// A loop over independent items on a few threads (the corners of a fit, one per thread).

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace hotlap {

/// Runs body(i) for every i < count on up to `threads` threads (at least one); item i goes to
/// thread i mod n, so which thread runs an item does not depend on timing. Every item is run
/// even if another throws; then the error of the lowest item that threw is rethrown. `body` must
/// be safe to call for different items at once.
template <class Body>
void ParallelFor(size_t count, int threads, Body&& body) {
  const size_t n = std::min<size_t>(count, static_cast<size_t>(std::max(1, threads)));
  std::vector<std::exception_ptr> errors(count);
  std::vector<std::thread> pool;
  for (size_t t = 0; t < n; ++t) {
    pool.emplace_back([&, t] {
      for (size_t i = t; i < count; i += n) {
        try {
          body(i);
        } catch (...) {
          errors[i] = std::current_exception();
        }
      }
    });
  }
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace hotlap
