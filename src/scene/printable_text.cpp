#include "cosmems/scene/printable_text.hpp"

#include <cstddef>

namespace cosmems {
namespace {

void AppendHex(unsigned char byte, std::string& out) {
  constexpr char kDigits[] = "0123456789ABCDEF";
  out += "\\x";
  out += kDigits[byte >> 4];
  out += kDigits[byte & 0xF];
}

bool InRange(unsigned char byte, unsigned lower, unsigned upper) {
  return byte >= lower && byte <= upper;
}

// The length of the valid UTF-8 sequence at text[at] that starts with a byte >= 0x80, or 0 when
// it is not one (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
std::size_t SequenceLength(std::string_view text, std::size_t at) {
  const auto byte = [&](std::size_t k) {
    return at + k < text.size() ? static_cast<unsigned char>(text[at + k]) : 0;
  };
  const unsigned char lead = byte(0);
  std::size_t length = 0;
  unsigned second_lower = 0x80, second_upper = 0xBF;
  if (InRange(lead, 0xC2, 0xDF)) {
    length = 2;
  } else if (InRange(lead, 0xE0, 0xEF)) {
    length = 3;
    if (lead == 0xE0) second_lower = 0xA0;
    if (lead == 0xED) second_upper = 0x9F;
  } else if (InRange(lead, 0xF0, 0xF4)) {
    length = 4;
    if (lead == 0xF0) second_lower = 0x90;
    if (lead == 0xF4) second_upper = 0x8F;
  } else {
    return 0;
  }
  if (!InRange(byte(1), second_lower, second_upper)) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (!InRange(byte(k), 0x80, 0xBF)) return 0;
  }
  return length;
}

}  // namespace

std::string PrintableText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t at = 0; at < text.size();) {
    const auto c = static_cast<unsigned char>(text[at]);
    if (c < 0x80) {
      if (c == '\n') {
        out += "\\n";
      } else if (c == '\r') {
        out += "\\r";
      } else if (c == '\t') {
        out += "\\t";
      } else if (c < 0x20 || c == 0x7F) {
        AppendHex(c, out);
      } else {
        out += static_cast<char>(c);
      }
      ++at;
      continue;
    }
    const std::size_t length = SequenceLength(text, at);
    // U+0080 ... U+009F, the C1 controls, are the two-byte sequences C2 80 ... C2 9F.
    const bool control =
        length == 2 && c == 0xC2 && static_cast<unsigned char>(text[at + 1]) < 0xA0;
    if (length == 0 || control) {
      // An invalid byte alone; a control character byte by byte.
      const std::size_t escaped = control ? 2 : 1;
      for (std::size_t k = 0; k < escaped; ++k)
        AppendHex(static_cast<unsigned char>(text[at + k]), out);
      at += escaped;
    } else {
      out.append(text.substr(at, length));
      at += length;
    }
  }
  return out;
}

}  // namespace cosmems
