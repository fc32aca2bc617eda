#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

namespace cosmems::testing {

// A FIFO holding a scene: a writer thread hands `text` to the first reader that opens it, then
// closes it. A loader that reads FIFOs gets the scene and its end (and the test fails cleanly)
// instead of blocking for ever in open(); one that refuses them leaves the writer waiting until
// the destructor stops it.
class FifoScene {
 public:
  FifoScene(std::filesystem::path path, std::string text) : path_(std::move(path)) {
    std::filesystem::remove(path_);
    if (mkfifo(path_.c_str(), 0600) != 0) throw std::runtime_error("mkfifo " + path_.string());
    writer_ = std::thread([this, scene = std::move(text)] {
      while (!stop_.load()) {
        // Without O_NONBLOCK, open() would wait for a reader that may never come.
        const int fd = open(path_.c_str(), O_WRONLY | O_NONBLOCK);
        if (fd >= 0) {
          [[maybe_unused]] const ssize_t written = write(fd, scene.data(), scene.size());
          close(fd);
          return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    });
  }
  ~FifoScene() {
    stop_.store(true);
    writer_.join();
    std::filesystem::remove(path_);
  }
  FifoScene(const FifoScene&) = delete;
  FifoScene& operator=(const FifoScene&) = delete;

  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
  std::atomic<bool> stop_{false};
  std::thread writer_;
};

}  // namespace cosmems::testing
