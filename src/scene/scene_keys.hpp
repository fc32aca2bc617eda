#pragma once

#include <Eigen/Core>
#include <array>
#include <initializer_list>
#include <optional>
#include <string>

#include "cosmems/scene/scene.hpp"
#include "scene_limits.hpp"

namespace cosmems::internal {

// Every key of a scene, once: its name, the field it fills, what it accepts, its default and what
// it means. The reader reads and validates a table by visiting its keys (KeyReader), the unknown
// keys are those its visit does not name, and `cosmems keys` prints the visits as the key
// reference of doc/scenes.md (KeyReference). What ties keys together (a time step within the
// duration, a surface effect that needs the gap) is checked after, in scene_reader.cpp.
//
// A visitor V has, for a key NAME of the table it visits:
//   Required(NAME, double&, NumberRule, meaning)
//   Number(NAME, double&, NumberRule, meaning)                        default: the field's value
//   Number(NAME, std::optional<double>&, NumberRule, default, meaning)  default: in words
//   Integer(NAME, int&, IntegerRange, meaning)
//   Flag(NAME, bool&, meaning)
//   Choice(NAME, Enum&, options, what, meaning) and RequiredChoice(...)
//   Text(NAME, std::string&, meaning)
//   Vector(NAME, Eigen::Vector3d&, Bounds, meaning)
//   Pair(NAME, std::optional<std::array<double, 2>>&, Bounds, Bounds, meaning)
//   Interval(NAME, std::array<double, 2>&, Bounds, meaning)  required [from, to], from < to
//   Position(NAME, std::optional<double>&, meaning)       a point of the beam, in [0, length]
//   Design(NAME, kind, {{KIND, &field}, ...}, NumberRule or IntegerRange, meaning)
//       a parametric device's design key, one meaning for every KIND listed: read into the
//       field of the scene's `kind` (its value is that device's default), refused for others
// and Scope(owner, chosen, unchosen): the keys after it belong to `owner` (an analysis type, an
// integrator, a time function); when it is not the chosen one they are skipped, or refused.

/// What a number accepts: its sign, then its bounds (`range` spells them when a fraction reads
/// better than digits); open: the bounds themselves excluded.
enum class Sign { kAny, kPositive, kNonNegative };
struct NumberRule {
  Sign sign;
  Bounds bounds;
  bool open = false;
  const char* range = nullptr;
};
constexpr NumberRule Positive(Bounds b) { return {Sign::kPositive, b}; }
constexpr NumberRule NonNegative(Bounds b) { return {Sign::kNonNegative, b}; }
constexpr NumberRule AnySign(Bounds b) { return {Sign::kAny, b}; }

/// An integer in [lower, upper].
struct IntegerRange {
  int lower;
  int upper;
};

/// What a scoped key does when its owner is not chosen: it is skipped (the parameters of another
/// analysis type, kept so that --set can switch), or refused (a parameter of another integrator
/// or time function shows an intent the run would not follow).
enum class Unchosen { kSkipped, kRefused };

inline constexpr std::array kStructureKinds = {
    StructureKind::kCantilever,           StructureKind::kBridge,       StructureKind::kFrame,
    StructureKind::kFoldedFlexure,        StructureKind::kCrabLeg,      StructureKind::kSerpentine,
    StructureKind::kTorsionalMicromirror, StructureKind::kAccelerometer};
inline constexpr std::array kTheories = {Theory::kLinear, Theory::kStretching, Theory::kCosserat};
inline constexpr std::array kAnalysisTypes = {AnalysisType::kStatic,    AnalysisType::kModal,
                                              AnalysisType::kBuckling,  AnalysisType::kPullin,
                                              AnalysisType::kTransient, AnalysisType::kRelease,
                                              AnalysisType::kHaptic};
inline constexpr std::array kDeviceBackends = {DeviceBackend::kScripted,
                                               DeviceBackend::kOpenHaptics};
inline constexpr std::array kIntegrators = {Integrator::kNewmark, Integrator::kHht,
                                            Integrator::kGeneralizedAlpha,
                                            Integrator::kCentralDifference, Integrator::kModal};
inline constexpr std::array kHapticIntegrators = {Integrator::kGeneralizedAlpha,
                                                  Integrator::kModal};
inline constexpr std::array kInitialStates = {InitialState::kRest, InitialState::kStatic};
inline constexpr std::array kTimeFunctions = {TimeFunctionKind::kStep, TimeFunctionKind::kRamp,
                                              TimeFunctionKind::kSine};

/// A design key's field in the design of one parametric device that reads it.
template <class T>
struct DesignField {
  StructureKind kind;
  T* field;
};
template <class T>
using DesignFields = std::initializer_list<DesignField<T>>;

/// The field of `kind`'s design, or nullptr when that kind reads no such key.
template <class T>
T* ChosenDesign(StructureKind kind, DesignFields<T> fields) {
  for (const DesignField<T>& f : fields) {
    if (f.kind == kind) return f.field;
  }
  return nullptr;
}

/// The devices that read a design key: structure.kind = "a", "b" or "c".
template <class T>
std::string DesignOwner(DesignFields<T> fields) {
  std::string owner = "structure.kind = ";
  std::size_t i = 0;
  for (const DesignField<T>& f : fields) {
    const char* separator = i == 0 ? "" : (i + 1 == fields.size() ? " or " : ", ");
    owner += separator + std::string("\"") + ToString(f.kind) + "\"";
    ++i;
  }
  return owner;
}

template <class V>
void VisitNode(V& v, SceneNode& n) {
  v.RequiredText("name", n.name, "unique; beams, bodies and loads refer to it");
  v.RequiredVector("position", n.position, kCoordinate, "on the members' centroid axes");
  v.Anchor("support", n.anchor,
           "\"free\" (default), \"clamped\", \"pinned\", \"guided\", or a list of the fixed dofs "
           "(\"ux\", \"uy\", \"uz\", \"rx\", \"ry\", \"rz\")");
}

template <class V>
void VisitBeam(V& v, SceneBeam& b) {
  v.Names("nodes", b.nodes, 2, "from, to: two named nodes");
  v.Required("width", b.width, Positive(kLength), "in the plane, across the member's axis");
  v.Number("thickness", b.thickness, Positive(kLength), "structure.thickness",
           "along its thickness direction");
  v.Integer("elements", b.elements, IntegerRange{1, kMaxElements}, "model.elements",
            "equal elements along the member");
  v.OptionalText("material", b.material, "[material]", "a [materials.NAME] table");
  v.Vector("thickness_direction", b.thickness_direction, kDirection,
           "only for a member not parallel to the substrate");
}

template <class V>
void VisitBody(V& v, SceneBody& b) {
  v.RequiredText("name", b.name, "unique among bodies; loads and results refer to it");
  v.RequiredVector("center", b.center, kCoordinate, "the block's centre");
  v.RequiredVector("size", b.size, kLength, "extents along x, y (thickness) and z, each > 0");
  v.Names("nodes", b.nodes, 0, "the nodes attached rigidly to the body (one or more)");
  v.OptionalText("material", b.material, "[material]",
                 "a [materials.NAME] table; its density gives mass and rotary inertia");
}

// The parametric devices' design keys, each once, with the devices that read it: a key several
// devices read means the same in each.
template <class V>
void VisitDesigns(V& v, SceneStructure& s) {
  using K = StructureKind;
  const K kind = s.kind;
  FoldedFlexureDesign& ff = s.folded_flexure;
  CrabLegDesign& cl = s.crab_leg;
  SerpentineDesign& sp = s.serpentine;
  TorsionalMicromirrorDesign& tm = s.torsional_micromirror;
  AccelerometerDesign& ac = s.accelerometer;
  const NumberRule length = Positive(kLength);
  v.Design("beam_length", kind,
           {{K::kFoldedFlexure, &ff.beam_length},
            {K::kTorsionalMicromirror, &tm.beam_length},
            {K::kAccelerometer, &ac.beam_length}},
           length, "each suspension beam's length");
  v.Design("beam_width", kind,
           {{K::kFoldedFlexure, &ff.beam_width},
            {K::kSerpentine, &sp.beam_width},
            {K::kTorsionalMicromirror, &tm.beam_width},
            {K::kAccelerometer, &ac.beam_width}},
           length, "each suspension beam's width, in the plane");
  v.Design("beam_spacing", kind, {{K::kFoldedFlexure, &ff.beam_spacing}}, length,
           "between an inner and an outer beam's axes");
  v.Design("truss_width", kind, {{K::kFoldedFlexure, &ff.truss_width}}, length,
           "the trusses' extent along z");
  v.Design("shuttle_width", kind,
           {{K::kFoldedFlexure, &ff.shuttle_width}, {K::kCrabLeg, &cl.shuttle_width}}, length,
           "the shuttle's extent along x, the direction it moves in");
  v.Design("shuttle_length", kind,
           {{K::kFoldedFlexure, &ff.shuttle_length}, {K::kCrabLeg, &cl.shuttle_length}}, length,
           "the shuttle's extent along z");
  v.Design("thigh_length", kind, {{K::kCrabLeg, &cl.thigh_length}}, length,
           "each leg's thigh, along x from its knee to its anchor");
  v.Design("thigh_width", kind, {{K::kCrabLeg, &cl.thigh_width}}, length,
           "the thighs' width, in the plane");
  v.Design("shin_length", kind, {{K::kCrabLeg, &cl.shin_length}}, length,
           "each leg's shin, along z from the shuttle to its knee");
  v.Design("shin_width", kind, {{K::kCrabLeg, &cl.shin_width}}, length,
           "the shins' width, in the plane");
  v.Design("span_length", kind, {{K::kSerpentine, &sp.span_length}}, length,
           "each spring's long segments, along z");
  v.Design("connector_length", kind, {{K::kSerpentine, &sp.connector_length}}, length,
           "each spring's short segments, along x: the spans' pitch");
  v.Design("turns", kind, {{K::kSerpentine, &sp.turns}}, IntegerRange{1, kMaxTurns},
           "the spans of each spring");
  v.Design("plate_width", kind,
           {{K::kSerpentine, &sp.plate_width}, {K::kTorsionalMicromirror, &tm.plate_width}}, length,
           "the plate's extent along x");
  v.Design("plate_length", kind,
           {{K::kSerpentine, &sp.plate_length}, {K::kTorsionalMicromirror, &tm.plate_length}},
           length, "the plate's extent along z");
  v.Design("mass_width", kind, {{K::kAccelerometer, &ac.mass_width}}, length,
           "the proof mass's extent along x, the sensitive direction");
  v.Design("mass_length", kind, {{K::kAccelerometer, &ac.mass_length}}, length,
           "the proof mass's extent along z");
}

template <class V>
void VisitStructure(V& v, SceneStructure& s) {
  v.RequiredChoice("kind", s.kind, kStructureKinds, "structure kind",
                   "a cantilever (clamped at x = 0, free at the tip), a bridge (both ends "
                   "clamped), a frame (a netlist of nodes, beams and rigid bodies), or a "
                   "parametric device: the folded-flexure or the crab-leg resonator, the "
                   "serpentine-suspended plate, the torsional micromirror or the proof-mass "
                   "accelerometer");
  v.Required("thickness", s.thickness, Positive(kLength),
             "along y, normal to the substrate (a frame's default for its members)");
  v.Number("gap", s.gap, Positive(kLength), "no substrate", "from the lower face to the substrate");
  v.Scope("a cantilever or a bridge", !IsDevice(s.kind), Unchosen::kRefused);
  v.Required("length", s.length, Positive(kLength), "along x");
  v.Required("width", s.width, Positive(kLength), "along z, in the substrate's plane");
  v.Number("axial_load", s.axial_load, AnySign(kForce), "residual axial force, tension > 0");
  v.Scope("structure.kind = \"frame\"", s.kind == StructureKind::kFrame, Unchosen::kRefused);
  v.Entries(
      "nodes", s.nodes, [](auto& e, SceneNode& n) { VisitNode(e, n); },
      "[[structure.nodes]]: the frame's named points");
  v.Entries(
      "beams", s.beams, [](auto& e, SceneBeam& b) { VisitBeam(e, b); },
      "[[structure.beams]]: members between two nodes, each meshed into model.elements");
  v.Entries(
      "bodies", s.bodies, [](auto& e, SceneBody& b) { VisitBody(e, b); },
      "[[structure.bodies]]: rigid blocks (plates, shuttles, proof masses, mirrors)");
  VisitDesigns(v, s);
}

template <class V>
void VisitMaterial(V& v, SceneMaterial& m) {
  v.Required("young_modulus", m.young_modulus, Positive(kYoungModulus), "E");
  v.Required("density", m.density, Positive(kDensity), "rho");
  v.Number("poisson_ratio", m.poisson_ratio, NumberRule{Sign::kAny, {-1.0, 0.5, ""}, true}, "nu");
  v.Flag("plate_modulus", m.plate_modulus, "true: the beam bends with E / (1 - nu^2) (wide beams)");
}

template <class V>
void VisitModel(V& v, SceneModel& m) {
  v.Choice("theory", m.theory, kTheories, "theory",
           "small deflections; mid-plane stretching (a bridge, or every member of a device); "
           "large deflections (the Cosserat rod, one beam, 3-D only)");
  v.Integer("dimension", m.dimension, IntegerRange{2, 3},
            "3: the full frame; 2: planar (u_x, u_y, theta_z)");
  v.Integer("elements", m.elements, IntegerRange{1, kMaxElements}, "equal elements along the beam");
  v.Integer("series_order", m.series_order, IntegerRange{0, kMaxSeriesOrder},
            "power-series terms of the mass: 0 = Hermite with consistent mass, 1 adds M_2, ...");
  v.Integer("modes", m.modes, IntegerRange{0, kMaxModes},
            "0: the full model; k > 0: k modes (the \"modal\" integrator)");
}

template <class V>
void VisitPointLoad(V& v, ScenePointLoad& p) {
  v.OptionalText("node", p.node, "none", "the node the load acts at; or:");
  v.OptionalText("body", p.body, "none", "the body at whose centre it acts");
  v.Vector("force", p.force, kForce, "N");
  v.Vector("moment", p.moment, kMoment, "N m, about the node or the body's centre");
}

template <class V>
void VisitLoads(V& v, SceneLoads& l, SceneTimeFunction& f, TimeFunctionKind chosen,
                StructureKind kind) {
  v.Vector("distributed", l.distributed, kForcePerLength,
           "over the whole length (a frame: over every member)");
  v.Choice("time_function", f.kind, kTimeFunctions, "time function",
           "the amplitude of every load in a transient: held from t = 0, rising linearly over "
           "ramp_time, or sin(2 pi frequency t)");
  v.Scope("the \"ramp\" time function", chosen == TimeFunctionKind::kRamp, Unchosen::kRefused);
  v.Required("ramp_time", f.ramp_time, Positive(kTime), "the ramp's rise time");
  v.Scope("the \"sine\" time function", chosen == TimeFunctionKind::kSine, Unchosen::kRefused);
  v.Required("frequency", f.frequency, Positive(kFrequency), "the sine's frequency");
  v.Scope("a cantilever or a bridge", !IsDevice(kind), Unchosen::kRefused);
  v.Vector("tip_force", l.tip_force, kForce, "at the free end (cantilever only)");
  v.Vector("midspan_force", l.midspan_force, kForce, "at x = length / 2");
  v.Vector("tip_moment", l.tip_moment, kMoment, "at the free end (cantilever only)");
  v.Scope("a device", IsDevice(kind), Unchosen::kRefused);
  v.Entries(
      "points", l.points, [](auto& e, ScenePointLoad& p) { VisitPointLoad(e, p); },
      "[[loads.points]]: a force and a moment at a node or a body's centre");
}

template <class V>
void VisitContact(V& v, ContactEffect& c) {
  v.Flag("enabled", c.enabled, "false: declared but not simulated");
  v.Number("separation", c.separation, NonNegative(kLengthOrZero),
           "0; a hundredth of the gap with a surface pressure (infinite at contact)",
           "how close the faces come in contact (asperities, an oxide); below half the gap");
  v.Number("tolerance", c.tolerance, Positive(kLength), "1e-4 of the gap",
           "the penetration accepted");
  v.Number("proximity", c.proximity, Positive(kLength), "a tenth of the gap",
           "the gap below which the beam is near (the proximity warning)");
}

template <class V>
void VisitStiction(V& v, StictionEffect& s) {
  v.Flag("enabled", s.enabled, "false: declared but not simulated");
  v.Number("adhesion_energy", s.adhesion_energy, NonNegative(kAdhesionEnergy), "required, > 0",
           "the work of adhesion Gamma; stiction implies contact");
}

// A transducer's alternating drive in a transient, V(t) = voltage + ac_voltage sin(2 pi f t).
template <class V>
void VisitAlternatingVoltage(V& v, double& ac_voltage, std::optional<double>& frequency) {
  v.Number("ac_voltage", ac_voltage, AnySign(kVoltage),
           "in a transient, the amplitude of the alternating part: V(t) = voltage + ac_voltage "
           "sin(2 pi frequency t)");
  v.Number("frequency", frequency, Positive(kFrequency), "required with ac_voltage",
           "of the alternating part");
}

template <class V>
void VisitElectrode(V& v, SceneElectrode& e) {
  v.Interval("x", e.x, kCoordinate, "the rectangle's extent along x, [from, to]");
  v.Interval("z", e.z, kCoordinate, "the rectangle's extent along z, [from, to]");
}

template <class V>
void VisitElectrostatic(V& v, ElectrostaticEffect& e, StructureKind kind) {
  v.Flag("enabled", e.enabled, "false: declared but not simulated");
  v.Number("voltage", e.voltage, AnySign(kVoltage), "required, except by a pull-in analysis",
           "across the gap (a pull-in analysis finds it)");
  v.Flag("fringing", e.fringing, "true: add the fringing-field correction");
  v.Scope("a cantilever or a bridge", !IsDevice(kind), Unchosen::kRefused);
  v.Position("electrode_start", e.electrode_start, "the electrode's start; default: x = 0");
  v.Position("electrode_end", e.electrode_end, "the electrode's end; default: the length");
  v.Scope("a device", IsDevice(kind), Unchosen::kRefused);
  v.Entries(
      "electrodes", e.electrodes, [](auto& c, SceneElectrode& r) { VisitElectrode(c, r); },
      "rectangles on the substrate, e.g. [ { x = [0.0, 40e-6], z = [-30e-6, 30e-6] } ]; none: one "
      "under all of the device");
  VisitAlternatingVoltage(v, e.ac_voltage, e.frequency);
}

template <class V>
void VisitCasimir(V& v, CasimirEffect& c) {
  v.Flag("enabled", c.enabled, "false: declared but not simulated");
}

template <class V>
void VisitVanDerWaals(V& v, VanDerWaalsEffect& w) {
  v.Flag("enabled", w.enabled, "false: declared but not simulated");
  v.Number("hamaker", w.hamaker, Positive(kHamaker), "required", "the Hamaker constant");
}

template <class V>
void VisitDamping(V& v, DampingEffect& d) {
  v.Flag("enabled", d.enabled, "false: declared but not simulated");
  v.Number("quality_factor", d.quality_factor, Positive(kQualityFactor),
           "quality_factor or rayleigh is required", "Q of every mode");
  v.Pair("rayleigh", d.rayleigh, kRayleighAlpha, kRayleighBeta,
         "[alpha, beta]: C = alpha M + beta K");
}

template <class V>
void VisitSqueezeFilm(V& v, SqueezeFilmEffect& s) {
  v.Flag("enabled", s.enabled, "false: declared but not simulated");
  v.Number("viscosity", s.viscosity, Positive(kViscosity), "air at 20 C, 1.81e-5",
           "the gas's dynamic viscosity");
  v.Number("mean_free_path", s.mean_free_path, NonNegative(kLengthOrZero), "0: no rarefaction",
           "the gas's mean free path (68e-9 for air at 1 atm adds the slip)");
}

template <class V>
void VisitComb(V& v, SceneComb& c) {
  v.Text("body", c.body, "the body carrying the movable fingers");
  v.Integer("fingers", c.fingers, IntegerRange{1, kMaxFingers},
            "movable fingers, each between two fixed ones");
  v.Required("gap", c.gap, Positive(kLength), "between a finger and each fixed neighbour");
  v.Required("overlap", c.overlap, Positive(kLength), "the fingers' engagement at rest");
  v.Vector("direction", c.direction, kDirection,
           "the direction the comb engages in, in the substrate plane (y = 0)");
  v.Required("voltage", c.voltage, AnySign(kVoltage), "across the fingers");
  VisitAlternatingVoltage(v, c.ac_voltage, c.frequency);
}

// The keys of [effects] itself (its tables are read one by one).
template <class V>
void VisitEffects(V& v, SceneEffects& e, StructureKind kind) {
  v.Scope("a device", IsDevice(kind), Unchosen::kRefused);
  v.Entries(
      "combs", e.combs, [](auto& c, SceneComb& comb) { VisitComb(c, comb); },
      "[[effects.combs]]: comb drives between a body and an anchor: the engagement force "
      "fingers eps0 t V^2 / gap at the body's centre, t the body's thickness");
}

template <class V>
void VisitAnalysis(V& v, SceneAnalysis& a, AnalysisType type, Integrator integrator,
                   StructureKind kind) {
  v.RequiredChoice("type", a.type, kAnalysisTypes, "analysis type", "what to compute");
  v.Scope("analysis.type = \"modal\"", type == AnalysisType::kModal, Unchosen::kSkipped);
  v.Integer("count", a.count, IntegerRange{1, kMaxModes}, "the modes, lowest first");
  const bool transient = type == AnalysisType::kTransient;
  v.Scope("analysis.type = \"transient\"", transient, Unchosen::kSkipped);
  v.Required("duration", a.duration, Positive(kTime), "simulated time");
  v.Required("time_step", a.time_step, Positive(kTime), "at most the duration, 1e8 steps");
  v.Choice("integrator", a.integrator, kIntegrators, "integrator",
           "Newmark-beta, HHT-alpha, generalised-alpha, explicit central difference, or "
           "model.modes modes propagated exactly");
  v.Choice("initial", a.initial, kInitialStates, "initial state",
           "undeformed at rest, or deflected under the loads, which are removed at t = 0");
  v.Scope("a device's transient", transient && IsDevice(kind),
          transient ? Unchosen::kRefused : Unchosen::kSkipped);
  v.OptionalNames("record", a.record, "the bodies",
                  "nodes and bodies whose displacement history.csv holds, then every other "
                  "body's centre; the first point's largest static component is watched");
  // Another integrator's parameter is refused in a transient, carried by the other types.
  const Unchosen other = transient ? Unchosen::kRefused : Unchosen::kSkipped;
  v.Scope("the \"newmark\" integrator", transient && integrator == Integrator::kNewmark, other);
  v.Number("beta", a.beta, AnySign({0.0, 0.5, ""}), "Newmark's beta");
  v.Number("gamma", a.gamma, AnySign({0.5, 1.0, ""}), "Newmark's gamma");
  v.Scope("the \"hht\" integrator", transient && integrator == Integrator::kHht, other);
  v.Number("alpha", a.alpha, NumberRule{Sign::kAny, {0.0, 1.0 / 3.0, ""}, false, "[0, 1/3]"},
           "HHT's alpha");
  v.Scope("the \"generalized-alpha\" integrator",
          transient && integrator == Integrator::kGeneralizedAlpha, other);
  v.Number("rho_inf", a.rho_inf, AnySign({0.0, 1.0, ""}),
           "the spectral radius at infinite frequency");
  v.Scope("analysis.type = \"pullin\"", type == AnalysisType::kPullin, Unchosen::kSkipped);
  v.Number("voltage_max", a.voltage_max, Positive(kVoltageMax), "none",
           "no fold below it: \"not converged\"");
  // The haptic analysis's duration and integrator mean what the transient's do, with their own
  // defaults and choices.
  v.Scope("analysis.type = \"haptic\"", type == AnalysisType::kHaptic, Unchosen::kSkipped);
  std::optional<double> session;
  Integrator stepping = Integrator::kGeneralizedAlpha;
  v.Number("duration", session, Positive(kHapticDuration),
           "the whole trajectory; openhaptics: 30 s",
           "the session's length (a built-in motion fitted to it in cycles of about 2 s)");
  v.Choice("integrator", stepping, kHapticIntegrators, "haptic integrator",
           "the full model, or model.modes modes with the forces held over each step");
  v.Number("rate", a.rate, AnySign({500.0, 2000.0, "Hz"}),
           "the servo rate and physics tick: 500, 1000 or 2000");
  if (type == AnalysisType::kHaptic) {
    a.duration = session.value_or(0.0);
    a.integrator = stepping;
  }
}

template <class V>
void VisitDevice(V& v, SceneDevice& d) {
  v.Choice("backend", d.backend, kDeviceBackends, "device backend",
           "a scripted stylus, or a PHANTOM Omni / Touch through OpenHaptics");
  v.Text("trajectory", d.trajectory,
         "scripted: \"press\", \"sweep\", \"tap\" or a CSV file time_s,x_m,y_m,z_m");
  v.Flag("realtime", d.realtime,
         "true: paced on the wall clock, physics on its own thread; false: as fast as possible");
  v.Number("position_scale", d.position_scale, Positive(kScale), "5000",
           "hand metres per micro metre");
  v.Number("force_scale", d.force_scale, Positive(kScale),
           "the coupling felt at half the device's renderable stiffness",
           "hand newtons per micro newton (larger is an error)");
  v.Number("coupling_stiffness", d.coupling_stiffness, Positive(kStiffness),
           "25 times the structure's stiffness under the probe", "the stylus-probe spring, N/m");
  v.Number("probe_radius", d.probe_radius, Positive(kLength), "the thickness",
           "the stylus tip's radius");
  v.OptionalText("target", d.target, "a device's first body",
                 "the device's node or body the built-in motions press (devices only)");
}

}  // namespace cosmems::internal
