#include "hotlap/ocp/solve_result_bytes.h"

#include <cstdint>
#include <cstring>

#include "hotlap/common/error.h"

namespace hotlap::ocp {

namespace {

// Little binary writer and reader: lengths as uint64, numbers as their bytes.
struct Writer {
  std::string out;
  template <class T>
  void Pod(const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void Text(const std::string& s) {
    Pod<uint64_t>(s.size());
    out.append(s);
  }
  void Numbers(const std::vector<double>& v) {
    Pod<uint64_t>(v.size());
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
};

struct Reader {
  const std::string& in;
  size_t at = 0;
  void Need(size_t n) {
    if (in.size() - at < n) throw InputError("solve results: the bytes end early");
  }
  template <class T>
  T Pod() {
    Need(sizeof(T));
    T v;
    std::memcpy(&v, in.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
  std::string Text() {
    const uint64_t n = Pod<uint64_t>();
    Need(n);
    std::string s = in.substr(at, n);
    at += n;
    return s;
  }
  std::vector<double> Numbers() {
    const uint64_t n = Pod<uint64_t>();
    if (n > (in.size() - at) / sizeof(double))
      throw InputError("solve results: the bytes end early");
    std::vector<double> v(n);
    if (n > 0) std::memcpy(v.data(), in.data() + at, n * sizeof(double));  // data() may be null
    at += n * sizeof(double);
    return v;
  }
};

constexpr uint64_t kMagic1 = 0x686f746c61707331;  // "hotlaps1": without barrier_mu
constexpr uint64_t kMagic = 0x686f746c61707332;   // "hotlaps2"

}  // namespace

std::string EncodeSolveResults(const std::vector<SolveResult>& results) {
  Writer w;
  w.Pod(kMagic);
  w.Pod<uint64_t>(results.size());
  for (const SolveResult& r : results) {
    w.Pod<int32_t>(static_cast<int32_t>(r.status));
    w.Text(r.message);
    w.Numbers(r.x);
    w.Numbers(r.z_lower);
    w.Numbers(r.z_upper);
    w.Numbers(r.lambda);
    w.Pod(r.objective);
    w.Pod<int32_t>(r.iterations);
    w.Pod<int32_t>(r.regularized_iterations);
    w.Pod(r.primal_infeasibility);
    w.Pod(r.dual_infeasibility);
    w.Pod(r.solve_seconds);
    w.Pod(r.barrier_mu);
  }
  return w.out;
}

std::vector<SolveResult> DecodeSolveResults(const std::string& bytes) {
  Reader r{bytes};
  const uint64_t magic = r.Pod<uint64_t>();
  if (magic != kMagic && magic != kMagic1) {
    throw InputError("solve results: not hotlap's encoding");
  }
  const uint64_t n = r.Pod<uint64_t>();
  if (n > bytes.size()) throw InputError("solve results: the bytes end early");
  std::vector<SolveResult> out(n);
  for (SolveResult& s : out) {
    const int32_t status = r.Pod<int32_t>();
    if (status < 0 || status > static_cast<int32_t>(SolveStatus::kOther)) {
      throw InputError("solve results: an unknown status");
    }
    s.status = static_cast<SolveStatus>(status);
    s.message = r.Text();
    s.x = r.Numbers();
    s.z_lower = r.Numbers();
    s.z_upper = r.Numbers();
    s.lambda = r.Numbers();
    s.objective = r.Pod<double>();
    s.iterations = r.Pod<int32_t>();
    s.regularized_iterations = r.Pod<int32_t>();
    s.primal_infeasibility = r.Pod<double>();
    s.dual_infeasibility = r.Pod<double>();
    s.solve_seconds = r.Pod<double>();
    if (magic == kMagic) s.barrier_mu = r.Pod<double>();
  }
  if (r.at != bytes.size()) throw InputError("solve results: bytes left over");
  return out;
}

}  // namespace hotlap::ocp
