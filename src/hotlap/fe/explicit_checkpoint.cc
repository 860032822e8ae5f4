#include "hotlap/fe/explicit_checkpoint.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace hotlap::fe {

namespace {

// The largest value of each enum in the state (a reader refuses anything above).
constexpr std::uint64_t EnumMax(StickModel) { return std::uint64_t(StickModel::kViscous); }
constexpr std::uint64_t EnumMax(RimDofMode) {
  return std::uint64_t(RimDofMode::kPrescribedVelocity);
}

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
    out_.PutString(name);
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
    for (const T& t : v) Put(t);
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
    const std::string got = in_.GetString();
    if (got != name) in_.Damaged("field '" + path_ + "' expected, '" + got + "' found");
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
    const size_t n = in_.GetCount(sizeof(double));
    if (n != v.size()) {
      Bad(std::to_string(n) + " entries where this model has " + std::to_string(v.size()));
    }
    for (T& t : v) Get(t);
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
  std::string path_;  // of the field being read, e.g. "road.friction.decay_s_per_m"
};

}  // namespace

void SaveExplicitState(const ExplicitModel& model, const ExplicitState& state, BinaryWriter& out) {
  out.PutTag("SOLV");
  out.PutDouble(model.time_step_s);
  VisitFields(state, FieldWriter(out));
}

void LoadExplicitState(const ExplicitModel& model, BinaryReader& in, ExplicitState& state) {
  in.ExpectTag("SOLV");
  const double dt = in.GetDouble();
  if (dt != model.time_step_s) {
    in.Damaged("its time step " + std::to_string(dt) + " s is not this model's " +
               std::to_string(model.time_step_s) + " s");
  }
  // Read into a copy (its arrays give the sizes); only a state read whole replaces `state`.
  ExplicitState read = state;
  VisitFields(read, FieldReader(in));
  state = std::move(read);
}

}  // namespace hotlap::fe
