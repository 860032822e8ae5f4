#pragma once
/// @file
/// Errors that reach the user. Every problem with user input (files, fields, values, command-line
/// options) is reported by throwing InputError with a complete message that names the file, the
/// field or line/column, the value and what was allowed. Programming errors use assertions
/// elsewhere; user data is never asserted on.

#include <stdexcept>
#include <string>

namespace hotlap {

/// Bad user input. The message is complete and meant to be printed as it is.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical failure that input validation could not foresee (a diverging integration, a
/// non-finite result). The message says what and where.
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hotlap
