#pragma once

namespace cosmems::viewer {

/// A linear RGB colour, each channel in [0, 1].
struct Colour {
  float r, g, b;
};

/// Flat colours, far apart in hue, so that the beam, the substrate and the rest can be told
/// apart on a screenshot pixel by pixel whatever the shading (which scales all three channels
/// alike): the beam orange, the substrate blue, the electrode gold, supports and stylus grey.
namespace palette {
inline constexpr Colour kBackground{0.09f, 0.10f, 0.12f};
inline constexpr Colour kBeam{0.95f, 0.45f, 0.10f};
inline constexpr Colour kSubstrate{0.22f, 0.40f, 0.75f};
inline constexpr Colour kElectrode{0.85f, 0.72f, 0.20f};
inline constexpr Colour kSupport{0.55f, 0.57f, 0.60f};
inline constexpr Colour kStylus{0.85f, 0.86f, 0.90f};
}  // namespace palette

}  // namespace cosmems::viewer
