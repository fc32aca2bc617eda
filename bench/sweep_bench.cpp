// Samples per second of `cosmems sweep` on this machine: in process on 1 and 2 worker threads,
// and through `mpirun -n R` (R - 1 ranks running samples, rank 0 dispatching). The sweep is the
// README's pull-in map at 10 x 10 lengths and gaps (one pull-in analysis a sample, about
// 0.3 ms). The ranks' figure includes mpirun's start-up of every rank, timed apart by the same
// command with one sample (`samples:1`).
#include <benchmark/benchmark.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <sstream>
#include <string>

#include "sweep_runner.hpp"

namespace cosmems {
namespace {

const char* const kScene = "cantilever-pullin";
const char* const kLengths = "structure.length=100e-6:300e-6:10";
const char* const kGaps = "structure.gap=1e-6:3e-6:10";
constexpr int kSamples = 100;

void BM_SweepThreads(benchmark::State& state) {
  internal::SweepRequest request;
  request.scene = kScene;
  request.vary = {internal::SweepRequest::SplitVary(kLengths),
                  internal::SweepRequest::SplitVary(kGaps)};
  request.threads = static_cast<int>(state.range(0));
  request.json = true;
  for (auto _ : state) {
    std::ostringstream out, err;
    if (internal::RunSweep(request, out, err, false) != 0) state.SkipWithError("sweep failed");
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_SweepThreads)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

#ifdef COSMEMS_MPIEXEC
void BM_SweepRanks(benchmark::State& state) {
  // OpenMPI refuses root and more ranks than cores unless told (the CI machine: root, 2 cores).
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  const bool one = state.range(1) == 1;
  const std::string command = std::string(COSMEMS_MPIEXEC) + " -n " +
                              std::to_string(state.range(0)) + " " + COSMEMS_BINARY + " sweep " +
                              kScene + " --vary " + (one ? "structure.length=[2e-4]" : kLengths) +
                              (one ? "" : std::string(" --vary ") + kGaps) +
                              " --json > /dev/null 2>&1";
  for (auto _ : state) {
    const int status = std::system(command.c_str());
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) state.SkipWithError("mpirun failed");
  }
  state.SetItemsProcessed(state.iterations() * (one ? 1 : kSamples));
}
BENCHMARK(BM_SweepRanks)
    ->ArgNames({"ranks", "samples"})
    ->Args({2, 1})
    ->Args({2, kSamples})
    ->Args({3, kSamples})
    ->Iterations(5)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
#endif

}  // namespace
}  // namespace cosmems
