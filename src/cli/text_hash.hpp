#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace cosmems::internal {

/// "fnv1a64:" and the 64-bit FNV-1a hash of `text` in 16 hex digits: a fingerprint that tells
/// an edited text from the one recorded (a sweep's scene), not a defence against forgery.
inline std::string TextHash(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;  // the FNV offset basis
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;  // the FNV prime
  }
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash));
  return std::string("fnv1a64:") + digits;
}

}  // namespace cosmems::internal
