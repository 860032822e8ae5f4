#pragma once
/// @file
/// Checkpoint I/O of structs with field lists (visit_fields.h): PutFields writes every field a
/// struct's VisitFields lists, each behind its name (but inside a vector's items) (numbers as their
/// bytes, flags and enums as u64, arrays as their elements, vectors as a count and their elements,
/// an optional as a flag and its value, a struct as its fields); GetFields reads it back, checking
/// each name, each value's range (finite doubles, flags 0 or 1, enums up to EnumMax, counts not
/// negative) and each vector's size against the struct read into (an empty vector takes the file's
/// size, a history; a sized one, a model's node array, must match). Errors throw InputError via the
/// reader, naming the field ("road.friction.decay_s_per_m"). Enums need an EnumMax(E) overload
/// beside them.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "hotlap/fe/checkpoint.h"
#include "hotlap/fe/visit_fields.h"

namespace hotlap::fe {
namespace internal {

template <typename T, typename Visitor>
concept HasFields = requires(T& t, Visitor& v) {
  VisitFields(t, v);
};

// Writes each field's name, then its value: numbers as their bytes, flags and enums as u64,
// arrays as their elements, vectors as a count and their elements, an optional as a flag and its
// value, a struct as its fields.
class FieldWriter {
 public:
  explicit FieldWriter(BinaryWriter& out) : out_(out) {}

  template <typename T>
  void operator()(const char* name, const T& value) {
    if (in_vector_ == 0) out_.PutString(name);  // not repeated for every item of a vector
    Put(value);
  }

 private:
  void Put(double d) { out_.PutDouble(d); }
  void Put(std::int64_t i) { out_.PutI64(i); }
  void Put(bool b) { out_.PutU64(b ? 1 : 0); }
  void Put(char c) { out_.PutU64(static_cast<unsigned char>(c)); }
  template <typename E>
  requires std::is_enum_v<E>
  void Put(E e) { out_.PutU64(static_cast<std::uint64_t>(e)); }
  void Put(const Eigen::Vector3d& v) { out_.PutVector(v); }
  void Put(const Eigen::Vector2d& v) {
    out_.PutDouble(v.x());
    out_.PutDouble(v.y());
  }
  template <typename T, size_t N>
  void Put(const std::array<T, N>& a) {
    for (const T& t : a) Put(t);
  }
  template <typename T>
  void Put(const std::vector<T>& v) {
    out_.PutU64(v.size());
    ++in_vector_;
    for (const T& t : v) Put(t);
    --in_vector_;
  }
  template <typename T>
  void Put(const std::optional<T>& o) {
    out_.PutU64(o ? 1 : 0);
    if (o) Put(*o);
  }
  template <typename T>
  requires HasFields<const T, FieldWriter>
  void Put(const T& s) { VisitFields(s, *this); }

  BinaryWriter& out_;
  int in_vector_ = 0;  // > 0 inside a vector's items
};

// Reads what FieldWriter wrote, checking each field's name, each vector's size against the
// state read into, and each value's range.
class FieldReader {
 public:
  explicit FieldReader(BinaryReader& in) : in_(in) {}

  template <typename T>
  void operator()(const char* name, T& value) {
    const size_t outer = path_.size();
    path_ += path_.empty() ? name : "." + std::string(name);
    if (in_vector_ == 0) {
      const std::string got = in_.GetString();
      if (got != name) in_.Damaged("field '" + path_ + "' expected, '" + got + "' found");
    }
    Get(value);
    path_.resize(outer);
  }

 private:
  [[noreturn]] void Bad(const std::string& what) { in_.Damaged(what + " in '" + path_ + "'"); }
  void Get(double& d) { d = in_.GetFinite(); }
  void Get(std::int64_t& i) {
    i = in_.GetI64();
    if (i < 0) Bad("a negative count");
  }
  std::uint64_t Flag() {
    const std::uint64_t f = in_.GetU64();
    if (f > 1) Bad("a flag out of range");
    return f;
  }
  void Get(bool& b) { b = Flag() != 0; }
  void Get(char& c) { c = static_cast<char>(Flag()); }
  template <typename E>
  requires std::is_enum_v<E>
  void Get(E& e) {
    const std::uint64_t u = in_.GetU64();
    if (u > EnumMax(E{})) Bad("a value out of range");
    e = static_cast<E>(u);
  }
  void Get(Eigen::Vector3d& v) {
    for (int k = 0; k < 3; ++k) v(k) = in_.GetFinite();
  }
  void Get(Eigen::Vector2d& v) {
    for (int k = 0; k < 2; ++k) v(k) = in_.GetFinite();
  }
  template <typename T, size_t N>
  void Get(std::array<T, N>& a) {
    for (T& t : a) Get(t);
  }
  template <typename T>
  void Get(std::vector<T>& v) {
    const size_t n = in_.GetCount(sizeof(double));  // every item holds at least 8 bytes
    if (v.empty()) {
      v.resize(n);
    } else if (n != v.size()) {
      Bad(std::to_string(n) + " entries where this model has " + std::to_string(v.size()));
    }
    ++in_vector_;
    for (T& t : v) Get(t);
    --in_vector_;
  }
  template <typename T>
  void Get(std::optional<T>& o) {
    if (Flag() == 0) {
      o.reset();
      return;
    }
    if (!o) o.emplace();
    Get(*o);
  }
  template <typename T>
  requires HasFields<T, FieldReader>
  void Get(T& s) { VisitFields(s, *this); }

  BinaryReader& in_;
  int in_vector_ = 0;  // > 0 inside a vector's items (their fields have no names)
  std::string path_;   // of the field being read, e.g. "road.friction.decay_s_per_m"
};

}  // namespace internal

/// Writes every field of `value` (VisitFields) to `out`.
template <typename T>
void PutFields(BinaryWriter& out, const T& value) {
  VisitFields(value, internal::FieldWriter(out));
}

/// Reads what PutFields wrote into `value` (see the file comment). On an error `value` may be
/// partly changed: read into a copy when that matters.
template <typename T>
void GetFields(BinaryReader& in, T& value) {
  VisitFields(value, internal::FieldReader(in));
}

}  // namespace hotlap::fe
