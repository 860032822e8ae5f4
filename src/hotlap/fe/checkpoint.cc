#include "hotlap/fe/checkpoint.h"

#include <cmath>
#include <cstring>
#include <system_error>

#include "hotlap/common/atomic_file.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"

namespace hotlap::fe {

namespace {

constexpr char kMagic[8] = {'H', 'L', 'F', 'E', 'C', 'K', 'P', 'T'};
constexpr std::uint32_t kByteOrderMark = 0x01020304;
// magic, version, byte order, mesh hash, nodes, elements, config hash, payload size.
constexpr size_t kHeaderBytes = 8 + 4 + 4 + 5 * 8;
constexpr size_t kTrailerBytes = 8;

template <class T>
void Append(std::string& s, const T& v) {
  s.append(reinterpret_cast<const char*>(&v), sizeof v);
}

template <class T>
T Load(const std::string& s, size_t at) {
  T v;
  std::memcpy(&v, s.data() + at, sizeof v);
  return v;
}

}  // namespace

std::uint64_t HashMesh(const Mesh& mesh) {
  BinaryWriter w;
  w.PutVectors(mesh.nodes);
  w.PutU64(mesh.elements.size());
  for (const auto& e : mesh.elements) {
    for (int n : e) w.PutI64(n);
  }
  for (int m : mesh.element_material) w.PutI64(m);
  w.PutU64(mesh.fibres.size());
  for (const FibreLayer& f : mesh.fibres) {
    w.PutI64(f.element);
    w.PutI64(f.rebar);
    w.PutDouble(f.volume_fraction);
    w.PutVector(f.direction);
  }
  w.PutU64(mesh.pressure_faces.size());
  for (const auto& f : mesh.pressure_faces) {
    for (int n : f) w.PutI64(n);
  }
  w.PutU64(mesh.rim_nodes.size());
  for (int n : mesh.rim_nodes) w.PutI64(n);
  w.PutU64(mesh.contact_nodes.size());
  for (int n : mesh.contact_nodes) w.PutI64(n);
  return Fnv1a64(w.bytes());
}

void BinaryWriter::PutString(std::string_view s) {
  PutU64(s.size());
  bytes_.append(s.data(), s.size());
}

void BinaryWriter::PutDoubles(const std::vector<double>& v) {
  PutU64(v.size());
  PutRaw(v.data(), v.size() * sizeof(double));
}

void BinaryWriter::PutVectors(const std::vector<Eigen::Vector3d>& v) {
  PutU64(v.size());
  for (const Eigen::Vector3d& x : v) PutVector(x);
}

void BinaryReader::Damaged(const std::string& what) const {
  throw InputError("checkpoint '" + name_ + "' is damaged: " + what);
}

void BinaryReader::GetRaw(void* p, size_t n) {
  if (n > data_.size() - at_) Damaged("it ends early");
  if (n > 0) std::memcpy(p, data_.data() + at_, n);  // p may be an empty vector's null data()
  at_ += n;
}

std::uint64_t BinaryReader::GetU64() {
  std::uint64_t v;
  GetRaw(&v, sizeof v);
  return v;
}

std::int64_t BinaryReader::GetI64() {
  std::int64_t v;
  GetRaw(&v, sizeof v);
  return v;
}

double BinaryReader::GetDouble() {
  double v;
  GetRaw(&v, sizeof v);
  return v;
}

double BinaryReader::GetFinite() {
  const double v = GetDouble();
  if (!std::isfinite(v)) Damaged("a non-finite number");
  return v;
}

Eigen::Vector3d BinaryReader::GetVector() {
  Eigen::Vector3d v;
  GetRaw(v.data(), 3 * sizeof(double));
  return v;
}

size_t BinaryReader::GetCount(size_t item_bytes) {
  const std::uint64_t n = GetU64();
  if (item_bytes > 0 && n > (data_.size() - at_) / item_bytes) {
    Damaged("a length of " + std::to_string(n) + " runs past its end");
  }
  return static_cast<size_t>(n);
}

std::string BinaryReader::GetString() {
  const size_t n = GetCount(1);
  std::string s(data_.substr(at_, n));
  at_ += n;
  return s;
}

std::vector<double> BinaryReader::GetDoubles(size_t expected_size) {
  const size_t n = GetCount(sizeof(double));
  if (n != expected_size) {
    Damaged("an array of " + std::to_string(n) + " where " + std::to_string(expected_size) +
            " were expected");
  }
  std::vector<double> v(n);
  GetRaw(v.data(), n * sizeof(double));
  return v;
}

std::vector<Eigen::Vector3d> BinaryReader::GetVectors(size_t expected_size) {
  const size_t n = GetCount(3 * sizeof(double));
  if (n != expected_size) {
    Damaged("an array of " + std::to_string(n) + " where " + std::to_string(expected_size) +
            " were expected");
  }
  std::vector<Eigen::Vector3d> v(n);
  for (Eigen::Vector3d& x : v) x = GetVector();
  return v;
}

void BinaryReader::ExpectTag(const char (&tag)[5]) {
  char got[4];
  GetRaw(got, 4);
  if (std::memcmp(got, tag, 4) != 0) Damaged(std::string("section '") + tag + "' not found");
}

void BinaryReader::ExpectEnd() const {
  if (at_ != data_.size()) {
    Damaged(std::to_string(data_.size() - at_) + " bytes left over after its last section");
  }
}

void WriteCheckpointFile(const std::filesystem::path& path, const CheckpointKey& key,
                         const std::string& payload) {
  std::string s;
  s.reserve(kHeaderBytes + payload.size() + kTrailerBytes);
  s.append(kMagic, sizeof kMagic);
  Append(s, kCheckpointVersion);
  Append(s, kByteOrderMark);
  Append(s, key.mesh_hash);
  Append(s, key.nodes);
  Append(s, key.elements);
  Append(s, key.config_hash);
  Append(s, static_cast<std::uint64_t>(payload.size()));
  s += payload;
  Append(s, Fnv1a64(s));
  WriteFileAtomically(path, [&](std::ostream& out) { out.write(s.data(), s.size()); });
}

std::string ReadCheckpointFile(const std::filesystem::path& path, const CheckpointKey& key) {
  const std::string name = path.string();
  const auto fail = [&](const std::string& what) -> void {
    throw InputError("checkpoint '" + name + "' " + what);
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail("does not exist or is not a file");
  std::string s;
  try {
    s = ReadWholeFile(path);
  } catch (const InputError& e) {
    fail(std::string("cannot be read (") + e.what() + ")");
  }
  if (s.size() < sizeof kMagic || std::memcmp(s.data(), kMagic, sizeof kMagic) != 0) {
    fail("is not a hotlap FE checkpoint (no HLFECKPT header)");
  }
  if (s.size() < kHeaderBytes + kTrailerBytes) fail("is damaged: it ends inside its header");
  const auto version = Load<std::uint32_t>(s, 8);
  const auto mark = Load<std::uint32_t>(s, 12);
  if (mark != kByteOrderMark) fail("was written on a machine of another byte order");
  if (version != kCheckpointVersion) {
    fail("has format version " + std::to_string(version) + "; this build reads version " +
         std::to_string(kCheckpointVersion));
  }
  const auto payload_size = Load<std::uint64_t>(s, kHeaderBytes - 8);
  if (payload_size != s.size() - kHeaderBytes - kTrailerBytes) {
    fail("is damaged: it is " + std::to_string(s.size()) + " bytes long, its header says " +
         std::to_string(payload_size + kHeaderBytes + kTrailerBytes) + " (truncated?)");
  }
  const std::string_view body(s.data(), s.size() - kTrailerBytes);
  if (Fnv1a64(body) != Load<std::uint64_t>(s, s.size() - kTrailerBytes)) {
    fail("is damaged: its checksum does not match its contents");
  }
  const auto mesh_hash = Load<std::uint64_t>(s, 16);
  const auto nodes = Load<std::uint64_t>(s, 24);
  const auto elements = Load<std::uint64_t>(s, 32);
  const auto config_hash = Load<std::uint64_t>(s, 40);
  if (nodes != key.nodes || elements != key.elements || mesh_hash != key.mesh_hash) {
    fail("was written for another mesh (" + std::to_string(elements) + " elements, " +
         std::to_string(nodes) + " nodes; this configuration makes " +
         std::to_string(key.elements) + " elements, " + std::to_string(key.nodes) + " nodes" +
         (elements == key.elements && nodes == key.nodes ? ", placed differently" : "") + ")");
  }
  if (config_hash != key.config_hash) {
    fail(
        "was written for another configuration (the configuration files differ from the ones "
        "it was written with)");
  }
  return s.substr(kHeaderBytes, payload_size);
}

}  // namespace hotlap::fe
