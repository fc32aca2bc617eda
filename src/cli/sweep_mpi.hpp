#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cosmems::internal {

/// Whether an MPI launcher (mpirun, mpiexec, srun) started this process: its environment names
/// a world size. A plain run of a binary built with MPI stays single-process and never
/// initialises MPI.
bool LaunchedByMpi();

/// The MPI world of one sweep, initialised on construction and finalised on destruction.
/// Rank 0 dispatches, the others run samples: an index goes out as soon as a rank returns its
/// last row (samples near pull-in cost many times more than others, so a static split would
/// leave ranks idle), and the rows come back as messages, so no file system is shared.
class MpiWorld {
 public:
  MpiWorld();
  ~MpiWorld();
  MpiWorld(const MpiWorld&) = delete;
  MpiWorld& operator=(const MpiWorld&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Rank 0's `text` to every rank (nothing: rank 0 failed before the sweep began, and the
  /// others return). Every rank calls it once, the others with nothing.
  std::optional<std::string> Share(const std::optional<std::string>& text) const;
  /// Rank 0: hands the indices of `todo` out one at a time and gives each returned row's text to
  /// `sink`; then stops every other rank (at once, for an empty `todo`). If `sink` throws, no
  /// index is handed out any more, the ranks are stopped and the exception is rethrown.
  void Dispatch(const std::vector<std::int64_t>& todo,
                const std::function<void(const std::string&)>& sink) const;
  /// The other ranks: the text of `run(index)` for each index rank 0 sends, until it stops them.
  /// An exception out of `run` aborts the job (mpirun exits non-zero): rank 0 would wait for
  /// the row for ever. A resume finishes the sweep.
  void Serve(const std::function<std::string(std::int64_t)>& run) const;

 private:
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace cosmems::internal
