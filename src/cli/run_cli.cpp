#include "run_cli.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <memory>
#include <new>
#include <stdexcept>

#include "buckling_report.hpp"
#include "cli_input_error.hpp"
#include "cosmems/scene/embedded_scenes.hpp"
#include "cosmems/scene/netlist_scene.hpp"
#include "cosmems/scene/scene_key_reference.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "frame_buckling_report.hpp"
#include "frame_modal_report.hpp"
#include "frame_pullin_report.hpp"
#include "frame_release_report.hpp"
#include "frame_static_report.hpp"
#include "haptic_report.hpp"
#include "modal_report.hpp"
#include "pullin_report.hpp"
#include "release_report.hpp"
#include "static_report.hpp"
#include "transient_report.hpp"

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

std::string OneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  return text;
}

std::unique_ptr<internal::AnalysisReport> RunAnalysis(const Scene& scene) {
  // A device runs every analysis.
  if (IsDevice(scene.structure.kind)) {
    if (scene.analysis.type == AnalysisType::kHaptic) return internal::HapticReport::Run(scene);
    if (scene.analysis.type == AnalysisType::kPullin)
      return internal::FramePullInReport::Run(scene);
    if (scene.analysis.type == AnalysisType::kModal) return internal::FrameModalReport::Run(scene);
    if (scene.analysis.type == AnalysisType::kTransient)
      return internal::TransientReport::Run(scene);
    if (scene.analysis.type == AnalysisType::kBuckling) {
      return internal::FrameBucklingReport::Run(scene);
    }
    if (scene.analysis.type == AnalysisType::kRelease) {
      return internal::FrameReleaseReport::Run(scene);
    }
    return internal::FrameStaticReport::Run(scene);
  }
  switch (scene.analysis.type) {
    case AnalysisType::kStatic:
      return internal::StaticReport::Run(scene);
    case AnalysisType::kModal:
      return internal::ModalReport::Run(scene);
    case AnalysisType::kTransient:
      return internal::TransientReport::Run(scene);
    case AnalysisType::kBuckling:
      return internal::BucklingReport::Run(scene);
    case AnalysisType::kPullin:
      return internal::PullInReport::Run(scene);
    case AnalysisType::kRelease:
      return internal::ReleaseReport::Run(scene);
    case AnalysisType::kHaptic:
      return internal::HapticReport::Run(scene);
  }
  throw std::logic_error(std::string("analysis.type = \"") + ToString(scene.analysis.type) +
                         "\" passed validation but has no runner");
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

  const std::unique_ptr<internal::AnalysisReport> report = RunAnalysis(scene);
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

// `cosmems netlist`: a parametric device's scene as the frame netlist its generator makes.
int PrintNetlist(const RunRequest& request, std::ostream& out) {
  std::vector<SceneOverride> overrides;
  for (const std::string& assignment : request.overrides) {
    overrides.push_back(SceneOverride::Parse(assignment));
  }
  const Scene scene = LoadScene(request.scene, overrides);
  if (!IsDevice(scene.structure.kind) || scene.structure.kind == StructureKind::kFrame) {
    throw internal::CliInputError(request.scene + ": structure.kind = \"" +
                                  ToString(scene.structure.kind) +
                                  "\" is no parametric device (it has no netlist to print)");
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
  run->add_option("--set", request.overrides,
                  "Override a key by its dotted path, VALUE read as TOML "
                  "(--set model.elements=8); repeatable")
      ->type_name("KEY=VALUE")
      ->expected(1)
      ->allow_extra_args(false)  // one value per --set, so SCENE may follow it
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
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
      "netlist", "Print the netlist a parametric device's scene makes, as a frame scene to edit");
  netlist->add_option("SCENE", netlist_request.scene, "A .toml scene file or an embedded scene")
      ->required();
  netlist->add_option("--set", netlist_request.overrides, "Override a key, as for run")
      ->type_name("KEY=VALUE")
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);

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
      err << "cosmems: unknown command \"" << OneLine(args.front()) << "\" (expected " << commands
          << ")\n";
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
    err << "cosmems: " << OneLine(error.what()) << " (see cosmems --help)\n";
    return kInvalidInput;
  }

  try {
    if (scenes->parsed()) return ListScenes(out);
    if (netlist->parsed()) return PrintNetlist(netlist_request, out);
    if (show->parsed()) return ShowScene(show_name, out);
    if (keys->parsed()) {
      out << SceneKeyReference();
      return kSuccess;
    }
    return Run(request, out);
  } catch (const std::invalid_argument& error) {  // SceneError, CliInputError, core checks
    err << "cosmems: " << OneLine(error.what()) << "\n";
    return kInvalidInput;
  } catch (const std::bad_alloc&) {
    err << "cosmems: out of memory\n";
    return kInternalError;
  } catch (const std::exception& error) {
    err << "cosmems: internal error: " << OneLine(error.what()) << "\n";
    return kInternalError;
  }
}

}  // namespace cosmems
