#include "key_origins.hpp"

namespace cosmems::internal {
namespace {

// Whether dotted key `inner` is `outer` or lies below it ("a.b", "a.b.c", "a.b[2]" below "a.b").
bool IsWithin(std::string_view inner, std::string_view outer) {
  if (inner.substr(0, outer.size()) != outer) return false;
  return inner.size() == outer.size() || inner[outer.size()] == '.' || inner[outer.size()] == '[';
}

}  // namespace

std::string KeyOrigins::SourceOf(std::string_view key) const {
  for (const std::string& written : overrides_) {
    if (IsWithin(key, written) || IsWithin(written, key)) return kOverride;
  }
  return source_;
}

}  // namespace cosmems::internal
