#pragma once
/// @file
/// Field lists of plain structs (in the spirit of Drake's Serialize/Visit): for a struct S,
///
///   template <SameOrConst<S> T, typename Visitor>
///   void VisitFields(T& s, Visitor&& visit) { visit("a", s.a); visit("b", s.b); }
///
/// calls visit(name, member) for every member in a fixed order, on a const struct (writing) or a
/// mutable one (reading). The FE checkpoint (explicit_checkpoint.h) walks these lists, so what it
/// saves is the struct whole; tests/fe/explicit_state_test.cc checks that each list covers every
/// byte of its struct but the padding.

#include <concepts>
#include <type_traits>

namespace hotlap::fe {

/// True when T is U or const U.
template <typename T, typename U>
concept SameOrConst = std::same_as<std::remove_const_t<T>, U>;

}  // namespace hotlap::fe
