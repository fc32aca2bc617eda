#include "atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <system_error>
#include <utility>

#include "cli_errors.hpp"

namespace cosmems::internal {
namespace {

// Few system calls for a long history, little memory beside it.
constexpr std::size_t kAtomicBufferBytes = std::size_t{1} << 16;

// Temporaries of one process differ by this count, those of two processes by their ids.
std::atomic<unsigned> temporaries_made{0};

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path path) : path_(std::move(path)) {
  // Hidden beside the file: a rename within one folder stays on one file system. A name left
  // by a killed process whose id came back is skipped.
  for (int attempt = 0; fd_ < 0; ++attempt) {
    temporary_ =
        path_.parent_path() / ("." + path_.filename().string() + "." + std::to_string(getpid()) +
                               "." + std::to_string(temporaries_made++) + ".tmp");
    fd_ = open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0 && (errno != EEXIST || attempt >= 100)) {
      Fail("cannot create a temporary file beside it", errno);
    }
  }
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) close(fd_);
  if (!temporary_.empty()) unlink(temporary_.c_str());
}

void AtomicFile::Write(std::string_view text) {
  buffer_.append(text);
  if (buffer_.size() >= kAtomicBufferBytes) Flush();
}

void AtomicFile::Flush() {
  for (std::size_t done = 0; done < buffer_.size();) {
    const ssize_t wrote = write(fd_, buffer_.data() + done, buffer_.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote < 0) Fail("cannot write", errno);
    done += static_cast<std::size_t>(wrote);
  }
  buffer_.clear();
}

void AtomicFile::Commit() {
  Flush();
  // A full disk may show only here (NFS reports it at the sync or the close).
  if (fsync(fd_) != 0) Fail("cannot write", errno);
  const int closed = close(fd_);
  fd_ = -1;
  if (closed != 0) Fail("cannot write", errno);
  if (rename(temporary_.c_str(), path_.c_str()) != 0) Fail("cannot replace the file", errno);
  temporary_.clear();
  // The rename itself reaches the disk with the folder. A file system that cannot sync a
  // folder still has the file whole under one of its two names, so a failure here is ignored.
  const std::filesystem::path folder = path_.has_parent_path() ? path_.parent_path() : ".";
  const int directory = open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (directory >= 0) {
    (void)fsync(directory);
    close(directory);
  }
}

void AtomicFile::WriteWhole(const std::filesystem::path& path, std::string_view text) {
  AtomicFile file(path);
  file.Write(text);
  file.Commit();
}

void AtomicFile::Fail(const std::string& what, int error) const {
  throw OutputFileError(path_.string() + ": " + what + ": " +
                        std::generic_category().message(error));
}

}  // namespace cosmems::internal
