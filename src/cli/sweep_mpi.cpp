#include "sweep_mpi.hpp"

#include <mpi.h>

#include <cstdlib>
#include <exception>
#include <stdexcept>

namespace cosmems::internal {
namespace {

// Rows (and a rank's first, empty "ready") travel to rank 0 as kRow; indices go out as kWork,
// the end as kStop.
constexpr int kRow = 1, kWork = 2, kStop = 3;

}  // namespace

bool LaunchedByMpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

MpiWorld::MpiWorld() {
  int provided = 0;
  // Only this thread calls MPI; a sample's own threads (a haptic run's) never do.
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    throw std::runtime_error("MPI_Init_thread failed");
  }
  // A rank that dies ends the job (mpirun exits non-zero) instead of leaving rank 0 waiting for
  // its row: said here rather than left to the implementation's default.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_ARE_FATAL);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiWorld::~MpiWorld() { MPI_Finalize(); }

std::optional<std::string> MpiWorld::Share(const std::optional<std::string>& text) const {
  // The length first (-1: nothing), then the characters.
  long long length = text ? static_cast<long long>(text->size()) : -1;
  MPI_Bcast(&length, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  if (length < 0) return std::nullopt;
  std::string shared = rank_ == 0 ? *text : std::string(static_cast<std::size_t>(length), '\0');
  MPI_Bcast(shared.data(), static_cast<int>(length), MPI_CHAR, 0, MPI_COMM_WORLD);
  return shared;
}

void MpiWorld::Dispatch(const std::vector<std::int64_t>& todo,
                        const std::function<void(const std::string&)>& sink) const {
  std::size_t next = 0;
  std::exception_ptr failure;
  std::string text;
  for (int active = size_ - 1; active > 0;) {
    MPI_Status status;
    MPI_Probe(MPI_ANY_SOURCE, kRow, MPI_COMM_WORLD, &status);
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    text.resize(static_cast<std::size_t>(length));
    MPI_Recv(text.data(), length, MPI_CHAR, status.MPI_SOURCE, kRow, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (!text.empty() && !failure) {
      try {
        sink(text);
      } catch (...) {  // an unwritable --out: finish the conversation, then report it
        failure = std::current_exception();
      }
    }
    if (next < todo.size() && !failure) {
      MPI_Send(&todo[next++], 1, MPI_INT64_T, status.MPI_SOURCE, kWork, MPI_COMM_WORLD);
    } else {
      MPI_Send(nullptr, 0, MPI_INT64_T, status.MPI_SOURCE, kStop, MPI_COMM_WORLD);
      --active;
    }
  }
  if (failure) std::rethrow_exception(failure);
}

void MpiWorld::Serve(const std::function<std::string(std::int64_t)>& run) const {
  std::string row;  // empty: ready for the first index
  for (;;) {
    MPI_Send(row.data(), static_cast<int>(row.size()), MPI_CHAR, 0, kRow, MPI_COMM_WORLD);
    std::int64_t index = 0;
    MPI_Status status;
    MPI_Recv(&index, 1, MPI_INT64_T, 0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    if (status.MPI_TAG == kStop) return;
    try {
      row = run(index);
    } catch (...) {
      // `run` makes a failing sample a row; what escapes it anyway (no memory left for the
      // row's text) must not finalise this rank while rank 0 waits for the row for ever.
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
  }
}

}  // namespace cosmems::internal
