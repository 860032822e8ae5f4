#include "hotlap/logs/motec_ld.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/common/enum_names.h"
#include "hotlap/common/error.h"
#include "hotlap/common/read_file.h"

namespace hotlap {
namespace {

// Channel descriptor field offsets, from the descriptor's start.
constexpr uint32_t kPrevAt = 0;
constexpr uint32_t kNextAt = 4;
constexpr uint32_t kSamplesAt = 8;
constexpr uint32_t kCountAt = 12;
constexpr uint32_t kTypeCodeAt = 18;
constexpr uint32_t kTypeSizeAt = 20;
constexpr uint32_t kRateAt = 22;
constexpr uint32_t kShiftAt = 24;
constexpr uint32_t kMulAt = 26;
constexpr uint32_t kScaleAt = 28;
constexpr uint32_t kDecAt = 30;
constexpr uint32_t kNameAt = 32;
constexpr uint32_t kShortNameAt = 64;
constexpr uint32_t kUnitAt = 72;

// Bounds-checked little-endian reads from the file's bytes; every read names what it reads.
class Bytes {
 public:
  Bytes(std::string_view bytes, const std::filesystem::path& path)
      : bytes_(bytes), file_(path.string()) {}

  size_t size() const { return bytes_.size(); }

  [[noreturn]] void Fail(uint64_t at, const std::string& what) const {
    throw InputError(fmt::format("{}: byte {}: {}", file_, at, what));
  }

  // Throws unless [at, at + n) lies inside the file; `what` names the block.
  void Need(uint64_t at, uint64_t n, std::string_view what) const {
    if (at > bytes_.size() || n > bytes_.size() - at) {
      Fail(at, fmt::format("{} ({} bytes) runs past the end of the file ({} bytes): truncated or "
                           "corrupted",
                           what, n, bytes_.size()));
    }
  }

  uint16_t U16(uint64_t at) const {
    Need(at, 2, "a 16-bit field");
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + at);
    return static_cast<uint16_t>(p[0] | (p[1] << 8));
  }
  int16_t I16(uint64_t at) const { return static_cast<int16_t>(U16(at)); }
  uint32_t U32(uint64_t at) const {
    Need(at, 4, "a 32-bit field");
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + at);
    return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) |
           (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
  }

  // A fixed-width text field: up to the first NUL, trailing spaces dropped, Latin-1 decoded to
  // UTF-8 (loggers write the degree sign as the single byte 0xB0).
  std::string Text(uint64_t at, uint32_t width) const {
    Need(at, width, "a text field");
    std::string_view raw = bytes_.substr(at, width);
    raw = raw.substr(0, raw.find('\0'));
    while (!raw.empty() && (raw.back() == ' ' || raw.back() == '\t')) raw.remove_suffix(1);
    std::string out;
    for (const char c : raw) {
      const auto u = static_cast<unsigned char>(c);
      if (u < 0x80) {
        out += c;
      } else {
        out += static_cast<char>(0xC0 | (u >> 6));
        out += static_cast<char>(0x80 | (u & 0x3F));
      }
    }
    return out;
  }

 private:
  std::string_view bytes_;
  std::string file_;
};

// The sample type of a descriptor's type code and size.
LdDataType TypeOf(const Bytes& b, uint32_t at) {
  const uint16_t code = b.U16(at + kTypeCodeAt);
  const uint16_t size = b.U16(at + kTypeSizeAt);
  const bool is_int = code == 0 || code == 3 || code == 5;
  const bool is_float = code == 7;
  if ((is_int || is_float) && (size == 2 || size == 4)) {
    if (is_int) return size == 2 ? LdDataType::kInt16 : LdDataType::kInt32;
    return size == 2 ? LdDataType::kFloat16 : LdDataType::kFloat32;
  }
  b.Fail(at + kTypeCodeAt,
         fmt::format("channel descriptor at byte {}: unknown data type (code {}, {} bytes a "
                     "sample); known: codes 0, 3, 5 (integer) and 7 (float), 2 or 4 bytes",
                     at, code, size));
}

double SampleAt(std::string_view bytes, uint64_t at, LdDataType type) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + at);
  const uint32_t u16 = p[0] | (p[1] << 8);
  switch (type) {
    case LdDataType::kInt16:
      return static_cast<int16_t>(u16);
    case LdDataType::kFloat16:
      return HalfToDouble(static_cast<uint16_t>(u16));
    case LdDataType::kInt32:
    case LdDataType::kFloat32: {
      const uint32_t u =
          u16 | (static_cast<uint32_t>(p[2]) << 16) | (static_cast<uint32_t>(p[3]) << 24);
      if (type == LdDataType::kInt32) return static_cast<int32_t>(u);
      float f = 0.0F;
      std::memcpy(&f, &u, sizeof f);
      return f;
    }
  }
  return 0.0;
}

LdChannel ReadChannel(const Bytes& b, std::string_view bytes, uint32_t at) {
  LdChannel c;
  c.descriptor_at = at;
  c.name = b.Text(at + kNameAt, 32);
  c.short_name = b.Text(at + kShortNameAt, 8);
  c.unit = b.Text(at + kUnitAt, 12);
  if (c.name.empty()) {
    b.Fail(at + kNameAt, fmt::format("channel descriptor at byte {} has no name", at));
  }
  c.type = TypeOf(b, at);
  const std::string which = fmt::format("channel '{}' (descriptor at byte {})", c.name, at);
  c.rate_hz = b.U16(at + kRateAt);
  if (c.rate_hz == 0) b.Fail(at + kRateAt, which + ": sample rate 0 Hz");
  c.scaling.shift = b.I16(at + kShiftAt);
  c.scaling.mul = b.I16(at + kMulAt);
  c.scaling.scale = b.I16(at + kScaleAt);
  c.scaling.dec = b.I16(at + kDecAt);
  if (c.scaling.mul == 0) b.Fail(at + kMulAt, which + ": multiplier 0");
  if (c.scaling.scale == 0) b.Fail(at + kScaleAt, which + ": scale 0");
  if (!std::isfinite(c.scaling.Apply(1.0)) || c.scaling.Apply(1.0) == c.scaling.Apply(0.0)) {
    b.Fail(at + kDecAt,
           fmt::format("{}: decimal places {} give no usable scaling", which, c.scaling.dec));
  }

  const uint32_t data_at = b.U32(at + kSamplesAt);
  const uint32_t count = b.U32(at + kCountAt);
  // 64-bit: a count near 2^32 times 4 bytes does not wrap.
  const uint64_t length = static_cast<uint64_t>(count) * LdDataTypeSize(c.type);
  if (data_at > b.size() || length > b.size() - data_at) {
    b.Fail(at + kSamplesAt,
           fmt::format("{}: {} samples of {} at byte {} ({} bytes) run past the end of the file "
                       "({} bytes): truncated or corrupted",
                       which, count, LdDataTypeName(c.type), data_at, length, b.size()));
  }
  c.values.resize(count);
  const uint32_t size = LdDataTypeSize(c.type);
  for (uint32_t i = 0; i < count; ++i) {
    const double raw = SampleAt(bytes, data_at + static_cast<uint64_t>(i) * size, c.type);
    const double value = c.scaling.Apply(raw);
    c.values[i] = std::isfinite(value) ? value : std::nan("");
  }
  return c;
}

}  // namespace

constexpr EnumNames<LdDataType, 4> kLdDataTypes{{{{LdDataType::kInt16, "int16"},
                                                  {LdDataType::kInt32, "int32"},
                                                  {LdDataType::kFloat16, "float16"},
                                                  {LdDataType::kFloat32, "float32"}}}};

std::string_view LdDataTypeName(LdDataType type) { return kLdDataTypes.Name(type); }

uint32_t LdDataTypeSize(LdDataType type) {
  return type == LdDataType::kInt16 || type == LdDataType::kFloat16 ? 2 : 4;
}

double HalfToDouble(uint16_t half) {
  const int sign = (half >> 15) != 0 ? -1 : 1;
  const int exponent = (half >> 10) & 0x1F;
  const int mantissa = half & 0x3FF;
  if (exponent == 0) return sign * std::ldexp(mantissa, -24);  // zero and subnormals
  if (exponent == 31) {
    return mantissa == 0 ? sign * HUGE_VAL : std::nan("");
  }
  return sign * std::ldexp(mantissa + 1024, exponent - 25);
}

uint16_t DoubleToHalf(double value) {
  if (std::isnan(value)) return 0x7E00;
  const uint16_t sign = std::signbit(value) ? 0x8000 : 0;
  const double a = std::abs(value);
  if (a >= 65520.0) return sign | 0x7C00;  // rounds past 65504: infinity
  if (a < std::ldexp(1.0, -14)) {
    // Subnormal: a multiple of 2^-24, rounded to even.
    const double m = std::nearbyint(std::ldexp(a, 24));
    return static_cast<uint16_t>(sign | static_cast<uint16_t>(m));
  }
  int e = 0;
  std::frexp(a, &e);  // a = f 2^e, f in [0.5, 1)
  // The mantissa with its leading bit, 11 bits, rounded to even (nearbyint's default mode).
  double m = std::nearbyint(std::ldexp(a, 11 - e));
  if (m >= 2048.0) {
    m /= 2.0;
    ++e;
  }
  const int biased = e - 1 + 15;
  if (biased >= 31) return sign | 0x7C00;
  return static_cast<uint16_t>(sign | (biased << 10) | (static_cast<int>(m) - 1024));
}

double LdScaling::Apply(double raw) const {
  return (raw / scale * std::pow(10.0, -dec) + shift) * mul;
}

double LdScaling::Invert(double value) const {
  return (value / mul - shift) * scale / std::pow(10.0, -dec);
}

bool IsMotecLd(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  if (ext == ".ld") return true;
  char head[4] = {};
  if (!in.read(head, 4)) return false;
  return head[0] == '\x40' && head[1] == '\0' && head[2] == '\0' && head[3] == '\0';
}

LdLog ReadMotecLd(const std::filesystem::path& path) {
  const std::string bytes = ReadWholeFile(path);
  return ParseMotecLd(bytes, path);
}

LdLog ParseMotecLd(std::string_view bytes, const std::filesystem::path& path) {
  const Bytes b(bytes, path);
  if (b.size() < kLdHeaderSize) {
    b.Fail(b.size(), fmt::format("the file ends inside the header ({} of its {} bytes): truncated "
                                 "or not a MoTeC .ld log",
                                 b.size(), kLdHeaderSize));
  }
  const uint32_t marker = b.U32(0);
  if (marker != kLdMarker) {
    b.Fail(0, fmt::format("marker 0x{:x} where a MoTeC .ld log has 0x40: not a .ld log", marker));
  }
  LdLog log;
  log.path = path;
  LdMetadata& m = log.metadata;
  m.device_serial = b.U32(kLdDeviceSerialAt);
  m.device_type = b.Text(kLdDeviceTypeAt, 8);
  m.device_version = b.U16(kLdDeviceVersionAt);
  m.date = b.Text(kLdDateAt, 16);
  m.time = b.Text(kLdTimeAt, 16);
  m.driver = b.Text(kLdDriverAt, 64);
  m.vehicle = b.Text(kLdVehicleAt, 64);
  m.venue = b.Text(kLdVenueAt, 64);
  m.short_comment = b.Text(kLdShortCommentAt, 64);

  const uint32_t event_at = b.U32(kLdEventAt);
  if (event_at != 0) {
    if (event_at < kLdHeaderSize || event_at > b.size() || kLdEventSize > b.size() - event_at) {
      b.Fail(kLdEventAt, fmt::format("the event block pointer {} is not inside the file ({} "
                                     "bytes, header {}): truncated or corrupted",
                                     event_at, b.size(), kLdHeaderSize));
    }
    m.event = b.Text(event_at, 64);
    m.session = b.Text(event_at + 64, 64);
    m.event_comment = b.Text(event_at + 128, 1024);
  }

  // The descriptor list: each pointer checked before it is followed; a descriptor met twice is a
  // loop (the list is finite: at most size / 124 descriptors fit).
  uint32_t at = b.U32(kLdChannelListAt);
  uint64_t pointer_at = kLdChannelListAt;  // where the pointer being followed is stored
  if (at == 0) b.Fail(kLdChannelListAt, "the log has no channels (channel list pointer 0)");
  std::set<uint32_t> seen;
  uint32_t previous = 0;
  while (at != 0) {
    if (at < kLdHeaderSize || at > b.size() || kLdChannelSize > b.size() - at) {
      b.Fail(pointer_at, fmt::format("channel descriptor pointer {} is not inside the file ({} "
                                     "bytes, header {}): truncated or corrupted",
                                     at, b.size(), kLdHeaderSize));
    }
    if (!seen.insert(at).second) {
      b.Fail(pointer_at,
             fmt::format("channel descriptor pointer {} points back into the list (a loop)", at));
    }
    if (b.U32(at + kPrevAt) != previous) {
      b.Fail(at + kPrevAt,
             fmt::format("channel descriptor at byte {}: previous pointer {}, but the previous "
                         "descriptor is at byte {}: corrupted",
                         at, b.U32(at + kPrevAt), previous));
    }
    LdChannel channel = ReadChannel(b, bytes, at);
    for (const LdChannel& other : log.channels) {
      if (other.name == channel.name) {
        b.Fail(at + kNameAt, fmt::format("channel '{}' is also the descriptor at byte {}",
                                         channel.name, other.descriptor_at));
      }
    }
    log.channels.push_back(std::move(channel));
    previous = at;
    pointer_at = at + kNextAt;
    at = b.U32(at + kNextAt);
  }
  return log;
}

}  // namespace hotlap
