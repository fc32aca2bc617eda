// cosmems-viewer [SCENE] [--set KEY=VALUE]... [--input auto|mouse|script|omni]
//                [--screenshot FILE.png [--frames N]] [--size WxH] [--json]
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "cosmems/scene/scene_loader.hpp"
#include "viewer_app.hpp"

namespace {

// Exit statuses, as the `cosmems` command's: 2 for input it refuses, 1 for a failure to run.
constexpr int kInvalidInput = 2;
constexpr int kFailed = 1;

}  // namespace

int main(int argc, char** argv) {
  using cosmems::viewer::Input;
  cosmems::viewer::ViewerOptions options;
  std::vector<std::string> sets;
  std::string size;
  bool json = false;
  CLI::App app(
      "cosmems-viewer: touch a MEMS beam in 3-D. Without --screenshot it opens a window; "
      "with it, it plays the scene's scripted stylus headless and writes the last frame.");
  app.add_option("scene", options.scene, "an embedded scene or a .toml file")
      ->capture_default_str();
  app.add_option("--set", sets, "override a scene key: KEY=VALUE (as `cosmems run --set`)");
  const std::map<std::string, Input> inputs = {{"auto", Input::kAuto},
                                               {"mouse", Input::kMouse},
                                               {"script", Input::kScript},
                                               {"omni", Input::kOmni}};
  app.add_option("--input", options.input,
                 "the stylus: auto (an Omni if one answers, else the mouse), mouse, script, omni")
      ->transform(CLI::CheckedTransformer(inputs, CLI::ignore_case));
  app.add_option("--screenshot", options.screenshot,
                 "headless: the scripted press, then the last frame written to this PNG");
  app.add_option("--frames", options.frames, "headless: frames to draw (at 60 Hz)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  app.add_option("--size", size, "window size in pixels, WxH (default 1280x800)");
  app.add_flag("--json", json, "print the figures as one JSON line");
  try {
    app.parse(argc, argv);
    if (!size.empty()) {
      char rest = '\0';
      const int read = std::sscanf(size.c_str(), "%dx%d%c", &options.width, &options.height, &rest);
      if (read != 2 || options.width < 400 || options.height < 300) {
        throw CLI::ValidationError("--size", size + ": must be WxH, at least 400x300");
      }
    }
    for (const std::string& set : sets) {
      options.overrides.push_back(cosmems::SceneOverride::Parse(set));
    }
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::invalid_argument& e) {
    std::cerr << "cosmems-viewer: " << e.what() << "\n";
    return kInvalidInput;
  }
  try {
    const cosmems::viewer::ViewerFigures figures = cosmems::viewer::RunViewer(options);
    if (json) {
      cosmems::viewer::PrintFiguresJson(figures, std::cout);
    } else {
      cosmems::viewer::PrintFigures(figures, std::cout);
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "cosmems-viewer: " << e.what() << "\n";
    return kInvalidInput;
  } catch (const std::exception& e) {
    std::cerr << "cosmems-viewer: " << e.what() << "\n";
    return kFailed;
  }
  return 0;
}
