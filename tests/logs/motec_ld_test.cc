// The MoTeC .ld reader: half floats, the scaling formula, the layout read against bytes put by
// hand, and corrupted or truncated files refused with the byte offset, never a crash.

#include "hotlap/logs/motec_ld.h"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/logs/motec_ld_writer.h"
#include "test_util.h"

namespace hotlap {
namespace {

using test::Contains;
using test::InputErrorOf;

constexpr uint32_t kFirstChannel = kLdHeaderSize + kLdEventSize;  // where the writer puts it

void Put32(std::string& bytes, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>((v >> (8 * i)) & 0xFF);
}
void Put16(std::string& bytes, size_t at, uint16_t v) {
  bytes[at] = static_cast<char>(v & 0xFF);
  bytes[at + 1] = static_cast<char>(v >> 8);
}
uint32_t Get32(const std::string& bytes, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i)
    v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

// Two channels: speed int16 at 10 Hz, a float32 temperature at 2 Hz.
std::string TwoChannelLog() {
  LdChannel speed;
  speed.name = "Ground Speed";
  speed.short_name = "Speed";
  speed.unit = "km/h";
  speed.type = LdDataType::kInt16;
  speed.rate_hz = 10;
  speed.scaling = {0, 1, 1, 1};  // 0.1 km/h steps
  speed.values = {100.0, 100.5, 101.0, 101.5};
  LdChannel temp;
  temp.name = "Brake Temp FL";
  temp.short_name = "BTFL";
  temp.unit = "degC";
  temp.type = LdDataType::kFloat32;
  temp.rate_hz = 2;
  temp.values = {350.0, 351.0};
  LdMetadata m;
  m.driver = "A. Driver";
  return EncodeMotecLd(m, {speed, temp});
}

std::string ErrorOf(const std::string& bytes) {
  return InputErrorOf([&] { ParseMotecLd(bytes, "log.ld"); });
}

TEST(HalfFloatTest, KnownBitPatterns) {
  EXPECT_EQ(HalfToDouble(0x3C00), 1.0);
  EXPECT_EQ(HalfToDouble(0xC000), -2.0);
  EXPECT_EQ(HalfToDouble(0x3555), 0.333251953125);
  EXPECT_EQ(HalfToDouble(0x7BFF), 65504.0);
  EXPECT_EQ(HalfToDouble(0x0001), std::ldexp(1.0, -24));  // smallest subnormal
  EXPECT_EQ(HalfToDouble(0x0400), std::ldexp(1.0, -14));  // smallest normal
  EXPECT_TRUE(std::isinf(HalfToDouble(0x7C00)));
  EXPECT_TRUE(std::isnan(HalfToDouble(0x7E00)));
  EXPECT_EQ(DoubleToHalf(1.0), 0x3C00);
  EXPECT_EQ(DoubleToHalf(-2.0), 0xC000);
  EXPECT_EQ(DoubleToHalf(65504.0), 0x7BFF);
  EXPECT_EQ(DoubleToHalf(1e6), 0x7C00);
  EXPECT_EQ(DoubleToHalf(std::ldexp(1.0, -24)), 0x0001);
  // 1 + 2^-11 lies halfway between 1 and 1 + 2^-10: ties to even gives 1.
  EXPECT_EQ(DoubleToHalf(1.0 + std::ldexp(1.0, -11)), 0x3C00);
  EXPECT_EQ(DoubleToHalf(1.0 + 3 * std::ldexp(1.0, -11)), 0x3C02);
  // Every finite half round-trips.
  for (uint32_t h = 0; h < 0x10000; ++h) {
    if (((h >> 10) & 0x1F) == 0x1F) continue;  // infinities and NaN
    ASSERT_EQ(DoubleToHalf(HalfToDouble(static_cast<uint16_t>(h))), h) << h;
  }
  EXPECT_EQ(DoubleToHalf(-0.0), 0x8000);
}

TEST(LdScalingTest, TheFormulaByHand) {
  // value = (raw / scale * 10^-dec + shift) * mul
  const LdScaling s{5, 3, 2, 1};
  EXPECT_DOUBLE_EQ(s.Apply(100.0), (100.0 / 2 * 0.1 + 5) * 3);  // 30
  EXPECT_DOUBLE_EQ(s.Apply(100.0), 30.0);
  EXPECT_DOUBLE_EQ(s.Invert(30.0), 100.0);
  const LdScaling negative_dec{0, 1, 1, -2};
  EXPECT_DOUBLE_EQ(negative_dec.Apply(7.0), 700.0);
}

TEST(MotecLdTest, ReadsTheLayoutAtTheDescribedOffsets) {
  // Bytes put at the offsets of the public descriptions, independently of the writer.
  std::string b(kLdHeaderSize + kLdChannelSize + 6, '\0');
  Put32(b, 0, 0x40);
  Put32(b, 8, kLdHeaderSize);                    // first descriptor right after the header
  Put32(b, 12, kLdHeaderSize + kLdChannelSize);  // data
  std::memcpy(&b[158], "Driver Name", 11);
  std::memcpy(&b[222], "Car 7", 5);
  std::memcpy(&b[350], "Darlington", 10);
  std::memcpy(&b[94], "14/03/2026", 10);
  std::memcpy(&b[126], "10:32:05", 8);
  std::memcpy(&b[1572], "short", 5);
  std::memcpy(&b[74], "ADL", 3);
  const size_t c = kLdHeaderSize;
  Put32(b, c + 8, kLdHeaderSize + kLdChannelSize);
  Put32(b, c + 12, 3);
  Put16(b, c + 18, 3);  // integer
  Put16(b, c + 20, 2);  // 2 bytes
  Put16(b, c + 22, 50);
  Put16(b, c + 24, static_cast<uint16_t>(-1));  // shift -1
  Put16(b, c + 26, 2);                          // mul 2
  Put16(b, c + 28, 4);                          // scale 4
  Put16(b, c + 30, 1);                          // dec 1
  std::memcpy(&b[c + 32], "Oil Temp", 8);
  std::memcpy(&b[c + 64], "OilT", 4);
  b[c + 72] = static_cast<char>(0xB0);  // Latin-1 degree sign
  b[c + 73] = 'C';
  Put16(b, c + 124, 400);
  Put16(b, c + 126, static_cast<uint16_t>(-40));
  Put16(b, c + 128, 0);
  const LdLog log = ParseMotecLd(b, "hand.ld");
  EXPECT_EQ(log.metadata.driver, "Driver Name");
  EXPECT_EQ(log.metadata.vehicle, "Car 7");
  EXPECT_EQ(log.metadata.venue, "Darlington");
  EXPECT_EQ(log.metadata.date, "14/03/2026");
  EXPECT_EQ(log.metadata.time, "10:32:05");
  EXPECT_EQ(log.metadata.short_comment, "short");
  EXPECT_EQ(log.metadata.device_type, "ADL");
  EXPECT_EQ(log.metadata.event, "");  // no event block
  ASSERT_EQ(log.channels.size(), 1u);
  const LdChannel& ch = log.channels[0];
  EXPECT_EQ(ch.name, "Oil Temp");
  EXPECT_EQ(ch.short_name, "OilT");
  EXPECT_EQ(ch.unit, "\u00B0C");
  EXPECT_EQ(ch.type, LdDataType::kInt16);
  EXPECT_EQ(ch.rate_hz, 50);
  EXPECT_EQ(ch.descriptor_at, kLdHeaderSize);
  // (raw / 4 * 0.1 - 1) * 2
  ASSERT_EQ(ch.values.size(), 3u);
  EXPECT_DOUBLE_EQ(ch.values[0], (400 / 4.0 * 0.1 - 1) * 2);  // 18
  EXPECT_DOUBLE_EQ(ch.values[1], (-40 / 4.0 * 0.1 - 1) * 2);  // -4
  EXPECT_DOUBLE_EQ(ch.values[2], -2.0);
}

TEST(MotecLdTest, TellsTheFormatByMarkerOrExtension) {
  const test::TempDir tmp;
  const auto ld = tmp.Write("a.bin", TwoChannelLog());
  const auto csv = tmp.Write("b.csv", "time_s,speed_mps\n0,1\n");
  const auto named = tmp.Write("c.LD", "not really");
  EXPECT_TRUE(IsMotecLd(ld));
  EXPECT_FALSE(IsMotecLd(csv));
  EXPECT_TRUE(IsMotecLd(named));
  EXPECT_FALSE(IsMotecLd(tmp.path() / "missing.ld"));
  EXPECT_TRUE(Contains(InputErrorOf([&] { ReadMotecLd(named); }),
                       "c.LD: byte 10: the file ends "
                       "inside the header"));
}

TEST(MotecLdTest, EveryTruncationIsRefusedWithTheOffset) {
  const std::string whole = TwoChannelLog();
  ASSERT_NO_THROW(ParseMotecLd(whole, "log.ld"));
  // Every cut point: the header, the event block, both descriptors, the samples.
  for (size_t cut = 0; cut < whole.size(); ++cut) {
    const std::string message = ErrorOf(whole.substr(0, cut));
    ASSERT_TRUE(Contains(message, "log.ld: byte ")) << "cut at " << cut;
    if (cut < kLdHeaderSize) {
      ASSERT_TRUE(Contains(message, "byte " + std::to_string(cut) +
                                        ": the file ends inside the "
                                        "header"))
          << cut;
    } else {
      ASSERT_TRUE(Contains(message, "truncated or corrupted")) << cut << ": " << message;
    }
  }
}

TEST(MotecLdTest, CorruptedPointersAndFieldsAreRefused) {
  const std::string good = TwoChannelLog();
  const uint32_t second = kFirstChannel + kLdChannelSize;
  struct Case {
    const char* what;
    size_t at;
    uint32_t value;
    int bits;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"marker", 0, 0x41, 32, "byte 0: marker 0x41"},
      {"list into the header", 8, 100, 32, "byte 8: channel descriptor pointer 100 is not inside"},
      {"list past the end", 8, 0xFFFFFFF0u, 32, "byte 8: channel descriptor pointer 4294967280"},
      {"no channels", 8, 0, 32, "byte 8: the log has no channels"},
      {"loop to itself", kFirstChannel + 4, kFirstChannel, 32,
       "points back into the list (a loop)"},
      {"next past the end", second + 4, static_cast<uint32_t>(good.size()) - 10, 32,
       "byte " + std::to_string(second + 4) + ": channel descriptor pointer"},
      {"prev wrong", second, 7, 32,
       "byte " + std::to_string(second) + ": channel descriptor at byte " + std::to_string(second) +
           ": previous pointer 7"},
      {"data past the end", kFirstChannel + 8, static_cast<uint32_t>(good.size()) - 2, 32,
       "byte " + std::to_string(kFirstChannel + 8) + ": channel 'Ground Speed'"},
      {"count overflows", kFirstChannel + 12, 0xFFFFFFFFu, 32, "4294967295 samples of int16"},
      {"unknown type code", kFirstChannel + 18, 9, 16,
       "byte " + std::to_string(kFirstChannel + 18) + ": channel descriptor at byte " +
           std::to_string(kFirstChannel) + ": unknown data type (code 9, 2 bytes"},
      {"unknown sample size", second + 20, 8, 16, "unknown data type (code 7, 8 bytes"},
      {"rate 0", kFirstChannel + 22, 0, 16, "sample rate 0 Hz"},
      {"mul 0", kFirstChannel + 26, 0, 16, "multiplier 0"},
      {"scale 0", kFirstChannel + 28, 0, 16, "scale 0"},
      {"dec absurd", kFirstChannel + 30, static_cast<uint16_t>(-400), 16, "decimal places -400"},
      {"event past the end", 36, static_cast<uint32_t>(good.size()) - 100, 32,
       "byte 36: the event block pointer"},
  };
  for (const Case& c : cases) {
    std::string bad = good;
    if (c.bits == 32) {
      Put32(bad, c.at, c.value);
    } else {
      Put16(bad, c.at, static_cast<uint16_t>(c.value));
    }
    EXPECT_TRUE(Contains(ErrorOf(bad), c.expected)) << c.what;
  }
  // A loop through two descriptors: the second's next points back at the first (prev matches).
  std::string loop = good;
  Put32(loop, second + 4, kFirstChannel);
  EXPECT_TRUE(Contains(ErrorOf(loop), "byte " + std::to_string(second + 4) +
                                          ": channel descriptor pointer " +
                                          std::to_string(kFirstChannel) + " points back"));
  // Two channels of one name.
  std::string twice = good;
  std::memcpy(&twice[second + 32], "Ground Speed\0\0", 14);
  EXPECT_TRUE(Contains(ErrorOf(twice), "channel 'Ground Speed' is also the descriptor at byte " +
                                           std::to_string(kFirstChannel)));
  // The header's channel count is not used: a wrong one is harmless.
  std::string count = good;
  Put32(count, kLdChannelCountAt, 99);
  EXPECT_EQ(ParseMotecLd(count, "log.ld").channels.size(), 2u);
  // The writer's list is what the reader followed.
  EXPECT_EQ(Get32(good, 8), kFirstChannel);
}

TEST(MotecLdTest, NonFiniteFloatSamplesAreNotMeasured) {
  LdChannel c;
  c.name = "X";
  c.type = LdDataType::kFloat32;
  c.values = {1.0, std::nan(""), 3.0};
  const LdLog log = ParseMotecLd(EncodeMotecLd({}, {c}), "nan.ld");
  ASSERT_EQ(log.channels[0].values.size(), 3u);
  EXPECT_EQ(log.channels[0].values[0], 1.0);
  EXPECT_TRUE(std::isnan(log.channels[0].values[1]));
  EXPECT_EQ(log.channels[0].values[2], 3.0);
}

}  // namespace
}  // namespace hotlap
