#pragma once
/// @file
/// Checkpoint files of long FE runs: an exact binary image of the state (doubles as their bytes,
/// so a restart continues bit for bit) behind a header that says what it belongs to.
///
/// How to use:
///
///   fe::BinaryWriter w;                  // the caller writes its state
///   solver.SaveState(w);                 // (explicit_checkpoint.h: the solver's, whole)
///   fe::WriteCheckpointFile(path, key, w.bytes());  // temporary file + rename
///   ...
///   const std::string payload = fe::ReadCheckpointFile(path, key);  // throws InputError
///   fe::BinaryReader r(payload, path.string());
///   solver.LoadState(r);
///   r.ExpectEnd();
///
/// File layout (little-endian hosts; the header records the byte order):
///   "HLFECKPT", u32 format version, u32 byte-order mark 0x01020304,
///   u64 mesh hash, u64 nodes, u64 elements, u64 configuration hash,
///   u64 payload size, payload bytes, u64 FNV-1a hash of everything before it.
/// ReadCheckpointFile refuses, with an InputError naming the file, anything that is not such a
/// file, a damaged one (size or hash wrong), another format version, and one written for another
/// mesh or configuration. A BinaryReader refuses to read past its end (InputError, "damaged"),
/// so even a payload that passed the hash check cannot make a reader overrun.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "hotlap/common/fnv1a.h"
#include "hotlap/fe/mesh.h"

namespace hotlap::fe {

/// The format version written and accepted. 2: the road's stick springs (tangential penalty
/// factor, stick model, each contact node's anchor) and the friction dissipated by their slips.
/// 3: the braking step's largest cord strain so far (and the stable step of the directional cord
/// bound, so a version-2 file's time step would not match anyway). 4: the solver's state and the
/// TyreRun's whole, each field behind its name (field_io.h), the rim's settings with them.
/// 5: the ABS wheel-speed sensor's sums over the controller period (abs/fe_abs_torque.h).
/// 6: the ABS wheel-speed filter's state (brake/wheel_speed_filter.h).
inline constexpr std::uint32_t kCheckpointVersion = 6;

using ::hotlap::Fnv1a64;  // common/fnv1a.h

/// Hash of the mesh: node positions (their bytes), connectivity, materials, cords, pressure
/// faces, rim and contact nodes.
std::uint64_t HashMesh(const Mesh& mesh);

/// What a checkpoint belongs to: its mesh and its configuration.
struct CheckpointKey {
  std::uint64_t mesh_hash = 0;
  std::uint64_t nodes = 0;
  std::uint64_t elements = 0;
  std::uint64_t config_hash = 0;  ///< chosen by the caller (e.g. the configuration files' bytes)
};

/// Appends values as their bytes.
class BinaryWriter {
 public:
  void PutU64(std::uint64_t v) { PutRaw(&v, sizeof v); }
  void PutI64(std::int64_t v) { PutRaw(&v, sizeof v); }
  void PutDouble(double v) { PutRaw(&v, sizeof v); }
  void PutVector(const Eigen::Vector3d& v) { PutRaw(v.data(), 3 * sizeof(double)); }
  /// A length (u64) then the bytes.
  void PutString(std::string_view s);
  /// A length (u64) then the doubles.
  void PutDoubles(const std::vector<double>& v);
  void PutVectors(const std::vector<Eigen::Vector3d>& v);
  /// A four-character section tag, checked on reading (catches a reader out of step).
  void PutTag(const char (&tag)[5]) { PutRaw(tag, 4); }

  const std::string& bytes() const { return bytes_; }

 private:
  void PutRaw(const void* p, size_t n) { bytes_.append(static_cast<const char*>(p), n); }
  std::string bytes_;
};

/// Reads what a BinaryWriter wrote. Every read checks the remaining size; a short or
/// inconsistent payload throws InputError("checkpoint '<name>' is damaged: ...").
class BinaryReader {
 public:
  BinaryReader(std::string_view data, std::string name) : data_(data), name_(std::move(name)) {}

  std::uint64_t GetU64();
  std::int64_t GetI64();
  double GetDouble();
  /// A finite double.
  double GetFinite();
  Eigen::Vector3d GetVector();
  std::string GetString();
  /// Doubles whose count must be `expected_size` (a mesh-sized array).
  std::vector<double> GetDoubles(size_t expected_size);
  std::vector<Eigen::Vector3d> GetVectors(size_t expected_size);
  /// Reads a length written by PutDoubles/PutVectors/PutString etc. and checks that `count`
  /// items of `item_bytes` each still fit in the payload.
  size_t GetCount(size_t item_bytes);
  void ExpectTag(const char (&tag)[5]);
  /// Throws unless everything has been read.
  void ExpectEnd() const;
  /// Throws InputError("checkpoint '<name>' is damaged: <what>").
  [[noreturn]] void Damaged(const std::string& what) const;

 private:
  void GetRaw(void* p, size_t n);
  std::string_view data_;
  size_t at_ = 0;
  std::string name_;
};

/// Writes header + payload + hash to `path` atomically (a temporary file beside it, renamed).
void WriteCheckpointFile(const std::filesystem::path& path, const CheckpointKey& key,
                         const std::string& payload);

/// Reads and checks a checkpoint file; returns its payload. Throws InputError naming the file
/// when it is missing, unreadable, not a checkpoint, damaged, of another format version, or
/// written for another mesh or configuration than `key`.
std::string ReadCheckpointFile(const std::filesystem::path& path, const CheckpointKey& key);

}  // namespace hotlap::fe
