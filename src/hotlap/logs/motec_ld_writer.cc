#include "hotlap/logs/motec_ld_writer.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "hotlap/common/atomic_file.h"

namespace hotlap {
namespace {

void PutU16(std::string& out, size_t at, uint32_t v) {
  out[at] = static_cast<char>(v & 0xFF);
  out[at + 1] = static_cast<char>((v >> 8) & 0xFF);
}

void PutU32(std::string& out, size_t at, uint32_t v) {
  PutU16(out, at, v & 0xFFFF);
  PutU16(out, at + 2, v >> 16);
}

// UTF-8 back to the file's Latin-1 (the reader's inverse); refuses what does not fit.
std::string ToLatin1(const std::string& text, const std::string& what) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    if (u < 0x80) {
      out += text[i];
    } else if ((u == 0xC2 || u == 0xC3) && i + 1 < text.size()) {
      out += static_cast<char>(((u & 0x03) << 6) | (static_cast<unsigned char>(text[++i]) & 0x3F));
    } else {
      throw std::invalid_argument(what + ": only Latin-1 text can be written");
    }
  }
  return out;
}

void PutText(std::string& out, size_t at, size_t width, const std::string& text,
             const std::string& what) {
  const std::string latin1 = ToLatin1(text, what);
  if (latin1.size() > width) {
    throw std::invalid_argument(
        fmt::format("{}: '{}' is longer than its {}-byte field", what, text, width));
  }
  std::memcpy(out.data() + at, latin1.data(), latin1.size());
}

void CheckInt16(int v, const std::string& what) {
  if (v < std::numeric_limits<int16_t>::min() || v > std::numeric_limits<int16_t>::max()) {
    throw std::invalid_argument(fmt::format("{}: {} does not fit an int16 field", what, v));
  }
}

void PutSample(std::string& out, size_t at, const LdChannel& c, double value, size_t i) {
  const auto fail = [&](const char* why) {
    throw std::invalid_argument(
        fmt::format("channel '{}' sample {} ({}): {}", c.name, i, value, why));
  };
  switch (c.type) {
    case LdDataType::kInt16:
    case LdDataType::kInt32: {
      if (std::isnan(value)) fail("NaN in an integer channel");
      const double raw = std::nearbyint(c.scaling.Invert(value));
      const bool wide = c.type == LdDataType::kInt32;
      const double lo = wide ? std::numeric_limits<int32_t>::min() : -32768.0;
      const double hi = wide ? std::numeric_limits<int32_t>::max() : 32767.0;
      if (!(raw >= lo && raw <= hi)) fail("out of the type's range after scaling");
      const auto r = static_cast<int64_t>(raw);
      if (wide) {
        PutU32(out, at, static_cast<uint32_t>(static_cast<int32_t>(r)));
      } else {
        PutU16(out, at, static_cast<uint16_t>(static_cast<int16_t>(r)));
      }
      return;
    }
    case LdDataType::kFloat16:
      PutU16(out, at, DoubleToHalf(c.scaling.Invert(value)));
      return;
    case LdDataType::kFloat32: {
      const auto f = static_cast<float>(c.scaling.Invert(value));
      uint32_t u = 0;
      std::memcpy(&u, &f, sizeof u);
      PutU32(out, at, u);
      return;
    }
  }
}

}  // namespace

std::string EncodeMotecLd(const LdMetadata& m, const std::vector<LdChannel>& channels) {
  const uint64_t event_at = kLdHeaderSize;
  const uint64_t list_at = event_at + kLdEventSize;
  uint64_t data_at = list_at + static_cast<uint64_t>(kLdChannelSize) * channels.size();
  uint64_t total = data_at;
  for (const LdChannel& c : channels) total += LdDataTypeSize(c.type) * c.values.size();
  if (total > std::numeric_limits<uint32_t>::max()) {
    throw std::invalid_argument("EncodeMotecLd: a .ld file holds at most 4 GiB");
  }
  std::string out(total, '\0');

  PutU32(out, 0, kLdMarker);
  PutU32(out, kLdChannelListAt, channels.empty() ? 0 : static_cast<uint32_t>(list_at));
  PutU32(out, kLdDataAt, static_cast<uint32_t>(data_at));
  PutU32(out, kLdEventAt, static_cast<uint32_t>(event_at));
  // Three fields of unknown meaning that loggers write as 1, 0x4240, 0xF; then after the version
  // 0xADB0, and 0xC81A4 before the short comment ("pro logging"): written as they are found.
  PutU16(out, 64, 1);
  PutU16(out, 66, 0x4240);
  PutU16(out, 68, 0xF);
  PutU32(out, kLdDeviceSerialAt, m.device_serial);
  PutText(out, kLdDeviceTypeAt, 8, m.device_type, "device type");
  PutU16(out, kLdDeviceVersionAt, m.device_version);
  PutU16(out, 84, 0xADB0);
  PutU32(out, kLdChannelCountAt, static_cast<uint32_t>(channels.size()));
  PutText(out, kLdDateAt, 16, m.date, "date");
  PutText(out, kLdTimeAt, 16, m.time, "time");
  PutText(out, kLdDriverAt, 64, m.driver, "driver");
  PutText(out, kLdVehicleAt, 64, m.vehicle, "vehicle");
  PutText(out, kLdVenueAt, 64, m.venue, "venue");
  PutU32(out, 1502, 0xC81A4);
  PutText(out, kLdShortCommentAt, 64, m.short_comment, "short comment");
  PutText(out, event_at, 64, m.event, "event");
  PutText(out, event_at + 64, 64, m.session, "session");
  PutText(out, event_at + 128, 1024, m.event_comment, "event comment");

  for (size_t k = 0; k < channels.size(); ++k) {
    const LdChannel& c = channels[k];
    const std::string what = fmt::format("channel {} '{}'", k, c.name);
    if (c.name.empty()) throw std::invalid_argument(what + ": no name");
    if (c.rate_hz < 1 || c.rate_hz > 65535) {
      throw std::invalid_argument(fmt::format("{}: rate {} Hz outside 1..65535", what, c.rate_hz));
    }
    CheckInt16(c.scaling.shift, what + " shift");
    CheckInt16(c.scaling.mul, what + " mul");
    CheckInt16(c.scaling.scale, what + " scale");
    CheckInt16(c.scaling.dec, what + " dec");
    if (c.scaling.mul == 0 || c.scaling.scale == 0) {
      throw std::invalid_argument(what + ": multiplier and scale must be non-zero");
    }
    const size_t at = list_at + static_cast<size_t>(kLdChannelSize) * k;
    PutU32(out, at, k == 0 ? 0 : static_cast<uint32_t>(at - kLdChannelSize));
    PutU32(out, at + 4, k + 1 == channels.size() ? 0 : static_cast<uint32_t>(at + kLdChannelSize));
    PutU32(out, at + 8, static_cast<uint32_t>(data_at));
    PutU32(out, at + 12, static_cast<uint32_t>(c.values.size()));
    PutU16(out, at + 16, 0x2EE1 + k);  // a running channel id, as loggers write it
    const bool is_float = c.type == LdDataType::kFloat16 || c.type == LdDataType::kFloat32;
    const bool is_int32 = c.type == LdDataType::kInt32;
    PutU16(out, at + 18, is_float ? 7 : (is_int32 ? 5 : 3));
    PutU16(out, at + 20, LdDataTypeSize(c.type));
    PutU16(out, at + 22, static_cast<uint32_t>(c.rate_hz));
    PutU16(out, at + 24, static_cast<uint16_t>(c.scaling.shift));
    PutU16(out, at + 26, static_cast<uint16_t>(c.scaling.mul));
    PutU16(out, at + 28, static_cast<uint16_t>(c.scaling.scale));
    PutU16(out, at + 30, static_cast<uint16_t>(c.scaling.dec));
    PutText(out, at + 32, 32, c.name, what + " name");
    PutText(out, at + 64, 8, c.short_name, what + " short name");
    PutText(out, at + 72, 12, c.unit, what + " unit");
    for (size_t i = 0; i < c.values.size(); ++i) {
      PutSample(out, data_at + LdDataTypeSize(c.type) * i, c, c.values[i], i);
    }
    data_at += LdDataTypeSize(c.type) * c.values.size();
  }
  return out;
}

void WriteMotecLd(const std::filesystem::path& path, const LdMetadata& metadata,
                  const std::vector<LdChannel>& channels) {
  const std::string bytes = EncodeMotecLd(metadata, channels);
  WriteFileAtomically(path, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace hotlap
