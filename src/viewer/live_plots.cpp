#include "live_plots.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace cosmems::viewer {
namespace {

// A plot of the ring `values` (oldest at `next` once full) with its newest value as the overlay;
// the vertical range covers the data and `floor` at least, so a still beam is not magnified.
void PlotRing(const char* label, const char* unit, const std::vector<float>& values, int count,
              int next, float floor, float width) {
  const int size = static_cast<int>(values.size());
  const int offset = count < size ? 0 : next;
  float low = -floor, high = floor;
  for (int i = 0; i < count; ++i) {
    low = std::min(low, values[static_cast<std::size_t>(i)]);
    high = std::max(high, values[static_cast<std::size_t>(i)]);
  }
  char overlay[64] = "";
  if (count > 0) {
    const float newest = values[static_cast<std::size_t>((next + size - 1) % size)];
    std::snprintf(overlay, sizeof(overlay), "%.3g %s", static_cast<double>(newest), unit);
  }
  ImGui::TextUnformatted(label);
  ImGui::PushID(label);
  ImGui::PlotLines("##plot", values.data(), count, offset, overlay, low, high,
                   ImVec2(width, 56.0f));
  ImGui::PopID();
}

}  // namespace

LivePlots::LivePlots(int samples)
    : deflection_(static_cast<std::size_t>(samples)), force_(static_cast<std::size_t>(samples)) {}

void LivePlots::Add(float deflection_um, float force_un) {
  deflection_[static_cast<std::size_t>(next_)] = deflection_um;
  force_[static_cast<std::size_t>(next_)] = force_un;
  next_ = (next_ + 1) % static_cast<int>(deflection_.size());
  count_ = std::min(count_ + 1, static_cast<int>(deflection_.size()));
}

void LivePlots::Clear() {
  next_ = 0;
  count_ = 0;
}

void LivePlots::Draw(const char* deflection_label, float width) const {
  PlotRing(deflection_label, "um", deflection_, count_, next_, 0.1f, width);
  PlotRing("probe force", "uN", force_, count_, next_, 0.1f, width);
}

}  // namespace cosmems::viewer
