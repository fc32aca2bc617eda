#pragma once

#include <vector>

namespace cosmems::viewer {

/// The last seconds of the tip's (a bridge's midspan's) deflection and of the probe's force,
/// one sample a displayed frame, drawn as two scrolling plots in the panel.
class LivePlots {
 public:
  explicit LivePlots(int samples = 600);

  /// One displayed frame: the deflection [um, toward the substrate < 0] and the force the beam
  /// pushes the probe with [uN].
  void Add(float deflection_um, float force_un);
  void Clear();
  /// Draws the plots (inside an ImGui window), `width` pixels wide, the first titled
  /// `deflection_label`.
  void Draw(const char* deflection_label, float width) const;

 private:
  std::vector<float> deflection_, force_;
  int next_ = 0;
  int count_ = 0;
};

}  // namespace cosmems::viewer
