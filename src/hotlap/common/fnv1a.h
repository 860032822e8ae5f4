#pragma once
/// @file
/// FNV-1a, 64 bit: a fast non-cryptographic hash for telling files and runs apart (checkpoints'
/// fingerprints and integrity checks), not for security.

#include <cstdint>
#include <string_view>

namespace hotlap {

/// FNV-1a, 64 bit, of `data`, continuing from `hash` (the offset basis by default).
constexpr std::uint64_t Fnv1a64(std::string_view data, std::uint64_t hash = 0xcbf29ce484222325ULL) {
  for (const char c : data) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

}  // namespace hotlap
