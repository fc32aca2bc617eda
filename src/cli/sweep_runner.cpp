#include "sweep_runner.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <new>
#include <optional>
#include <set>
#include <thread>

#include "analysis_runner.hpp"
#include "atomic_file.hpp"
#include "cli_errors.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "sweep_condition.hpp"
#include "sweep_plan.hpp"
#include "sweep_plots.hpp"
#include "sweep_store.hpp"
#include "sweep_summary.hpp"
#if COSMEMS_WITH_MPI
#include "sweep_mpi.hpp"
#endif
#include "text_format.hpp"
#include "text_hash.hpp"

namespace cosmems::internal {
namespace {

constexpr std::int64_t kDefaultDraws = 100;
constexpr std::uint64_t kDefaultSeed = 1;

// What every sample of the sweep shares: the scene's text is read once (a file changed during
// the sweep does not change its samples; MPI ranks receive it from rank 0).
struct Sweep {
  SweepPlan plan;
  std::vector<SweepCondition> conditions;
  std::vector<SceneOverride> sets;
  std::string scene;  ///< its name or path, as errors and results name it
  std::string text;
};

Sweep Prepare(const SweepRequest& request, std::string text) {
  std::vector<SweepParameter> parameters;
  std::set<std::string> keys;
  for (const auto& [key, spec] : request.vary) {
    if (!keys.insert(key).second) throw CliInputError("--vary " + key + ": varied twice");
    parameters.emplace_back(key, spec);
  }
  if (parameters.empty()) {
    throw CliInputError(request.scene +
                        ": nothing to sweep (give --vary KEY=SPEC or a "
                        "[sweep.vary] table)");
  }
  const SweepMethod method = ParseSweepMethod(request.method.value_or("monte-carlo"), "--method");
  Sweep sweep{SweepPlan(std::move(parameters), method, request.samples.value_or(kDefaultDraws),
                        request.seed.value_or(kDefaultSeed)),
              {},
              {},
              request.scene,
              std::move(text)};
  for (const std::string& spec : request.specs) sweep.conditions.emplace_back(spec);
  for (const std::string& set : request.sets) sweep.sets.push_back(SceneOverride::Parse(set));
  return sweep;
}

std::vector<SceneOverride> Overrides(const Sweep& sweep,
                                     const std::vector<nlohmann::json>& values) {
  std::vector<SceneOverride> overrides = sweep.sets;
  for (std::size_t j = 0; j < values.size(); ++j) {
    overrides.push_back({sweep.plan.parameters()[j].key(), TomlLiteral(values[j])});
  }
  return overrides;
}

// A haptic scene on a real device cannot be a sweep's sample: there is one device and one hand,
// and samples run at once (threads, ranks). Throws naming device.backend.
void RequireNoDevice(const Scene& scene) {
  if (scene.analysis.type != AnalysisType::kHaptic || !scene.device ||
      scene.device->backend != DeviceBackend::kOpenHaptics) {
    return;
  }
  throw CliInputError(
      "device.backend = \"openhaptics\": a sweep cannot run a haptic scene on a device (one "
      "device, one hand, and the samples run at once); sweep the scripted stylus instead");
}

// A paced haptic scene measures the machine's real-time behaviour: its samples run one at a time.
bool PacedHaptic(const Scene& scene) {
  return scene.analysis.type == AnalysisType::kHaptic && scene.device && scene.device->realtime;
}

// Every grid value, and each distribution's median, must make a valid scene (the others at
// their nominal values): an invalid sweep is refused before a sample runs. Returns whether any
// of those scenes is a paced haptic one.
bool Validate(const Sweep& sweep) {
  const std::vector<SweepParameter>& parameters = sweep.plan.parameters();
  std::vector<nlohmann::json> nominal;
  for (const SweepParameter& p : parameters) nominal.push_back(p.Nominal());
  bool paced = false;
  auto check = [&](const std::vector<nlohmann::json>& values) {
    const Scene scene = LoadSceneText(sweep.text, sweep.scene, Overrides(sweep, values));
    RequireNoDevice(scene);
    paced = paced || PacedHaptic(scene);
  };
  check(nominal);
  for (std::size_t j = 0; j < parameters.size(); ++j) {
    std::vector<nlohmann::json> values = nominal;
    for (std::size_t v = 1; v < parameters[j].values().size(); ++v) {
      values[j] = parameters[j].values()[v];
      check(values);
    }
  }
  return paced;
}

SweepRow RunSample(const Sweep& sweep, std::int64_t index) {
  SweepRow row;
  row.index = index;
  const std::vector<nlohmann::json> values = sweep.plan.Values(index);
  for (std::size_t j = 0; j < values.size(); ++j) {
    row.parameters[sweep.plan.parameters()[j].key()] = values[j];
  }
  try {
    const Scene scene = LoadSceneText(sweep.text, sweep.scene, Overrides(sweep, values));
    RequireNoDevice(scene);  // a combination of values Validate() did not load
    row.result = RunAnalysis(scene)->Json();
    row.status = row.result.value("status", std::string("no status"));
  } catch (const std::invalid_argument& error) {  // a drawn value the scene refuses
    row.status = std::string("invalid: ") + error.what();
  } catch (const std::bad_alloc&) {  // this sample's model too large for the memory left
    row.status = "error: out of memory";
  } catch (const std::exception& error) {
    // Whatever else one sample meets is its row: the other samples, the other threads and,
    // under MPI, rank 0 waiting for this row go on.
    row.status = std::string("error: ") + error.what();
  } catch (...) {
    row.status = "error: an exception of unknown type";
  }
  return row;
}

// What sweep.json records: what decides the samples' values and results (not threads, shards
// or output): the scene's text by its hash (an edited file is another design), the --set as
// given and the program's version.
nlohmann::ordered_json Description(const Sweep& sweep, const SweepRequest& request) {
  nlohmann::ordered_json vary = nlohmann::ordered_json::object();
  for (const SweepParameter& p : sweep.plan.parameters()) vary[p.key()] = p.spec();
  return {{"scene", request.scene},
          {"scene_text_hash", TextHash(sweep.text)},
          {"set", request.sets},
          {"vary", vary},
          {"method", ToString(sweep.plan.method())},
          {"samples", sweep.plan.draws()},
          {"seed", sweep.plan.seed()},
          {"version", COSMEMS_VERSION}};
}

// Runs `todo` on `workers` threads, each taking the next index as it finishes one (samples near
// pull-in cost many times more than others), and hands each row to `sink` under one lock.
template <typename Sink>
void RunOnThreads(const Sweep& sweep, const std::vector<std::int64_t>& todo, int workers,
                  Sink&& sink) {
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  std::exception_ptr failure;
  auto work = [&] {
    for (std::size_t i; (i = next++) < todo.size();) {
      try {
        SweepRow row = RunSample(sweep, todo[i]);
        const std::lock_guard<std::mutex> hold(lock);
        sink(std::move(row));
      } catch (...) {  // an unwritable --out (a sample's own failure is its row): the sweep stops
        const std::lock_guard<std::mutex> hold(lock);
        if (!failure) failure = std::current_exception();
        next = todo.size();
      }
    }
  };
  std::vector<std::thread> threads;
  for (int w = 1; w < workers; ++w) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

void PrintSummary(const nlohmann::ordered_json& summary,
                  const std::vector<SweepCondition>& conditions, std::ostream& out) {
  out << "sweep: " << summary["samples"].get<std::int64_t>() << " samples, "
      << summary["failed"].get<std::int64_t>() << " failed, "
      << Significant(summary["wall_time_s"].get<double>(), 3) << " s on "
      << summary["workers"].get<int>() << " workers\n";
  if (summary.contains("yield")) {
    std::string specs;
    for (const SweepCondition& c : conditions) specs += (specs.empty() ? "" : ", ") + c.text();
    out << "yield: " << Significant(100.0 * summary["yield"].get<double>(), 4) << " % (" << specs
        << ")\n";
  }
  for (const auto& [field, s] : summary["outputs"].items()) {
    out << "  " << field << ": mean " << Scientific(s["mean"].get<double>()) << ", std "
        << Scientific(s["std"].get<double>(), 3) << ", min " << Scientific(s["min"].get<double>())
        << ", max " << Scientific(s["max"].get<double>()) << "\n";
  }
}

// The plots of a sweep: the fields asked (or the default ones) over its numeric grid keys, or
// as histograms when it draws keys.
SweepPlotRequest PlotRequest(const Sweep& sweep, const SweepRequest& request,
                             const std::vector<SweepRow>& rows) {
  SweepPlotRequest plots;
  plots.fields = request.plots.empty() ? DefaultPlotFields(rows, sweep.conditions) : request.plots;
  plots.conditions = sweep.conditions;
  for (const SweepParameter& p : sweep.plan.parameters()) {
    plots.random = plots.random || !p.IsGrid();
    const bool numeric =
        p.IsGrid() && std::all_of(p.values().begin(), p.values().end(),
                                  [](const nlohmann::json& v) { return v.is_number(); });
    if (numeric) plots.grid_keys.push_back(p.key());
  }
  return plots;
}

// Runs the samples `todo`, handing each row to `sink` on the calling thread; `workers` is how
// many run at once.
struct Executor {
  int workers = 0;
  std::function<void(const std::vector<std::int64_t>& todo,
                     const std::function<void(SweepRow)>& sink)>
      run;
};

// The sweep on this process's threads, or on `ranks` when given.
int Run(SweepRequest request, std::string text, std::ostream& out, std::ostream& err, bool progress,
        const Executor* ranks, std::vector<SweepRow>* rows_out = nullptr) {
  const auto start = std::chrono::steady_clock::now();
  request.MergeSceneTable(text, request.scene);
  const Sweep sweep = Prepare(request, std::move(text));
  const bool paced = Validate(sweep);
  if (paced && ranks && ranks->workers > 1) {
    throw CliInputError(
        "device.realtime = true: a paced haptic sweep runs one sample at a time (its timings are "
        "the machine's); run it on threads, not on MPI ranks");
  }

  std::optional<SweepStore> store;
  if (!request.out.empty()) store.emplace(request.out, Description(sweep, request), err);
  std::vector<SweepRow> rows = store ? store->previous() : std::vector<SweepRow>{};
  std::set<std::int64_t> done;
  for (const SweepRow& row : rows) done.insert(row.index);
  std::vector<std::int64_t> todo;
  for (std::int64_t i = request.shard - 1; i < sweep.plan.Count(); i += request.shards) {
    if (done.count(i) == 0) todo.push_back(i);
  }
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int workers = ranks   ? ranks->workers
                      : paced ? 1
                              : static_cast<int>(std::clamp<std::int64_t>(
                                    request.threads > 0 ? request.threads : hardware, 1,
                                    std::max<std::size_t>(todo.size(), 1)));

  std::size_t finished = 0, failed = 0;
  auto sink = [&](SweepRow row) {
    if (store) store->Append(row);
    failed += row.ok() ? 0 : 1;
    rows.push_back(std::move(row));
    if (progress) {
      const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      err << "\rsweep: " << ++finished << "/" << todo.size() << " samples, " << failed
          << " failed, " << Significant(elapsed, 3) << " s" << std::flush;
    }
  };
  if (ranks) {
    ranks->run(todo, sink);
  } else {
    RunOnThreads(sweep, todo, workers, sink);
  }
  if (progress && !todo.empty()) err << "\n";

  std::sort(rows.begin(), rows.end(),
            [](const SweepRow& a, const SweepRow& b) { return a.index < b.index; });
  nlohmann::ordered_json summary = SummarizeSweep(rows, sweep.conditions);
  summary["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary["workers"] = workers;
  if (store) {
    AtomicFile::WriteWhole(store->directory() / "summary.json", summary.dump(2) + "\n");
    WriteSweepCsv(store->directory() / "samples.csv", rows);
    (void)WriteSweepPlots(store->directory(), rows, PlotRequest(sweep, request, rows));
  }
  if (rows_out) *rows_out = std::move(rows);
  if (request.json) {
    out << summary.dump(2) << "\n";
  } else {
    PrintSummary(summary, sweep.conditions, out);
    if (store) out << "files written to " << store->directory().string() << "\n";
  }
  return 0;
}

#if COSMEMS_WITH_MPI
// Rank 0 runs the sweep, the others its samples. Every rank has the command line; the scene's
// text comes from rank 0, so no other rank needs its file. When rank 0 refuses the sweep (or
// fails) it stops the others before it reports why; they print nothing.
int RunOnRanks(const SweepRequest& request, std::ostream& out, std::ostream& err, bool progress,
               const MpiWorld& world, std::vector<SweepRow>* rows) {
  if (world.rank() == 0) {
    std::string text;
    try {
      text = SceneText(request.scene);
    } catch (...) {
      world.Share(std::nullopt);
      throw;
    }
    world.Share(text);
    bool stopped = false;
    Executor ranks{world.size() - 1, [&](const std::vector<std::int64_t>& todo,
                                         const std::function<void(SweepRow)>& sink) {
                     stopped = true;
                     world.Dispatch(todo, [&](const std::string& row) {
                       sink(SweepRow::FromJson(nlohmann::ordered_json::parse(row)));
                     });
                   }};
    try {
      return Run(request, std::move(text), out, err, progress, &ranks, rows);
    } catch (...) {
      if (!stopped) world.Dispatch({}, [](const std::string&) {});
      throw;
    }
  }
  std::optional<std::string> text = world.Share(std::nullopt);
  if (!text) return 0;
  std::optional<Sweep> sweep;
  try {
    SweepRequest copy = request;
    copy.MergeSceneTable(*text, request.scene);
    sweep.emplace(Prepare(copy, std::move(*text)));
  } catch (const std::exception&) {
    // Rank 0 fails alike, reports it and hands out no sample.
  }
  world.Serve(
      [&](std::int64_t index) { return sweep ? RunSample(*sweep, index).Text() : std::string(); });
  return 0;
}
#endif

}  // namespace

int RunSweep(const SweepRequest& request, std::ostream& out, std::ostream& err, bool progress,
             std::vector<SweepRow>* rows) {
#if COSMEMS_WITH_MPI
  if (LaunchedByMpi()) {
    const MpiWorld world;
    if (world.size() > 1) return RunOnRanks(request, out, err, progress, world, rows);
  }
#endif
  return Run(request, SceneText(request.scene), out, err, progress, nullptr, rows);
}

}  // namespace cosmems::internal
