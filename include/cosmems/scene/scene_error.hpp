#pragma once

#include <stdexcept>
#include <string>

namespace cosmems {

/// Invalid scene input. what() is one line, "SOURCE: KEY = VALUE: REASON", where SOURCE is the
/// scene file as given, the embedded scene's name or "--set", KEY the dotted key and VALUE the
/// offending value spelled as TOML (`"foo"`, `-2e-06`, `[0, 1]`). A missing key has no value
/// ("SOURCE: KEY: REASON"), an unreadable file no key ("SOURCE: REASON"). Control characters
/// and invalid UTF-8 in any part are escaped (PrintableText); the accessors return them as given.
class SceneError : public std::invalid_argument {
 public:
  SceneError(const std::string& source, const std::string& key, const std::string& value,
             const std::string& reason);

  const std::string& source() const { return source_; }
  const std::string& key() const { return key_; }
  const std::string& value() const { return value_; }

 private:
  std::string source_;
  std::string key_;
  std::string value_;
};

}  // namespace cosmems
