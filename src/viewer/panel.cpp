#include "panel.hpp"

#include <imgui.h>

#include "viewport.hpp"

namespace cosmems::viewer {
namespace {

const ImVec4 kWarning{1.0f, 0.75f, 0.2f, 1.0f};
const ImVec4 kAlarm{1.0f, 0.35f, 0.3f, 1.0f};
const ImVec4 kFine{0.45f, 0.85f, 0.45f, 1.0f};

// An SI value edited in display units (`scale` of them per SI unit); true once an edit is
// completed.
bool EditScaled(const char* label, double& si, double scale, const char* format) {
  double shown = si * scale;
  if (ImGui::InputDouble(label, &shown, 0.0, 0.0, format)) si = shown / scale;
  return ImGui::IsItemDeactivatedAfterEdit();
}

bool EditInt(const char* label, int& value, int low, int high) {
  ImGui::SliderInt(label, &value, low, high);
  return ImGui::IsItemDeactivatedAfterEdit();
}

ImVec4 StateColour(ContactState state) {
  switch (state) {
    case ContactState::kFree:
      return kFine;
    case ContactState::kNear:
      return kWarning;
    case ContactState::kContact:
      return kWarning;
    case ContactState::kStuck:
      return kAlarm;
  }
  return kAlarm;
}

}  // namespace

PanelActions Panel::Draw(const PanelStatus& status, const LivePlots& plots, DisplaySpace& space,
                         float height) {
  PanelActions actions;
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(kPanelWidth), height));
  ImGui::Begin("cosmems", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-150.0f);
  DrawState(status, actions);
  const float width = ImGui::GetContentRegionAvail().x;
  plots.Draw(IsDevice(draft_.kind)                       ? "deflection at the target"
             : draft_.kind == StructureKind::kCantilever ? "tip deflection"
                                                         : "midspan deflection",
             width);
  DrawFigures(status);
  if (ImGui::CollapsingHeader("Structure and material", ImGuiTreeNodeFlags_DefaultOpen)) {
    actions.rebuild |= DrawStructure();
  }
  if (ImGui::CollapsingHeader("Model", ImGuiTreeNodeFlags_DefaultOpen)) {
    actions.rebuild |= DrawModel();
  }
  if (ImGui::CollapsingHeader("Effects", ImGuiTreeNodeFlags_DefaultOpen)) {
    actions.rebuild |= DrawEffects();
  }
  if (ImGui::CollapsingHeader("View")) {
    float exaggeration = static_cast<float>(space.exaggeration);
    if (ImGui::SliderFloat("vertical scale", &exaggeration, 1.0f, 20.0f, "x %.1f")) {
      space.exaggeration = static_cast<double>(exaggeration);
    }
  }
  if (!status.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kAlarm);
    ImGui::TextWrapped("not applied: %s", status.error.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PopItemWidth();
  ImGui::End();
  return actions;
}

void Panel::DrawState(const PanelStatus& status, PanelActions& actions) const {
  ImGui::TextWrapped("%s", status.scene.c_str());
  ImGui::TextDisabled("%s, %d dofs", status.device.c_str(), status.dofs);
  if (!status.input_note.empty()) ImGui::TextWrapped("%s", status.input_note.c_str());
  if (!status.device_alert.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, kAlarm);
    ImGui::TextWrapped("%s", status.device_alert.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::Separator();
  const ContactState state = status.frame ? status.frame->contact.state : ContactState::kFree;
  const bool stuck = state == ContactState::kStuck;
  if (stuck) {
    ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.7f, 0.15f, 0.12f, 1.0f));
    ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.85f, 0.2f, 0.15f, 1.0f));
  }
  actions.reset = ImGui::Button("Reset Failure", ImVec2(140.0f, 0.0f));
  if (stuck) ImGui::PopStyleColor(2);
  ImGui::SameLine();
  if (stuck) {
    ImGui::TextColored(StateColour(state), "STUCK, %s",
                       status.frame->contact.shape == StuckShape::kArc ? "arc-shaped" : "S-shaped");
  } else {
    ImGui::TextColored(StateColour(state), "%s %s", IsDevice(draft_.kind) ? "device" : "beam",
                       ToString(state));
  }
  if (status.frame) {
    const ContactEvents& e = status.frame->events;
    ImGui::TextDisabled("%ld warnings, %ld contacts, %ld stuck, %ld released", e.proximity_warnings,
                        e.contacts, e.stuck, e.releases);
  }
}

void Panel::DrawFigures(const PanelStatus& status) const {
  const LoopStats& s = status.servo;
  ImGui::Text("display   %.1f Hz (longest frame %.1f ms)", status.display_rate_hz,
              status.frame_interval_max_ms);
  ImGui::Text("servo     %.1f Hz, %s", s.rate_hz,
              s.realtime ? "real-time" : (s.paced ? "paced" : "unpaced"));
  ImGui::Text("tick      median %.0f us, p99 %.0f us, max %.0f us", s.ComputeQuantileUs(0.5),
              s.ComputeQuantileUs(0.99), s.compute_max_us);
  ImGui::Text("deadline misses %llu of %llu ticks",
              static_cast<unsigned long long>(s.deadline_misses),
              static_cast<unsigned long long>(s.ticks));
}

bool Panel::DrawStructure() {
  bool done = false;
  if (IsDevice(draft_.kind)) {
    // A device keeps its kind; a parametric one edits its design keys, rebuilt on each edit.
    ImGui::TextDisabled("structure: %s", ToString(draft_.kind));
    for (DesignParameter& p : draft_.design) {
      if (p.integer) {
        int count = static_cast<int>(p.value);
        ImGui::InputInt(p.key.c_str(), &count);
        p.value = count;
        done |= ImGui::IsItemDeactivatedAfterEdit();
      } else {
        done |= EditScaled((p.key + " [um]").c_str(), p.value, 1e6, "%.2f");
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.meaning.c_str());
    }
    done |= EditScaled("thickness [um]", draft_.thickness_m, 1e6, "%.3f");
    return done | DrawSubstrateAndMaterial();
  }
  int kind = draft_.kind == StructureKind::kCantilever ? 0 : 1;
  if (ImGui::Combo("structure", &kind, "cantilever\0bridge\0")) {
    draft_.kind = kind == 0 ? StructureKind::kCantilever : StructureKind::kBridge;
    done = true;
  }
  done |= EditScaled("length [um]", draft_.length_m, 1e6, "%.2f");
  done |= EditScaled("width [um]", draft_.width_m, 1e6, "%.2f");
  done |= EditScaled("thickness [um]", draft_.thickness_m, 1e6, "%.3f");
  return done | DrawSubstrateAndMaterial();
}

bool Panel::DrawSubstrateAndMaterial() {
  bool done = ImGui::Checkbox("substrate", &draft_.substrate);
  if (draft_.substrate) done |= EditScaled("gap [um]", draft_.gap_m, 1e6, "%.3f");
  done |= EditScaled("E [GPa]", draft_.young_modulus_pa, 1e-9, "%.1f");
  done |= EditScaled("density [kg/m3]", draft_.density_kg_m3, 1.0, "%.0f");
  return done;
}

bool Panel::DrawModel() {
  bool done =
      EditInt(IsDevice(draft_.kind) ? "elements a member" : "elements", draft_.elements, 1, 200);
  int theory = draft_.theory == Theory::kLinear ? 0 : 1;
  if (ImGui::Combo("theory", &theory, "linear\0stretching\0")) {
    draft_.theory = theory == 0 ? Theory::kLinear : Theory::kStretching;
    done = true;
  }
  done |= EditInt("series order", draft_.series_order, 0, 3);
  ImGui::TextDisabled("integrator: generalised-alpha, %d steps a tick", draft_.physics.Substeps());
  done |= EditInt("steps a tick (0: the default)", draft_.physics.substeps, 0, 100);
  float rho = static_cast<float>(draft_.physics.rho_inf);
  if (ImGui::SliderFloat("rho_inf", &rho, 0.0f, 1.0f, "%.2f")) {
    draft_.physics.rho_inf = static_cast<double>(rho);
  }
  done |= ImGui::IsItemDeactivatedAfterEdit();
  return done;
}

bool Panel::DrawEffects() {
  bool done = ImGui::Checkbox("contact", &draft_.contact);
  done |= ImGui::Checkbox("stiction", &draft_.stiction);
  if (draft_.stiction) done |= EditScaled("Gamma [J/m2]", draft_.adhesion_energy_j_m2, 1.0, "%.4f");
  done |= ImGui::Checkbox("electrostatic", &draft_.electrostatic);
  if (draft_.electrostatic) done |= EditScaled("voltage [V]", draft_.voltage_v, 1.0, "%.3f");
  done |= ImGui::Checkbox("Casimir", &draft_.casimir);
  done |= ImGui::Checkbox("van der Waals", &draft_.van_der_waals);
  if (draft_.van_der_waals) done |= EditScaled("Hamaker [J]", draft_.hamaker_j, 1.0, "%.3e");
  return done;
}

}  // namespace cosmems::viewer
