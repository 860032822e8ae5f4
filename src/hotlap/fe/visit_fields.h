#pragma once
/// @file
/// Field lists of plain structs (in the spirit of Drake's Serialize/Visit, each member listed once
/// as MuJoCo's mjxmacro.h lists them): for a struct S with members a and b,
///
///   HOTLAP_VISIT_FIELDS(S, a, b)
///
/// defines
///
///   template <SameOrConst<S> T, typename Visitor>
///   void VisitFields(T& s, Visitor&& visit) { visit("a", s.a); visit("b", s.b); }
///
/// which calls visit(name, member) for every member in the listed order, on a const struct
/// (writing) or a mutable one (reading); the name is the member's own. The FE checkpoint
/// (explicit_checkpoint.h) walks these lists, so what it saves is the struct whole;
/// tests/fe/explicit_state_test.cc checks that each list covers every byte of its struct but the
/// padding.

#include <concepts>
#include <type_traits>

namespace hotlap::fe {

/// True when T is U or const U.
template <typename T, typename U>
concept SameOrConst = std::same_as<std::remove_const_t<T>, U>;

}  // namespace hotlap::fe

// HOTLAP_FOR_EACH(m, a, b, c) expands to m(a) m(b) m(c): C++20's __VA_OPT__ ends the recursion,
// and the nested rescans (4^3 = 64) allow up to 64 arguments.
#define HOTLAP_PARENS ()
#define HOTLAP_EXPAND(...) \
  HOTLAP_EXPAND3(HOTLAP_EXPAND3(HOTLAP_EXPAND3(HOTLAP_EXPAND3(__VA_ARGS__))))
#define HOTLAP_EXPAND3(...) \
  HOTLAP_EXPAND2(HOTLAP_EXPAND2(HOTLAP_EXPAND2(HOTLAP_EXPAND2(__VA_ARGS__))))
#define HOTLAP_EXPAND2(...) \
  HOTLAP_EXPAND1(HOTLAP_EXPAND1(HOTLAP_EXPAND1(HOTLAP_EXPAND1(__VA_ARGS__))))
#define HOTLAP_EXPAND1(...) __VA_ARGS__
#define HOTLAP_FOR_EACH(macro, ...) \
  __VA_OPT__(HOTLAP_EXPAND(HOTLAP_FOR_EACH_STEP(macro, __VA_ARGS__)))
#define HOTLAP_FOR_EACH_STEP(macro, first, ...) \
  macro(first) __VA_OPT__(HOTLAP_FOR_EACH_AGAIN HOTLAP_PARENS(macro, __VA_ARGS__))
#define HOTLAP_FOR_EACH_AGAIN() HOTLAP_FOR_EACH_STEP

#define HOTLAP_VISIT_FIELD(member) visit(#member, s.member);
/// VisitFields of `Type` over its members in the order given (above).
#define HOTLAP_VISIT_FIELDS(Type, ...)                           \
  template <::hotlap::fe::SameOrConst<Type> S, typename Visitor> \
  void VisitFields(S& s, Visitor&& visit) {                      \
    HOTLAP_FOR_EACH(HOTLAP_VISIT_FIELD, __VA_ARGS__)             \
  }
