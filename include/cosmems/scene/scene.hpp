#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cosmems/beam/beam_description.hpp"
#include "cosmems/scene/scene_effects.hpp"
#include "cosmems/structure/accelerometer.hpp"
#include "cosmems/structure/crab_leg.hpp"
#include "cosmems/structure/folded_flexure.hpp"
#include "cosmems/structure/serpentine.hpp"
#include "cosmems/structure/structure_description.hpp"
#include "cosmems/structure/torsional_micromirror.hpp"

namespace cosmems {

/// The beam theory a scene asks for (model.theory).
enum class Theory {
  kLinear,      ///< "linear": small deflections
  kStretching,  ///< "stretching": mid-plane stretching (K_NL)
  kCosserat,    ///< "cosserat": large deflections
};

/// The analysis a scene runs (analysis.type).
enum class AnalysisType { kStatic, kModal, kBuckling, kPullin, kTransient, kRelease, kHaptic };

/// The haptic device driver of a haptic analysis (device.backend).
enum class DeviceBackend { kScripted, kOpenHaptics };

/// The time integrator of a transient analysis (analysis.integrator).
enum class Integrator {
  kNewmark,            ///< "newmark": Newmark-beta with beta, gamma
  kHht,                ///< "hht": Hilber-Hughes-Taylor with alpha
  kGeneralizedAlpha,   ///< "generalized-alpha": Chung-Hulbert with rho_inf
  kCentralDifference,  ///< "central-difference": explicit, conditionally stable
  kModal,              ///< "modal": model.modes modes propagated exactly
};

/// Where a transient analysis starts (analysis.initial).
enum class InitialState {
  kRest,    ///< "rest": undeformed and still, the loads applied by their time function
  kStatic,  ///< "static": deflected under the loads, which are removed at t = 0
};

/// How the loads vary in time in a transient analysis (loads.time_function).
enum class TimeFunctionKind {
  kStep,  ///< "step": applied at t = 0 and held
  kRamp,  ///< "ramp": rising linearly to full over ramp_time, then held
  kSine,  ///< "sine": times sin(2 pi frequency t)
};

/// The scene-file spelling: "cantilever" | "bridge" | "frame" | "folded_flexure" | "crab_leg" |
/// "serpentine" | "torsional_micromirror" | "accelerometer".
constexpr const char* ToString(StructureKind kind) {
  switch (kind) {
    case StructureKind::kCantilever:
      return "cantilever";
    case StructureKind::kBridge:
      return "bridge";
    case StructureKind::kFrame:
      return "frame";
    case StructureKind::kFoldedFlexure:
      return "folded_flexure";
    case StructureKind::kCrabLeg:
      return "crab_leg";
    case StructureKind::kSerpentine:
      return "serpentine";
    case StructureKind::kTorsionalMicromirror:
      return "torsional_micromirror";
    case StructureKind::kAccelerometer:
      return "accelerometer";
  }
  return "unknown";
}

/// The scene-file spelling: "linear" | "stretching" | "cosserat".
constexpr const char* ToString(Theory theory) {
  switch (theory) {
    case Theory::kLinear:
      return "linear";
    case Theory::kStretching:
      return "stretching";
    case Theory::kCosserat:
      return "cosserat";
  }
  return "unknown";
}

/// The scene-file and JSON spelling: "static" | "modal" | "buckling" | "pullin" | "transient" |
/// "release" | "haptic".
constexpr const char* ToString(AnalysisType type) {
  switch (type) {
    case AnalysisType::kStatic:
      return "static";
    case AnalysisType::kModal:
      return "modal";
    case AnalysisType::kBuckling:
      return "buckling";
    case AnalysisType::kPullin:
      return "pullin";
    case AnalysisType::kTransient:
      return "transient";
    case AnalysisType::kRelease:
      return "release";
    case AnalysisType::kHaptic:
      return "haptic";
  }
  return "unknown";
}

/// The scene-file spelling: "scripted" | "openhaptics".
constexpr const char* ToString(DeviceBackend backend) {
  switch (backend) {
    case DeviceBackend::kScripted:
      return "scripted";
    case DeviceBackend::kOpenHaptics:
      return "openhaptics";
  }
  return "unknown";
}

/// The scene-file and JSON spelling: "newmark" | "hht" | "generalized-alpha" |
/// "central-difference" | "modal".
constexpr const char* ToString(Integrator integrator) {
  switch (integrator) {
    case Integrator::kNewmark:
      return "newmark";
    case Integrator::kHht:
      return "hht";
    case Integrator::kGeneralizedAlpha:
      return "generalized-alpha";
    case Integrator::kCentralDifference:
      return "central-difference";
    case Integrator::kModal:
      return "modal";
  }
  return "unknown";
}

/// The scene-file spelling: "rest" | "static".
constexpr const char* ToString(InitialState initial) {
  switch (initial) {
    case InitialState::kRest:
      return "rest";
    case InitialState::kStatic:
      return "static";
  }
  return "unknown";
}

/// The scene-file spelling: "step" | "ramp" | "sine".
constexpr const char* ToString(TimeFunctionKind kind) {
  switch (kind) {
    case TimeFunctionKind::kStep:
      return "step";
    case TimeFunctionKind::kRamp:
      return "ramp";
    case TimeFunctionKind::kSine:
      return "sine";
  }
  return "unknown";
}

/// [[structure.nodes]]: a named point of a frame, where members meet and anchors hold.
struct SceneNode {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m, on the members' axes
  AnchorMask anchor{};  ///< support: a named support or a list of fixed dofs; none: free
};

/// [[structure.beams]]: a member of a frame between two named nodes.
struct SceneBeam {
  std::vector<std::string> nodes;       ///< from, to
  double width = 0.0;                   ///< m, in the plane, across the member's axis
  std::optional<double> thickness;      ///< m; empty: structure.thickness
  std::optional<int> elements;          ///< empty: model.elements
  std::optional<std::string> material;  ///< a [materials.NAME]; empty: [material]
  Eigen::Vector3d thickness_direction = Eigen::Vector3d::UnitY();
};

/// [[structure.bodies]]: a rigid block of a frame, holding the named nodes.
struct SceneBody {
  std::string name;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< m
  Eigen::Vector3d size = Eigen::Vector3d::Zero();    ///< m along x, y (thickness), z
  std::vector<std::string> nodes;
  std::optional<std::string> material;  ///< a [materials.NAME]; empty: [material]
};

/// [structure]: the beam's shape and supports, in metres (x runs along the beam from the first
/// support, y away from the substrate, z across the width), or a frame's netlist.
struct SceneStructure {
  StructureKind kind = StructureKind::kCantilever;
  double length = 0.0;        ///< m (beams)
  double width = 0.0;         ///< m, along z (beams)
  double thickness = 0.0;     ///< m, along y; a frame's default for its members
  std::optional<double> gap;  ///< m between the lower face and the substrate; empty: no substrate
  double axial_load = 0.0;    ///< N, residual axial force, tension > 0 (beams)
  std::vector<SceneNode> nodes;   ///< frames
  std::vector<SceneBeam> beams;   ///< frames
  std::vector<SceneBody> bodies;  ///< frames
  /// The parametric devices' geometries, each read when `kind` names it (the thickness,
  /// material, elements per member and series order come from structure.thickness, [material]
  /// and [model]).
  FoldedFlexureDesign folded_flexure;
  CrabLegDesign crab_leg;
  SerpentineDesign serpentine;
  TorsionalMicromirrorDesign torsional_micromirror;
  AccelerometerDesign accelerometer;
};

/// [material]: an isotropic linear-elastic material.
struct SceneMaterial {
  double young_modulus = 0.0;   ///< E [Pa]
  double density = 0.0;         ///< rho [kg/m^3]
  double poisson_ratio = 0.22;  ///< nu [-], in (-1, 0.5)
  bool plate_modulus = false;   ///< true: the beam bends with E / (1 - nu^2) (wide beams)
};

/// [model]: how the beam is discretised.
struct SceneModel {
  Theory theory = Theory::kLinear;
  int dimension = 3;     ///< 2: planar (ux, uy, rz); 3: full 3-D frame
  int elements = 20;     ///< equal elements along the beam
  int series_order = 1;  ///< power-series terms: 0 = Hermite + consistent mass, 1 adds M2, ...
  int modes = 0;         ///< 0: the full model; k > 0: k modes (the "modal" integrator)
};

/// [loads] time_function and its parameters: the amplitude s(t) that multiplies every load of
/// a transient analysis. Static and modal analyses take the loads as they are.
struct SceneTimeFunction {
  TimeFunctionKind kind = TimeFunctionKind::kStep;
  double ramp_time = 0.0;  ///< s, > 0: the rise time of a ramp (kRamp only)
  double frequency = 0.0;  ///< Hz, > 0: s(t) = sin(2 pi frequency t) (kSine only)
};

/// [[loads.points]]: a force and a moment at a frame's node or at a body's centre.
struct ScenePointLoad {
  std::optional<std::string> node;
  std::optional<std::string> body;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< N
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< N m
};

/// [loads]: loads in SI, components along x, y, z.
struct SceneLoads {
  Eigen::Vector3d tip_force = Eigen::Vector3d::Zero();      ///< N at the free end (cantilever)
  Eigen::Vector3d midspan_force = Eigen::Vector3d::Zero();  ///< N at x = length / 2
  Eigen::Vector3d distributed = Eigen::Vector3d::Zero();    ///< N/m over the whole length
  Eigen::Vector3d tip_moment = Eigen::Vector3d::Zero();     ///< N m at the free end (cantilever)
  std::vector<ScenePointLoad> points;                       ///< a frame's loads at nodes, bodies
  /// Empty when the scene does not give loads.time_function: a step.
  std::optional<SceneTimeFunction> time_function;
};

/// [analysis]: what to compute, and the parameters of that analysis. Only the chosen analysis
/// reads its parameters; the others keep their defaults.
struct SceneAnalysis {
  AnalysisType type = AnalysisType::kStatic;
  int count = 4;  ///< modal: the number of modes, lowest first

  // transient
  double duration = 0.0;   ///< s, > 0
  double time_step = 0.0;  ///< s, in (0, duration], at most 1e8 steps
  Integrator integrator = Integrator::kNewmark;
  double beta = 0.25;    ///< newmark, in [0, 0.5]
  double gamma = 0.5;    ///< newmark, in [0.5, 1]
  double alpha = 0.05;   ///< hht, in [0, 1/3]
  double rho_inf = 0.8;  ///< generalized-alpha: spectral radius at infinite frequency, in [0, 1]
  InitialState initial = InitialState::kRest;
  /// a device: the nodes and bodies whose motion history.csv holds besides every body's centre
  std::vector<std::string> record;

  // pullin
  std::optional<double> voltage_max;  ///< V: search no further than this voltage

  // haptic (duration above: empty or 0 runs the whole trajectory)
  double rate = 1000.0;  ///< Hz, the servo rate (and the physics tick)
};

/// [device]: the haptic device of a haptic analysis.
struct SceneDevice {
  DeviceBackend backend = DeviceBackend::kScripted;
  std::string trajectory = "press";  ///< a built-in motion or a CSV file (time_s, x_m, y_m, z_m)
  bool realtime = false;             ///< true: paced at the rate on the wall clock
  // Hand <-> micro world (HandScaling); empty: derived from the structure and the device.
  std::optional<double> position_scale;      ///< hand m per micro m (default 5000)
  std::optional<double> force_scale;         ///< hand N per micro N (default: the coupling is
                                             ///< felt at half the device's renderable stiffness)
  std::optional<double> coupling_stiffness;  ///< N/m, stylus-probe spring (default 25 k_struct)
  std::optional<double> probe_radius;        ///< m, the stylus tip (default: the thickness)
  /// A device's node or body the built-in motions press (default: its first body).
  std::optional<std::string> target;
};

/// A scene file in typed form: SI units, the documented defaults for every optional key
/// (see doc/scenes.md). LoadScene and its siblings produce only validated scenes.
struct Scene {
  std::string source;  ///< the file path as given, or the embedded scene's name
  SceneStructure structure;
  SceneMaterial material;  ///< a frame may leave it out when every entry names its material
  std::map<std::string, SceneMaterial> materials;  ///< [materials.NAME] (frames)
  SceneModel model;
  SceneLoads loads;
  SceneEffects effects;
  SceneAnalysis analysis;
  std::optional<SceneDevice> device;
};

}  // namespace cosmems
