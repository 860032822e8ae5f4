#pragma once
/// @file
/// Writing MoTeC `.ld` logs in the layout motec_ld.h reads, for tests (round trips, corrupted
/// files) and for turning other logs into `.ld`.
///
/// How to use: fill an LdMetadata and LdChannels (values in each channel's unit, its type, rate
/// and scaling), then EncodeMotecLd() for the bytes or WriteMotecLd() for a file. The layout:
/// header at 0, event block right after it, the descriptors one after another, then each channel's
/// samples in descriptor order.
///
/// Pitfalls: integer channels store round(LdScaling::Invert(value)): pick the scaling so that the
/// values are representable (a value that falls outside int16/int32 is refused); float16 keeps 11
/// significant bits. NaN is written as NaN in a float channel and refused in an integer one.

#include <filesystem>
#include <string>
#include <vector>

#include "hotlap/logs/motec_ld.h"

namespace hotlap {

/// The bytes of a `.ld` log of these channels (LdChannel::descriptor_at ignored). Throws
/// std::invalid_argument naming the channel for: an empty name, text longer than its field (name
/// 32, short name 8, unit 12, metadata fields as in motec_ld.h), a rate outside 1..65535 Hz, a
/// scaling field outside int16 or a zero multiplier or scale, an integer channel's value that is
/// NaN or does not fit its type after scaling, a file over 4 GiB.
std::string EncodeMotecLd(const LdMetadata& metadata, const std::vector<LdChannel>& channels);

/// EncodeMotecLd() written to `path` atomically (WriteFileAtomically).
void WriteMotecLd(const std::filesystem::path& path, const LdMetadata& metadata,
                  const std::vector<LdChannel>& channels);

}  // namespace hotlap
