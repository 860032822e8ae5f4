#pragma once
/// @file
/// Converting a parameter struct from one scalar type to another (double -> Jet to start a fit,
/// Jet -> double to read its result). A struct opts in with one static member listing its fields:
///
///   template <class Self> static auto FieldsOf(Self& s) { return std::tie(s.a, s.b); }
///
/// and gets `CastFields<U>(from, to)`. Jet -> double keeps the value only.

#include <tuple>
#include <utility>

#include "hotlap/common/scalar.h"

namespace hotlap {

/// Converts one scalar: keeps the value; derivative parts start at zero.
template <Scalar To, Scalar From>
To ScalarCast(const From& x) {
  if constexpr (std::is_same_v<To, From>) {
    return x;
  } else {
    return To(ValueOf(x));
  }
}

/// Copies every field of `from` into `to`, converting the scalar type.
template <class From, class To>
void CastFields(const From& from, To& to) {
  auto src = From::FieldsOf(from);
  auto dst = To::FieldsOf(to);
  static_assert(std::tuple_size_v<decltype(src)> == std::tuple_size_v<decltype(dst)>);
  [&]<size_t... I>(std::index_sequence<I...>) {
    ((std::get<I>(dst) = ScalarCast<std::decay_t<decltype(std::get<I>(dst))>>(std::get<I>(src))),
     ...);
  }
  (std::make_index_sequence<std::tuple_size_v<decltype(src)>>{});
}

}  // namespace hotlap
