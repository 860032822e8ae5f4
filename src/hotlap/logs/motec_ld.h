#pragma once
/// @file
/// Reading MoTeC `.ld` binary logs (docs/telemetry-formats.md): the header's metadata and every
/// channel's samples in its own unit at its own rate.
///
/// How to use: IsMotecLd(path) tells the format by its first four bytes (the marker 0x40) or the
/// `.ld` extension; ReadMotecLd(path) reads it; ParseMotecLd(bytes, path) reads bytes already in
/// memory (the tests corrupt them). motec_ld_table.h turns the channels into one table on one time
/// base; motec_ld_writer.h writes the format back.
///
/// The layout, little-endian throughout, is the one the public reverse-engineered descriptions
/// give (no MoTeC document is public): a 1762-byte header at 0 with the pointers to the first
/// channel descriptor and to the event block; a linked list of 124-byte channel descriptors (prev,
/// next, data pointer, sample count, type, rate, scaling, names, unit); each channel's samples
/// stored contiguously at its data pointer. Offsets of the fields are the kLd* constants below.
///
/// Pitfalls: every pointer and count comes from the file and is checked against its size before
/// use; a problem is an InputError "FILE: byte OFFSET: what" naming the offset of the field that
/// is wrong, never a crash or a read past the end.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hotlap {

/// Size of the file header, bytes.
inline constexpr uint32_t kLdHeaderSize = 1762;
/// Size of one channel descriptor, bytes.
inline constexpr uint32_t kLdChannelSize = 124;
/// Size of the event block (name, session, comment, venue pointer), bytes.
inline constexpr uint32_t kLdEventSize = 1154;
/// The value of the header's first four bytes.
inline constexpr uint32_t kLdMarker = 0x40;

/// Header field offsets (bytes from the start of the file).
inline constexpr uint32_t kLdChannelListAt = 8;      // uint32: first channel descriptor
inline constexpr uint32_t kLdDataAt = 12;            // uint32: start of the channel data
inline constexpr uint32_t kLdEventAt = 36;           // uint32: event block, 0 for none
inline constexpr uint32_t kLdDeviceSerialAt = 70;    // uint32
inline constexpr uint32_t kLdDeviceTypeAt = 74;      // 8 bytes of text
inline constexpr uint32_t kLdDeviceVersionAt = 82;   // uint16
inline constexpr uint32_t kLdChannelCountAt = 86;    // uint32
inline constexpr uint32_t kLdDateAt = 94;            // 16 bytes, "dd/mm/yyyy"
inline constexpr uint32_t kLdTimeAt = 126;           // 16 bytes, "hh:mm:ss"
inline constexpr uint32_t kLdDriverAt = 158;         // 64 bytes
inline constexpr uint32_t kLdVehicleAt = 222;        // 64 bytes
inline constexpr uint32_t kLdVenueAt = 350;          // 64 bytes
inline constexpr uint32_t kLdShortCommentAt = 1572;  // 64 bytes

/// The sample types of a channel: the descriptor's type code (0, 3 or 5 integer, 7 float) and
/// its sample size (2 or 4 bytes).
enum class LdDataType { kInt16, kInt32, kFloat16, kFloat32 };

/// "int16", "int32", "float16" or "float32".
std::string_view LdDataTypeName(LdDataType type);

/// Bytes per sample: 2 or 4.
uint32_t LdDataTypeSize(LdDataType type);

/// IEEE 754 half precision (binary16) to double: exact, subnormals, infinities and NaN included.
double HalfToDouble(uint16_t half);

/// A double to the nearest half precision value (ties to even); beyond the largest finite half
/// (65504) gives an infinity.
uint16_t DoubleToHalf(double value);

/// How a channel's stored numbers become values in its unit. The formula, as the public
/// descriptions give it and as we use it both ways:
///   value = (raw / scale * 10^(-dec) + shift) * mul.
struct LdScaling {
  int shift = 0;
  int mul = 1;
  int scale = 1;
  int dec = 0;

  /// The value in the channel's unit of a stored number.
  double Apply(double raw) const;
  /// The stored number (unrounded) of a value; `mul` and `scale` must be non-zero.
  double Invert(double value) const;
};

/// One channel of a `.ld` log.
struct LdChannel {
  /// The name (32 bytes in the file), e.g. "Ground Speed".
  std::string name;
  /// The short name (8 bytes), e.g. "Speed".
  std::string short_name;
  /// The unit (12 bytes), e.g. "km/h"; a Latin-1 degree sign is read as UTF-8 "°".
  std::string unit;
  LdDataType type = LdDataType::kFloat32;
  /// Samples per second (a uint16 in the file), at least 1.
  int rate_hz = 1;
  LdScaling scaling;
  /// The samples in the channel's unit (LdScaling::Apply of the stored numbers); a stored float
  /// that is NaN or infinite is NaN (not measured). Sample i is at time i / rate_hz.
  std::vector<double> values;
  /// Byte offset of the channel's descriptor in the file (0 for a channel to be written).
  uint32_t descriptor_at = 0;
};

/// The header's and the event block's text.
struct LdMetadata {
  std::string driver;
  std::string vehicle;
  std::string venue;
  /// The event block's name, session and comment (empty where the file has no event block).
  std::string event;
  std::string session;
  std::string event_comment;
  /// As written: "dd/mm/yyyy" and "hh:mm:ss".
  std::string date;
  std::string time;
  std::string short_comment;
  /// The logger: type (e.g. "ADL"), serial number and firmware version.
  std::string device_type;
  uint32_t device_serial = 0;
  uint16_t device_version = 0;
};

/// A `.ld` log as read.
struct LdLog {
  /// The file it was read from, for messages.
  std::filesystem::path path;
  LdMetadata metadata;
  /// The channels in the order of the descriptor list.
  std::vector<LdChannel> channels;
};

/// True if the file's first four bytes are the marker 0x40 0 0 0 (no text file starts so), or its
/// extension is `.ld` (any case: then a file too short or with the wrong marker is refused by the
/// reader with a message, not read as CSV). False for a file that cannot be read.
bool IsMotecLd(const std::filesystem::path& path);

/// Reads a `.ld` file (ParseMotecLd of its bytes).
LdLog ReadMotecLd(const std::filesystem::path& path);

/// Reads a `.ld` log from its bytes. Throws InputError "FILE: byte N: ..." (FILE is `path`, N the
/// offset of the field at fault) for: a file shorter than the header; a wrong marker; no channels;
/// a descriptor pointer inside the header or whose descriptor runs past the end; a loop in the
/// list (a descriptor met twice); a prev pointer that is not the previous descriptor; an unknown
/// type code or sample size; a rate of 0; a scale or multiplier of 0; samples that run past the
/// end (the sample count times the size computed without overflow); an event block past the end;
/// two channels of one name; a scaling that gives a non-finite value.
LdLog ParseMotecLd(std::string_view bytes, const std::filesystem::path& path);

}  // namespace hotlap
