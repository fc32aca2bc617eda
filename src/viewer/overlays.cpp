#include "overlays.hpp"

#include <imgui.h>

namespace cosmems::viewer {
namespace {

constexpr ImGuiWindowFlags kOverlay = ImGuiWindowFlags_NoDecoration |
                                      ImGuiWindowFlags_AlwaysAutoResize |
                                      ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                                      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;

}  // namespace

void DrawSurfaceWarning(const ContactSummary& contact, const char* what, const Viewport& viewport) {
  if (contact.state == ContactState::kFree) return;
  const bool stuck = contact.Stuck();
  ImGui::SetNextWindowPos(ImVec2(viewport.x + 0.5f * viewport.width, viewport.y + 12.0f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::PushStyleColor(ImGuiCol_WindowBg, stuck ? ImVec4(0.55f, 0.08f, 0.06f, 0.92f)
                                                 : ImVec4(0.50f, 0.33f, 0.02f, 0.92f));
  ImGui::Begin("Proximity warning", nullptr, kOverlay);
  switch (contact.state) {
    case ContactState::kNear:
      ImGui::Text("Warning: the %s is close to the substrate", what);
      break;
    case ContactState::kContact:
      ImGui::Text("Warning: the %s touches the substrate", what);
      break;
    case ContactState::kStuck:
      ImGui::Text("Failure: the %s is stuck to the substrate, %s", what, Describe(contact.shape));
      ImGui::TextUnformatted("Press Reset Failure (or the stylus's second button) to free it");
      break;
    case ContactState::kFree:
      break;
  }
  ImGui::End();
  ImGui::PopStyleColor();
}

void DrawViewCaption(const Viewport& viewport, double exaggeration, bool mouse_drives_stylus) {
  ImGui::SetNextWindowPos(ImVec2(viewport.x + 10.0f, viewport.y + viewport.height - 10.0f),
                          ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.45f);
  ImGui::Begin("Caption", nullptr, kOverlay);
  ImGui::Text("y (toward the substrate) drawn x %.1f", exaggeration);
  ImGui::TextDisabled(mouse_drives_stylus
                          ? "left drag: stylus   right drag: orbit   middle drag: pan   wheel: zoom"
                          : "right drag: orbit   middle drag: pan   wheel: zoom");
  ImGui::End();
}

}  // namespace cosmems::viewer
