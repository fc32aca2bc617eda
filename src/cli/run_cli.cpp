#include "run_cli.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <stdexcept>

#include "analysis_runner.hpp"
#include "cli_errors.hpp"
#include "cosmems/scene/embedded_scenes.hpp"
#include "cosmems/scene/netlist_scene.hpp"
#include "cosmems/scene/printable_text.hpp"
#include "cosmems/scene/scene_key_reference.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "sweep_runner.hpp"

namespace cosmems {
namespace {

constexpr int kSuccess = 0;
constexpr int kInternalError = 1;
constexpr int kInvalidInput = 2;
constexpr int kNumericalFailure = 3;

// What `cosmems run` was asked to do.
struct RunRequest {
  std::string scene;
  std::vector<std::string> overrides;
  bool json = false;
  std::string out;
};

// An option given once per value, any number of times (--set A=1 --set B=2): one value each,
// so that the positional SCENE may follow it.
void Repeatable(CLI::Option* option) {
  option->expected(1)->allow_extra_args(false)->multi_option_policy(
      CLI::MultiOptionPolicy::TakeAll);
}

std::filesystem::path PrepareOutDirectory(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory)) {
    const std::string why = error ? error.message() : "not a directory";
    throw internal::CliInputError("--out " + directory + ": cannot create the directory: " + why);
  }
  return directory;
}

int Run(const RunRequest& request, std::ostream& out) {
  std::vector<SceneOverride> overrides;
  for (const std::string& assignment : request.overrides) {
    overrides.push_back(SceneOverride::Parse(assignment));
  }
  const Scene scene = LoadScene(request.scene, overrides);
  std::filesystem::path directory;
  if (!request.out.empty()) directory = PrepareOutDirectory(request.out);

  const std::unique_ptr<internal::AnalysisReport> report = internal::RunAnalysis(scene);
  const bool ok = report->header().status == Status::kOk;
  if (ok && !directory.empty()) report->WriteFiles(directory);
  if (request.json) {
    out << report->Json().dump(2) << "\n";
  } else {
    report->PrintSummary(out);
    if (ok && !directory.empty()) out << "files written to " << directory.string() << "\n";
  }
  return ok ? kSuccess : kNumericalFailure;
}

// `cosmems netlist`: a generated structure's scene (a cantilever, a bridge or a parametric
// device) as the frame netlist its generator makes.
int PrintNetlist(const RunRequest& request, std::ostream& out) {
  std::vector<SceneOverride> overrides;
  for (const std::string& assignment : request.overrides) {
    overrides.push_back(SceneOverride::Parse(assignment));
  }
  const Scene scene = LoadScene(request.scene, overrides);
  if (scene.structure.kind == StructureKind::kFrame) {
    throw internal::CliInputError(request.scene +
                                  ": structure.kind = \"frame\" is a netlist already");
  }
  out << NetlistScene(scene);
  return kSuccess;
}

int ListScenes(std::ostream& out) {
  std::size_t width = 0;
  for (const EmbeddedScene& scene : EmbeddedScenes()) width = std::max(width, scene.name.size());
  for (const EmbeddedScene& scene : EmbeddedScenes()) {
    out << scene.name << std::string(width + 2 - scene.name.size(), ' ') << scene.description
        << "\n";
  }
  return kSuccess;
}

int ShowScene(const std::string& name, std::ostream& out) {
  const EmbeddedScene* scene = FindEmbeddedScene(name);
  if (scene == nullptr) {
    std::string names;
    for (const EmbeddedScene& embedded : EmbeddedScenes()) {
      names += (names.empty() ? "" : ", ") + std::string(embedded.name);
    }
    throw internal::CliInputError(name + ": not an embedded scene (" + names + ")");
  }
  out << scene->toml;
  return kSuccess;
}

}  // namespace

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app(
      "cosmems: fast simulation of MEMS beams (cantilevers, clamped-clamped bridges) and "
      "frames of beams and rigid bodies",
      "cosmems");
  app.set_version_flag("--version", std::string("cosmems ") + COSMEMS_VERSION);
  app.require_subcommand(1);

  RunRequest request;
  CLI::App* run = app.add_subcommand("run", "Run the analysis a scene declares");
  run->add_option("SCENE", request.scene, "A .toml scene file or the name of an embedded scene")
      ->required();
  Repeatable(run->add_option("--set", request.overrides,
                             "Override a key by its dotted path, VALUE read as TOML "
                             "(--set model.elements=8); repeatable")
                 ->type_name("KEY=VALUE"));
  run->add_flag("--json", request.json, "Print one JSON object on stdout and nothing else");
  run->add_option("--out", request.out, "Write CSV files (deflection, modes, history) into DIR")
      ->type_name("DIR")
      ->check(CLI::Validator(
          [](const std::string& directory) {
            return directory.empty() ? std::string("DIR must not be empty") : std::string();
          },
          "DIR"));

  RunRequest netlist_request;
  CLI::App* netlist = app.add_subcommand(
      "netlist",
      "Print the netlist a cantilever's, a bridge's or a parametric device's scene makes, as a "
      "frame scene to edit");
  netlist->add_option("SCENE", netlist_request.scene, "A .toml scene file or an embedded scene")
      ->required();
  Repeatable(netlist->add_option("--set", netlist_request.overrides, "Override a key, as for run")
                 ->type_name("KEY=VALUE"));

  internal::SweepRequest sweep_request;
  std::vector<std::string> varied;
  std::string shard;
  CLI::App* sweep = app.add_subcommand(
      "sweep", "Run a scene over varied keys (a grid, random draws) and summarise the outputs");
  sweep->add_option("SCENE", sweep_request.scene, "A .toml scene file or an embedded scene")
      ->required();
  Repeatable(sweep
                 ->add_option("--vary", varied,
                              "Vary KEY by SPEC: A:B:N, log:A:B:N, [v1, v2], "
                              "uniform:A:B, normal:M:S, lognormal:M:S, "
                              "truncnormal:M:S:LO:HI; repeatable")
                 ->type_name("KEY=SPEC"));
  sweep->add_option("--samples", sweep_request.samples, "Draws of the random keys (100)")
      ->type_name("N");
  sweep->add_option("--method", sweep_request.method, "monte-carlo (default), lhs or sobol")
      ->type_name("M");
  sweep->add_option("--seed", sweep_request.seed, "The sweep's seed (1)")->type_name("S");
  Repeatable(sweep
                 ->add_option("--spec", sweep_request.specs,
                              "A condition on an output (pullin_voltage_v>=20); repeatable")
                 ->type_name("EXPR"));
  Repeatable(
      sweep
          ->add_option("--plot", sweep_request.plots,
                       "An output to plot into --out (the specs' fields, else the analysis's "
                       "first); repeatable")
          ->type_name("FIELD"));
  sweep->add_option("--threads", sweep_request.threads, "Workers (one per hardware thread)")
      ->type_name("T")
      ->check(CLI::PositiveNumber);
  sweep->add_option("--shard", shard, "Run only shard K of N (K from 1)")->type_name("K/N");
  sweep
      ->add_option("--out", sweep_request.out,
                   "Write samples.jsonl, samples.csv and summary.json into DIR; resume there")
      ->type_name("DIR");
  sweep->add_flag("--json", sweep_request.json, "Print the summary as one JSON object");
  Repeatable(
      sweep->add_option("--set", sweep_request.sets, "Override a key in every sample, as for run")
          ->type_name("KEY=VALUE"));

  CLI::App* scenes = app.add_subcommand("scenes", "List the embedded scenes, one line each");
  std::string show_name;
  CLI::App* show = app.add_subcommand("show", "Print an embedded scene as TOML, to edit");
  show->add_option("NAME", show_name, "The embedded scene")->required();
  CLI::App* keys = app.add_subcommand(
      "keys", "Print every scene key: what it accepts, its default, its meaning (markdown)");

  // CLI11 reports a mistyped command as "A subcommand is required"; name it instead.
  if (!args.empty() && !args.front().empty() && args.front().front() != '-') {
    std::string commands;
    bool known = false;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
      known = known || command->get_name() == args.front();
      commands += (commands.empty() ? "" : ", ") + command->get_name();
    }
    if (!known) {
      err << "cosmems: unknown command \"" << PrintableText(args.front()) << "\" (expected "
          << commands << ")\n";
      return kInvalidInput;
    }
  }

  std::vector<const char*> argv = {"cosmems"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Success& help_or_version) {
    return app.exit(help_or_version, out, err);
  } catch (const CLI::ParseError& error) {
    err << "cosmems: " << PrintableText(error.what()) << " (see cosmems --help)\n";
    return kInvalidInput;
  }

  try {
    if (scenes->parsed()) return ListScenes(out);
    if (netlist->parsed()) return PrintNetlist(netlist_request, out);
    if (show->parsed()) return ShowScene(show_name, out);
    if (sweep->parsed()) {
      for (const std::string& assignment : varied) {
        sweep_request.vary.push_back(internal::SweepRequest::SplitVary(assignment));
      }
      if (!shard.empty()) sweep_request.SetShard(shard);
      const bool progress = &err == &std::cerr && isatty(STDERR_FILENO) != 0;
      return internal::RunSweep(sweep_request, out, err, progress);
    }
    if (keys->parsed()) {
      out << SceneKeyReference();
      return kSuccess;
    }
    return Run(request, out);
  } catch (const std::invalid_argument& error) {  // SceneError, CliInputError, core checks
    err << "cosmems: " << PrintableText(error.what()) << "\n";
    return kInvalidInput;
  } catch (const internal::OutputFileError& error) {  // a full disk: the system, not the input
    err << "cosmems: " << PrintableText(error.what()) << "\n";
    return kInternalError;
  } catch (const std::bad_alloc&) {
    err << "cosmems: out of memory\n";
    return kInternalError;
  } catch (const std::exception& error) {
    err << "cosmems: internal error: " << PrintableText(error.what()) << "\n";
    return kInternalError;
  }
}

}  // namespace cosmems
