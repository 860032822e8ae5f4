// The MoTeC .ld writer: a round trip through the reader for every data type with non-trivial
// shift, multiplier, scale and decimal places, the metadata, and what the writer refuses.

#include "hotlap/logs/motec_ld_writer.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hotlap/logs/motec_ld.h"
#include "test_util.h"

namespace hotlap {
namespace {

// A channel whose values are the scaling of the stored numbers `raw`, so that the round trip is
// exact: the writer inverts the scaling and rounds back to `raw`.
LdChannel Channel(const std::string& name, LdDataType type, int rate_hz, LdScaling scaling,
                  const std::vector<double>& raw) {
  LdChannel c;
  c.name = name;
  c.short_name = name.substr(0, 4);
  c.unit = "u";
  c.type = type;
  c.rate_hz = rate_hz;
  c.scaling = scaling;
  for (double r : raw) c.values.push_back(scaling.Apply(r));
  return c;
}

TEST(MotecLdWriterTest, RoundTripForEveryDataType) {
  const std::vector<LdChannel> channels = {
      Channel("i16", LdDataType::kInt16, 100, {-20, 2, 5, 1}, {-32768, -1, 0, 1, 1234, 32767}),
      Channel("i32", LdDataType::kInt32, 50, {7, -3, 4, 2},
              {-2147483648.0, -5, 0, 99, 123456789, 2147483647.0}),
      Channel("f16", LdDataType::kFloat16, 20, {1, 3, 2, -1},
              {-65504, -0.5, 0, 0.333251953125, 1, 2048}),
      Channel("f32", LdDataType::kFloat32, 10, {-4, 5, 10, 3},
              {-1.5e7, -0.1f, 0, 3.25, 1e-3f, 6.02e23f}),
  };
  LdMetadata m;
  m.driver = "A. Driver";
  m.vehicle = "Gen7 #48";
  m.venue = "Darlington";
  m.event = "Spring test";
  m.session = "Practice 1";
  m.event_comment = "a long comment, with commas";
  m.date = "14/03/2026";
  m.time = "10:32:05";
  m.short_comment = "baseline";
  m.device_type = "ADL";
  m.device_serial = 8004;
  m.device_version = 420;
  const std::string bytes = EncodeMotecLd(m, channels);
  const LdLog log = ParseMotecLd(bytes, "rt.ld");

  EXPECT_EQ(log.metadata.driver, m.driver);
  EXPECT_EQ(log.metadata.vehicle, m.vehicle);
  EXPECT_EQ(log.metadata.venue, m.venue);
  EXPECT_EQ(log.metadata.event, m.event);
  EXPECT_EQ(log.metadata.session, m.session);
  EXPECT_EQ(log.metadata.event_comment, m.event_comment);
  EXPECT_EQ(log.metadata.date, m.date);
  EXPECT_EQ(log.metadata.time, m.time);
  EXPECT_EQ(log.metadata.short_comment, m.short_comment);
  EXPECT_EQ(log.metadata.device_type, m.device_type);
  EXPECT_EQ(log.metadata.device_serial, m.device_serial);
  EXPECT_EQ(log.metadata.device_version, m.device_version);

  ASSERT_EQ(log.channels.size(), channels.size());
  for (size_t k = 0; k < channels.size(); ++k) {
    const LdChannel& want = channels[k];
    const LdChannel& got = log.channels[k];
    SCOPED_TRACE(want.name);
    EXPECT_EQ(got.name, want.name);
    EXPECT_EQ(got.short_name, want.short_name);
    EXPECT_EQ(got.unit, want.unit);
    EXPECT_EQ(got.type, want.type);
    EXPECT_EQ(got.rate_hz, want.rate_hz);
    EXPECT_EQ(got.scaling.shift, want.scaling.shift);
    EXPECT_EQ(got.scaling.mul, want.scaling.mul);
    EXPECT_EQ(got.scaling.scale, want.scaling.scale);
    EXPECT_EQ(got.scaling.dec, want.scaling.dec);
    ASSERT_EQ(got.values.size(), want.values.size());
    for (size_t i = 0; i < want.values.size(); ++i) {
      EXPECT_EQ(got.values[i], want.values[i]) << "sample " << i;
    }
  }
  // The samples follow the descriptors, in order, at each type's size.
  const size_t data_at = kLdHeaderSize + kLdEventSize + 4 * kLdChannelSize;
  EXPECT_EQ(bytes.size(), data_at + 6 * (2 + 4 + 2 + 4));
}

TEST(MotecLdWriterTest, ValuesBetweenStepsRoundToTheNearestStoredNumber) {
  LdChannel c;
  c.name = "Speed";
  c.type = LdDataType::kInt16;
  c.scaling = {0, 1, 1, 1};  // 0.1 steps
  c.values = {12.34, -12.36, 0.04};
  const LdLog log = ParseMotecLd(EncodeMotecLd({}, {c}), "r.ld");
  EXPECT_DOUBLE_EQ(log.channels[0].values[0], 12.3);
  EXPECT_DOUBLE_EQ(log.channels[0].values[1], -12.4);
  EXPECT_DOUBLE_EQ(log.channels[0].values[2], 0.0);
  c.type = LdDataType::kFloat16;
  c.scaling = {};
  c.values = {300.3};  // float16 keeps 11 significant bits: 300.25
  EXPECT_EQ(ParseMotecLd(EncodeMotecLd({}, {c}), "r.ld").channels[0].values[0], 300.25);
}

TEST(MotecLdWriterTest, DegreeSignIsWrittenAsLatin1AndReadBack) {
  LdChannel c;
  c.name = "Brake Temp FL";
  c.unit = "\u00B0C";
  c.values = {1.0};
  const std::string bytes = EncodeMotecLd({}, {c});
  EXPECT_EQ(static_cast<unsigned char>(bytes[kLdHeaderSize + kLdEventSize + 72]), 0xB0);
  EXPECT_EQ(ParseMotecLd(bytes, "d.ld").channels[0].unit, "\u00B0C");
}

TEST(MotecLdWriterTest, RefusesWhatTheFormatCannotHold) {
  LdChannel c;
  c.name = "X";
  c.type = LdDataType::kInt16;
  c.values = {40000.0};
  EXPECT_THROW(EncodeMotecLd({}, {c}), std::invalid_argument);  // past int16
  c.values = {std::nan("")};
  EXPECT_THROW(EncodeMotecLd({}, {c}), std::invalid_argument);  // NaN in an integer channel
  c.values = {1.0};
  c.name = std::string(33, 'n');
  EXPECT_THROW(EncodeMotecLd({}, {c}), std::invalid_argument);  // name past 32 bytes
  c.name = "";
  EXPECT_THROW(EncodeMotecLd({}, {c}), std::invalid_argument);
  c.name = "X";
  c.rate_hz = 0;
  EXPECT_THROW(EncodeMotecLd({}, {c}), std::invalid_argument);
  c.rate_hz = 1;
  c.scaling.scale = 0;
  EXPECT_THROW(EncodeMotecLd({}, {c}), std::invalid_argument);
  c.scaling.scale = 40000;
  EXPECT_THROW(EncodeMotecLd({}, {c}), std::invalid_argument);
}

TEST(MotecLdWriterTest, WritesAFileThatReadsBack) {
  const test::TempDir tmp;
  LdChannel c;
  c.name = "X";
  c.values = {1.0, 2.0};
  WriteMotecLd(tmp.path() / "x.ld", {}, {c});
  EXPECT_EQ(ReadMotecLd(tmp.path() / "x.ld").channels[0].values, c.values);
}

}  // namespace
}  // namespace hotlap
