#include "viewer_app.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "comb_mesh.hpp"
#include "cosmems/haptics/periodic_deadline.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/touch_target.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "device_mesh.hpp"
#include "device_stage.hpp"
#include "overlays.hpp"
#include "panel.hpp"
#include "renderer.hpp"
#include "screenshot.hpp"
#include "stage.hpp"

namespace cosmems::viewer {
namespace {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// GLFW and Dear ImGui for the life of one window.
class Window {
 public:
  Window(int width, int height, bool headless) {
    if (glfwInit() != GLFW_TRUE) {
      throw std::runtime_error(
          "no display: GLFW could not initialise (set DISPLAY, or run headless under xvfb-run)");
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_RESIZABLE, headless ? GLFW_FALSE : GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, "cosmems viewer", nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw std::runtime_error("no OpenGL 3.3 core context: the window could not be created");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(0);  // the display loop paces itself (kDisplayRateHz)
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed: nothing to remember
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
  }
  ~Window() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* get() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

// What the display needs of a scene besides the frames: its netlist (a beam's one member or a
// device's), the mesh whose carriers the frames move, its combs and the point whose deflection
// the plot follows (TouchTarget: a device's device.target, default its first body; a cantilever's
// tip; a bridge's midspan).
struct DrawnStructure {
  explicit DrawnStructure(const Scene& scene)
      : structure(MakeStructureDescription(scene)),
        mesh(structure),
        combs(MakeCombDrives(scene, structure)),
        beam(IsStraightBeam(scene)) {
    const FrameRecordPoint target = TouchTarget(scene, structure);
    target_node = target.node;
    target_body = target.body;
    if (target.member < 0) return;
    // The members' elements come one member after another.
    target_element = 0;
    for (int m = 0; m < target.member; ++m) target_element += structure.members[m].elements;
    const int elements = structure.members[target.member].elements;
    const int k = std::min(elements - 1, static_cast<int>(target.at * elements));
    target_element += k;
    target_xi = target.at * elements - k;
  }

  // u_y of the target [m] in `frame`.
  double TargetDeflection(const HapticFrame& frame) const {
    if (target_node >= 0) return NodeMotion(frame, mesh, target_node)[1];
    if (target_body >= 0) return frame.carrier_motion_m(1, mesh.body_carrier[target_body]);
    if (target_element >= 0) return ElementPointMotion(frame, mesh, target_element, target_xi)[1];
    return 0.0;
  }

  StructureDescription structure;
  FrameMesh mesh;
  std::vector<CombDrive> combs;
  bool beam;
  int target_body = -1, target_node = -1, target_element = -1;
  double target_xi = 0.0;
};

// The viewer's state between frames.
class ViewerApp {
 public:
  explicit ViewerApp(const ViewerOptions& options)
      : options_(options),
        headless_(!options.screenshot.empty()),
        scene_(Load({})),
        drawn_(std::make_unique<DrawnStructure>(scene_)),
        settings_(ModelSettings::FromScene(scene_, HapticPhysicsOptions{})),
        panel_(settings_),
        camera_(DefaultCamera(scene_, space_)) {}

  ViewerFigures Run() {
    Window window(options_.width, options_.height, headless_);
    Renderer renderer;
    StartSession(scene_);
    PeriodicDeadline deadline(kDisplayRateHz);
    std::vector<double> draw_ms;
    double first = 0.0, last = 0.0, longest = 0.0;
    std::uint64_t frames = 0;
    while (!glfwWindowShouldClose(window.get()) &&
           (!headless_ || frames < static_cast<std::uint64_t>(options_.frames))) {
      const double start = Now();
      if (frames == 0) first = start;
      if (frames > 0) longest = std::max(longest, start - last);
      last = start;
      ++frames;
      glfwPollEvents();
      const bool final_frame = headless_ && frames == static_cast<std::uint64_t>(options_.frames);
      DrawFrame(window.get(), renderer, frames > 1 ? (frames - 1) / (start - first) : 0.0, longest);
      if (final_frame) {
        int width = 0, height = 0;
        glfwGetFramebufferSize(window.get(), &width, &height);
        WriteScreenshot(options_.screenshot, width, height);
      }
      glfwSwapBuffers(window.get());
      draw_ms.push_back(1e3 * (Now() - start));
      deadline.SleepUntilNext();
    }
    return Finish(window.get(), frames, frames > 1 ? (frames - 1) / (last - first) : 0.0, longest,
                  draw_ms);
  }

 private:
  Scene Load(const std::vector<SceneOverride>& edits) const {
    std::vector<SceneOverride> overrides = options_.overrides;
    overrides.insert(overrides.end(), edits.begin(), edits.end());
    // Whatever analysis the scene declares, the viewer touches it.
    overrides.push_back({"analysis.type", "\"haptic\""});
    return LoadScene(options_.scene, overrides);
  }

  void StartSession(const Scene& scene) {
    session_ =
        ViewerSession::Start(scene, headless_ ? Input::kScript : options_.input, settings_.physics);
    plots_.Clear();
    dragging_ = false;
  }

  // Applies the panel's draft; a draft the loader or the device refuses leaves the running
  // model as it was and says why.
  void Rebuild() {
    const ModelSettings draft = panel_.draft();
    Scene next;
    try {
      next = Load(draft.ToOverrides());
    } catch (const std::exception& e) {
      error_ = e.what();
      return;
    }
    session_.reset();
    const ModelSettings previous = settings_;
    try {
      settings_ = draft;
      StartSession(next);
      scene_ = next;
      drawn_ = std::make_unique<DrawnStructure>(scene_);
      error_.clear();
    } catch (const std::exception& e) {
      error_ = e.what();
      settings_ = previous;
      StartSession(scene_);
    }
  }

  void HandleMouse(const Viewport& viewport) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool in_view = !io.WantCaptureMouse;
    if (in_view && io.MouseWheel != 0.0f) camera_.Zoom(static_cast<double>(io.MouseWheel));
    if (in_view && ImGui::IsMouseDown(ImGuiMouseButton_Right)) {
      camera_.Orbit(static_cast<double>(io.MouseDelta.x), static_cast<double>(io.MouseDelta.y));
    }
    if (in_view && ImGui::IsMouseDown(ImGuiMouseButton_Middle)) {
      camera_.Pan(static_cast<double>(io.MouseDelta.x), static_cast<double>(io.MouseDelta.y),
                  viewport);
    }
    LiveTrajectory* hand = session_->hand();
    if (!hand) return;
    if (in_view && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
      // The stylus moves in the plane through the probe that faces the eye.
      dragging_ = true;
      drag_point_ = space_.ToWorld(session_->frame().probe_m);
      drag_normal_ = (camera_.Eye() - camera_.target()).normalized();
    }
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) dragging_ = false;
    if (!dragging_) return;
    const Ray ray = camera_.Unproject(Eigen::Vector2d(io.MousePos.x, io.MousePos.y), viewport);
    const double facing = ray.direction.dot(drag_normal_);
    if (std::abs(facing) < 1e-6) return;
    const double along = (drag_point_ - ray.origin).dot(drag_normal_) / facing;
    const Eigen::Vector3d world = ray.origin + along * ray.direction;
    hand->MoveTo(session_->opened().settings.scaling.ToDevice(space_.ToMicro(world)));
  }

  void DrawFrame(GLFWwindow* window, Renderer& renderer, double rate_hz, double longest_s) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window, &width, &height);
    const Viewport viewport = SceneViewport(width, height);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (!headless_) HandleMouse(viewport);

    session_->UpdateFrame();
    const HapticFrame& frame = session_->frame();
    plots_.Add(static_cast<float>(1e6 * drawn_->TargetDeflection(frame)),
               static_cast<float>(1e6 * frame.probe_force_n.norm()));

    const Stage stage = BuildStage(scene_, space_);
    BuildDeviceMesh(frame, drawn_->mesh, drawn_->structure, space_, beam_, bodies_);
    for (const CombDrive& comb : drawn_->combs) {
      AddCombFingers(comb, drawn_->structure.bodies[comb.body], CombHalf::kMoving,
                     frame.carrier_motion_m.col(drawn_->mesh.body_carrier[comb.body]), space_,
                     bodies_);
    }
    const double size = FootprintOf(drawn_->structure).Extent();
    const HapticSettings& settings = session_->opened().settings;
    BuildStylus(frame.probe_m, settings.probe.radius, 0.25 * size, space_, stylus_);
    renderer.BeginScene(width, height, viewport,
                        camera_.Projection(viewport.Aspect()) * camera_.View());
    renderer.Draw(stage.substrate, palette::kSubstrate);
    renderer.Draw(stage.electrode, palette::kElectrode);
    renderer.Draw(stage.supports, palette::kSupport);
    renderer.Draw(beam_, palette::kBeam);
    renderer.Draw(bodies_, palette::kBeam);
    renderer.Draw(stylus_, palette::kStylus);
    renderer.EndScene(width, height);

    PanelStatus status;
    status.scene = scene_.source;
    status.device = session_->opened().device->specs().model + std::string(" (") +
                    ToString(session_->input()) + ")";
    status.input_note = session_->input_note();
    status.device_alert = session_->DeviceAlert();
    status.dofs = session_->dofs();
    status.frame = &frame;
    status.servo = session_->opened().device->stats();
    status.display_rate_hz = rate_hz;
    status.frame_interval_max_ms = 1e3 * longest_s;
    status.error = error_;
    const PanelActions actions = panel_.Draw(status, plots_, space_, static_cast<float>(height));
    DrawSurfaceWarning(frame.contact, drawn_->beam ? "beam" : "device", viewport);
    DrawViewCaption(viewport, space_.exaggeration, session_->hand() != nullptr);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (actions.reset) session_->RequestReset();
    if (actions.rebuild) Rebuild();
  }

  ViewerFigures Finish(GLFWwindow* window, std::uint64_t frames, double rate_hz, double longest_s,
                       std::vector<double> draw_ms) {
    session_->Stop();
    session_->UpdateFrame();
    ViewerFigures f;
    f.scene = scene_.source;
    f.input = ToString(session_->input());
    const OpenedDevice& opened = session_->opened();
    f.device = opened.device->specs().model;
    f.screenshot = options_.screenshot;
    glfwGetFramebufferSize(window, &f.width, &f.height);
    f.frames = frames;
    f.display_rate_hz = rate_hz;
    f.frame_interval_max_ms = 1e3 * longest_s;
    if (!draw_ms.empty()) {
      std::sort(draw_ms.begin(), draw_ms.end());
      f.draw_median_ms = draw_ms[draw_ms.size() / 2];
      f.draw_max_ms = draw_ms.back();
    }
    f.servo = opened.device->stats();
    f.physics = session_->physics_stats();
    f.failed_physics_ticks = session_->failed_ticks();
    if (opened.scripted) f.realtime_note = opened.scripted->realtime_note();
    f.contact = session_->frame().contact;
    f.events = session_->frame().events;
    session_.reset();
    return f;
  }

  const ViewerOptions& options_;
  const bool headless_;
  Scene scene_;
  std::unique_ptr<DrawnStructure> drawn_;
  ModelSettings settings_;
  Panel panel_;
  DisplaySpace space_;
  OrbitCamera camera_;
  std::unique_ptr<ViewerSession> session_;
  LivePlots plots_;
  Mesh beam_, bodies_, stylus_;
  std::string error_;
  bool dragging_ = false;
  Eigen::Vector3d drag_point_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d drag_normal_ = Eigen::Vector3d::UnitZ();
};

}  // namespace

ViewerFigures RunViewer(const ViewerOptions& options) { return ViewerApp(options).Run(); }

}  // namespace cosmems::viewer
