#pragma once

#include <string>
#include <string_view>

namespace cosmems {

/// User text (a file name, a `--set` value, a node's name) made safe to echo on one line of a
/// terminal: line feed, carriage return and tab as `\n`, `\r`, `\t`, every other control
/// character (C0, DEL, and C1 such as U+009B, which some terminals take as the start of an
/// escape sequence) and every byte that is not part of valid UTF-8 as `\xNN` per byte. Printable
/// ASCII and valid UTF-8 pass unchanged, so applying it twice changes nothing more.
std::string PrintableText(std::string_view text);

}  // namespace cosmems
