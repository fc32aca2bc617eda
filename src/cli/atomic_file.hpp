#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace cosmems::internal {

/// A file that appears whole or not at all. The text goes to a new temporary file beside
/// `path` (created exclusively, never through a symbolic link); Commit() syncs it to the disk
/// and renames it over `path`, so that a reader, a concurrent writer of the same file or a
/// crash sees the old file or the new one, never a part. A symbolic link at `path` is replaced,
/// not followed: what it pointed to is left as it was. Without Commit() (an exception on the
/// way) the temporary is removed and `path` is untouched.
///
/// Every failure throws OutputFileError naming `path` and the system's reason.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Appends `text` (buffered).
  void Write(std::string_view text);
  /// The temporary's path, for a program that writes the file itself (gnuplot's PNG): it exists,
  /// empty, until Commit().
  const std::filesystem::path& temporary() const { return temporary_; }
  /// Writes what is buffered, syncs the file, renames it to `path` and syncs the folder.
  void Commit();

  /// The whole of `text` as the file `path`.
  static void WriteWhole(const std::filesystem::path& path, std::string_view text);

 private:
  void Flush();
  [[noreturn]] void Fail(const std::string& what, int error) const;

  std::filesystem::path path_;
  std::filesystem::path temporary_;
  int fd_ = -1;
  std::string buffer_;
};

}  // namespace cosmems::internal
