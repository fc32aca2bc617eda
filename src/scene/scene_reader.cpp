#include "scene_reader.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "scene_limits.hpp"
#include "toml_field_reader.hpp"
#include "toml_format.hpp"

namespace cosmems::internal {
namespace {

constexpr std::array kStructureKinds = {StructureKind::kCantilever, StructureKind::kBridge};
constexpr std::array kTheories = {Theory::kLinear, Theory::kStretching, Theory::kCosserat};
constexpr std::array kAnalysisTypes = {AnalysisType::kStatic,    AnalysisType::kModal,
                                       AnalysisType::kBuckling,  AnalysisType::kPullin,
                                       AnalysisType::kTransient, AnalysisType::kRelease,
                                       AnalysisType::kHaptic};
constexpr std::array kDeviceBackends = {DeviceBackend::kScripted, DeviceBackend::kOpenHaptics};
constexpr std::array kIntegrators = {Integrator::kNewmark, Integrator::kHht,
                                     Integrator::kGeneralizedAlpha, Integrator::kCentralDifference,
                                     Integrator::kModal};
constexpr std::array kInitialStates = {InitialState::kRest, InitialState::kStatic};
constexpr std::array kTimeFunctions = {TimeFunctionKind::kStep, TimeFunctionKind::kRamp,
                                       TimeFunctionKind::kSine};

SceneStructure ReadStructure(const TomlFieldReader& r) {
  r.RequireTable("structure");
  r.RejectUnknownKeys("structure", {"kind", "length", "width", "thickness", "gap", "axial_load"});
  SceneStructure s;
  s.kind = r.RequiredChoice("structure.kind", kStructureKinds, "structure kind");
  s.length = r.RequiredPositive("structure.length", kLength);
  s.width = r.RequiredPositive("structure.width", kLength);
  s.thickness = r.RequiredPositive("structure.thickness", kLength);
  s.gap = r.OptionalPositive("structure.gap", kLength);
  s.axial_load = r.OptionalNumber("structure.axial_load", kForce).value_or(s.axial_load);
  return s;
}

SceneMaterial ReadMaterial(const TomlFieldReader& r) {
  r.RequireTable("material");
  r.RejectUnknownKeys("material", {"young_modulus", "density", "poisson_ratio", "plate_modulus"});
  SceneMaterial m;
  m.young_modulus = r.RequiredPositive("material.young_modulus", kYoungModulus);
  m.density = r.RequiredPositive("material.density", kDensity);
  m.poisson_ratio = r.Number("material.poisson_ratio", m.poisson_ratio);
  r.Require(m.poisson_ratio > -1.0 && m.poisson_ratio < 0.5, "material.poisson_ratio",
            "must lie in (-1, 0.5)");
  m.plate_modulus = r.Boolean("material.plate_modulus", m.plate_modulus);
  return m;
}

SceneModel ReadModel(const TomlFieldReader& r) {
  SceneModel m;
  if (!r.HasTable("model")) return m;
  r.RejectUnknownKeys("model", {"theory", "dimension", "elements", "series_order", "modes"});
  m.theory = r.OptionalChoice("model.theory", kTheories, "theory").value_or(m.theory);
  m.dimension = r.Integer("model.dimension", m.dimension);
  r.Require(m.dimension == 2 || m.dimension == 3, "model.dimension", "must be 2 or 3");
  m.elements = r.Integer("model.elements", m.elements);
  r.Require(m.elements >= 1, "model.elements", "must be at least 1");
  r.Require(m.elements <= kMaxElements, "model.elements",
            "must be at most " + std::to_string(kMaxElements));
  m.series_order = r.Integer("model.series_order", m.series_order);
  r.Require(m.series_order >= 0 && m.series_order <= kMaxSeriesOrder, "model.series_order",
            "must lie in 0 ... " + std::to_string(kMaxSeriesOrder));
  m.modes = r.Integer("model.modes", m.modes);
  r.Require(m.modes >= 0, "model.modes", "must be non-negative");
  r.Require(m.modes <= kMaxModes, "model.modes", "must be at most " + std::to_string(kMaxModes));
  return m;
}

// Each component within `bounds`.
Eigen::Vector3d ReadVector3(const TomlFieldReader& r, const std::string& key,
                            const Bounds& bounds) {
  const std::optional<std::vector<double>> values = r.OptionalNumbers(key, 3);
  if (!values) return Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < values->size(); ++i) {
    r.RequireWithin(key + "[" + std::to_string(i) + "]", (*values)[i], bounds);
  }
  return Eigen::Vector3d((*values)[0], (*values)[1], (*values)[2]);
}

// A parameter that only one choice takes: given beside another choice it is refused rather than
// ignored, since it shows an intent that the run would not follow.
std::optional<double> ReadParameterOf(const TomlFieldReader& r, const std::string& key, bool chosen,
                                      const std::string& owner) {
  const std::optional<double> value = r.OptionalNumber(key);
  r.Require(!value || chosen, key, "only " + owner + " takes it");
  return value;
}

// The time function's parameters are checked whatever the analysis: they describe the loads,
// and a scene may switch to a transient analysis with --set.
std::optional<SceneTimeFunction> ReadTimeFunction(const TomlFieldReader& r) {
  const std::optional<TimeFunctionKind> kind =
      r.OptionalChoice("loads.time_function", kTimeFunctions, "time function");
  const TimeFunctionKind chosen = kind.value_or(TimeFunctionKind::kStep);
  SceneTimeFunction f;
  f.kind = chosen;
  const std::optional<double> ramp_time = ReadParameterOf(
      r, "loads.ramp_time", chosen == TimeFunctionKind::kRamp, "the \"ramp\" time function");
  const std::optional<double> frequency = ReadParameterOf(
      r, "loads.frequency", chosen == TimeFunctionKind::kSine, "the \"sine\" time function");
  if (chosen == TimeFunctionKind::kRamp) {
    r.Require(ramp_time.has_value(), "loads.time_function", "needs loads.ramp_time (s, > 0)");
    r.Require(*ramp_time > 0.0, "loads.ramp_time", "must be positive");
    r.RequireWithin("loads.ramp_time", *ramp_time, kTime);
    f.ramp_time = *ramp_time;
  }
  if (chosen == TimeFunctionKind::kSine) {
    r.Require(frequency.has_value(), "loads.time_function", "needs loads.frequency (Hz, > 0)");
    r.Require(*frequency > 0.0, "loads.frequency", "must be positive");
    r.RequireWithin("loads.frequency", *frequency, kFrequency);
    f.frequency = *frequency;
  }
  if (!kind) return std::nullopt;
  return f;
}

SceneLoads ReadLoads(const TomlFieldReader& r) {
  SceneLoads l;
  if (!r.HasTable("loads")) return l;
  r.RejectUnknownKeys("loads", {"tip_force", "midspan_force", "distributed", "tip_moment",
                                "time_function", "ramp_time", "frequency"});
  l.tip_force = ReadVector3(r, "loads.tip_force", kForce);
  l.midspan_force = ReadVector3(r, "loads.midspan_force", kForce);
  l.distributed = ReadVector3(r, "loads.distributed", kForcePerLength);
  l.tip_moment = ReadVector3(r, "loads.tip_moment", kMoment);
  l.time_function = ReadTimeFunction(r);
  return l;
}

// A point of the beam axis, x in [0, length].
std::optional<double> ReadPositionOnBeam(const TomlFieldReader& r, const std::string& key,
                                         const SceneStructure& structure) {
  const std::optional<double> x = r.OptionalNumber(key);
  r.Require(!x || (*x >= 0.0 && *x <= structure.length), key,
            "must lie on the beam, in [0, " + FormatNumber(structure.length) + "]");
  return x;
}

// An effect table: present (as a table) or not, and enabled unless it says otherwise.
bool HasEffect(const TomlFieldReader& r, const std::string& name,
               std::initializer_list<std::string_view> parameters, bool& enabled) {
  const std::string table = "effects." + name;
  if (!r.HasTable(table)) return false;
  r.RejectUnknownKeys(table, parameters);
  enabled = r.Boolean(table + ".enabled", true);
  return true;
}

std::optional<ContactEffect> ReadContact(const TomlFieldReader& r) {
  ContactEffect c;
  if (!HasEffect(r, "contact", {"enabled", "separation", "tolerance", "proximity"}, c.enabled)) {
    return std::nullopt;
  }
  c.separation = r.OptionalNonNegative("effects.contact.separation", kLengthOrZero);
  c.tolerance = r.OptionalPositive("effects.contact.tolerance", kLength);
  c.proximity = r.OptionalPositive("effects.contact.proximity", kLength);
  return c;
}

std::optional<StictionEffect> ReadStiction(const TomlFieldReader& r) {
  StictionEffect s;
  if (!HasEffect(r, "stiction", {"enabled", "adhesion_energy"}, s.enabled)) return std::nullopt;
  s.adhesion_energy = r.OptionalNonNegative("effects.stiction.adhesion_energy", kAdhesionEnergy);
  return s;
}

std::optional<ElectrostaticEffect> ReadElectrostatic(const TomlFieldReader& r,
                                                     const SceneStructure& structure) {
  ElectrostaticEffect s;
  if (!HasEffect(r, "electrostatic",
                 {"enabled", "voltage", "fringing", "electrode_start", "electrode_end"},
                 s.enabled)) {
    return std::nullopt;
  }
  s.voltage = r.OptionalNumber("effects.electrostatic.voltage", kVoltage);
  s.fringing = r.Boolean("effects.electrostatic.fringing", s.fringing);
  s.electrode_start = ReadPositionOnBeam(r, "effects.electrostatic.electrode_start", structure);
  s.electrode_end = ReadPositionOnBeam(r, "effects.electrostatic.electrode_end", structure);
  r.Require(!s.electrode_start || !s.electrode_end || *s.electrode_start < *s.electrode_end,
            "effects.electrostatic.electrode_end", "must exceed electrode_start");
  return s;
}

std::optional<CasimirEffect> ReadCasimir(const TomlFieldReader& r) {
  CasimirEffect c;
  if (!HasEffect(r, "casimir", {"enabled"}, c.enabled)) return std::nullopt;
  return c;
}

std::optional<VanDerWaalsEffect> ReadVanDerWaals(const TomlFieldReader& r) {
  VanDerWaalsEffect v;
  if (!HasEffect(r, "van_der_waals", {"enabled", "hamaker"}, v.enabled)) return std::nullopt;
  v.hamaker = r.OptionalPositive("effects.van_der_waals.hamaker", kHamaker);
  return v;
}

std::optional<DampingEffect> ReadDamping(const TomlFieldReader& r) {
  DampingEffect d;
  if (!HasEffect(r, "damping", {"enabled", "quality_factor", "rayleigh"}, d.enabled)) {
    return std::nullopt;
  }
  d.quality_factor = r.OptionalPositive("effects.damping.quality_factor", kQualityFactor);
  if (const auto rayleigh = r.OptionalNumbers("effects.damping.rayleigh", 2)) {
    r.Require((*rayleigh)[0] >= 0.0 && (*rayleigh)[1] >= 0.0, "effects.damping.rayleigh",
              "alpha and beta must be non-negative");
    r.RequireWithin("effects.damping.rayleigh[0]", (*rayleigh)[0], kRayleighAlpha);
    r.RequireWithin("effects.damping.rayleigh[1]", (*rayleigh)[1], kRayleighBeta);
    r.Require(!d.quality_factor, "effects.damping.rayleigh",
              "give quality_factor or rayleigh, not both");
    d.rayleigh = std::array<double, 2>{(*rayleigh)[0], (*rayleigh)[1]};
  }
  // An enabled table that names no model would run undamped while the scene says otherwise.
  r.Require(!d.enabled || d.quality_factor || d.rayleigh, "effects.damping",
            "needs quality_factor or rayleigh = [alpha, beta]");
  return d;
}

std::optional<SqueezeFilmEffect> ReadSqueezeFilm(const TomlFieldReader& r) {
  SqueezeFilmEffect s;
  if (!HasEffect(r, "squeeze_film", {"enabled", "viscosity", "mean_free_path"}, s.enabled)) {
    return std::nullopt;
  }
  s.viscosity = r.OptionalPositive("effects.squeeze_film.viscosity", kViscosity);
  s.mean_free_path = r.OptionalNonNegative("effects.squeeze_film.mean_free_path", kLengthOrZero);
  return s;
}

SceneEffects ReadEffects(const TomlFieldReader& r, const SceneStructure& structure) {
  SceneEffects e;
  if (!r.HasTable("effects")) return e;
  r.RejectUnknownKeys("effects",
                      {"contact", "stiction", "electrostatic", "casimir", "van_der_waals",
                       "damping", "squeeze_film"},
                      "effect");
  e.contact = ReadContact(r);
  e.stiction = ReadStiction(r);
  e.electrostatic = ReadElectrostatic(r, structure);
  e.casimir = ReadCasimir(r);
  e.van_der_waals = ReadVanDerWaals(r);
  e.damping = ReadDamping(r);
  e.squeeze_film = ReadSqueezeFilm(r);
  return e;
}

// An integrator parameter: the integrator that takes it, its range and where it goes.
struct IntegratorParameter {
  const char* key;
  Integrator owner;
  double lower;
  double upper;
  const char* range;
  double SceneAnalysis::*field;
};

void ReadTransient(const TomlFieldReader& r, SceneAnalysis& a) {
  a.duration = r.RequiredPositive("analysis.duration", kTime);
  a.time_step = r.RequiredPositive("analysis.time_step", kTime);
  r.Require(a.time_step <= a.duration, "analysis.time_step",
            "must not exceed analysis.duration = " + FormatNumber(a.duration));
  r.Require(std::round(a.duration / a.time_step) <= kMaxSteps, "analysis.time_step",
            "more than 1e8 steps over analysis.duration = " + FormatNumber(a.duration));
  a.integrator =
      r.OptionalChoice("analysis.integrator", kIntegrators, "integrator").value_or(a.integrator);
  const std::array<IntegratorParameter, 4> parameters = {
      {{"beta", Integrator::kNewmark, 0.0, 0.5, "[0, 0.5]", &SceneAnalysis::beta},
       {"gamma", Integrator::kNewmark, 0.5, 1.0, "[0.5, 1]", &SceneAnalysis::gamma},
       {"alpha", Integrator::kHht, 0.0, 1.0 / 3.0, "[0, 1/3]", &SceneAnalysis::alpha},
       {"rho_inf", Integrator::kGeneralizedAlpha, 0.0, 1.0, "[0, 1]", &SceneAnalysis::rho_inf}}};
  for (const IntegratorParameter& p : parameters) {
    const std::string key = std::string("analysis.") + p.key;
    const std::optional<double> value =
        ReadParameterOf(r, key, a.integrator == p.owner,
                        "the \"" + std::string(ToString(p.owner)) + "\" integrator");
    if (!value) continue;
    r.Require(*value >= p.lower && *value <= p.upper, key, std::string("must lie in ") + p.range);
    a.*p.field = *value;
  }
  a.initial =
      r.OptionalChoice("analysis.initial", kInitialStates, "initial state").value_or(a.initial);
}

SceneAnalysis ReadAnalysis(const TomlFieldReader& r) {
  r.RequireTable("analysis");
  // The parameters of every documented analysis are known keys, so that a scene can carry
  // them while it runs another type (switching with --set analysis.type=...); only the chosen
  // analysis reads its own.
  r.RejectUnknownKeys("analysis",
                      {"type", "count", "duration", "time_step", "integrator", "initial", "beta",
                       "gamma", "alpha", "rho_inf", "voltage_max", "rate"});
  SceneAnalysis a;
  a.type = r.RequiredChoice("analysis.type", kAnalysisTypes, "analysis type");
  if (a.type == AnalysisType::kModal) {
    a.count = r.Integer("analysis.count", a.count);
    r.Require(a.count >= 1, "analysis.count", "must be at least 1");
    r.Require(a.count <= kMaxModes, "analysis.count",
              "must be at most " + std::to_string(kMaxModes));
  }
  if (a.type == AnalysisType::kTransient) ReadTransient(r, a);
  if (a.type == AnalysisType::kHaptic) {
    a.duration = r.OptionalPositive("analysis.duration", kHapticDuration).value_or(0.0);
    a.integrator = r.OptionalChoice("analysis.integrator", kIntegrators, "integrator")
                       .value_or(Integrator::kGeneralizedAlpha);
    r.Require(a.integrator == Integrator::kGeneralizedAlpha || a.integrator == Integrator::kModal,
              "analysis.integrator",
              "the haptic analysis steps by \"generalized-alpha\" (the full model) or \"modal\"");
    a.rate = r.Number("analysis.rate", a.rate);
    r.Require(a.rate == 500.0 || a.rate == 1000.0 || a.rate == 2000.0, "analysis.rate",
              "must be 500, 1000 or 2000 (Hz: the rates haptic devices run at)");
  }
  if (a.type == AnalysisType::kPullin) {
    a.voltage_max = r.OptionalPositive("analysis.voltage_max", kVoltageMax);
  }
  return a;
}

std::optional<SceneDevice> ReadDevice(const TomlFieldReader& r) {
  if (!r.HasTable("device")) return std::nullopt;
  r.RejectUnknownKeys("device", {"backend", "trajectory", "realtime", "position_scale",
                                 "force_scale", "coupling_stiffness", "probe_radius"});
  SceneDevice d;
  d.backend =
      r.OptionalChoice("device.backend", kDeviceBackends, "device backend").value_or(d.backend);
  d.trajectory = r.OptionalString("device.trajectory").value_or(d.trajectory);
  r.Require(!d.trajectory.empty(), "device.trajectory", "must not be empty");
  d.realtime = r.Boolean("device.realtime", d.realtime);
  d.position_scale = r.OptionalPositive("device.position_scale", kScale);
  d.force_scale = r.OptionalPositive("device.force_scale", kScale);
  d.coupling_stiffness = r.OptionalPositive("device.coupling_stiffness", kStiffness);
  d.probe_radius = r.OptionalPositive("device.probe_radius", kLength);
  return d;
}

// Loads the structure cannot carry or the model cannot represent.
void CheckLoads(const TomlFieldReader& r, const Scene& scene) {
  if (scene.structure.kind == StructureKind::kBridge) {
    const std::string reason = "a bridge has no free end (tip loads need a cantilever)";
    r.Require(scene.loads.tip_force.isZero(0.0), "loads.tip_force", reason);
    r.Require(scene.loads.tip_moment.isZero(0.0), "loads.tip_moment", reason);
  }
  if (scene.model.dimension == 2) {
    const std::string reason = "out of plane for model.dimension = 2";
    r.Require(scene.loads.tip_force.z() == 0.0, "loads.tip_force[2]", reason);
    r.Require(scene.loads.midspan_force.z() == 0.0, "loads.midspan_force[2]", reason);
    r.Require(scene.loads.distributed.z() == 0.0, "loads.distributed[2]", reason);
    r.Require(scene.loads.tip_moment.x() == 0.0, "loads.tip_moment[0]", reason);
    r.Require(scene.loads.tip_moment.y() == 0.0, "loads.tip_moment[1]", reason);
  }
}

// What a transient analysis needs of the rest of the scene.
void CheckTransient(const TomlFieldReader& r, const Scene& scene) {
  if (scene.analysis.type != AnalysisType::kTransient) return;
  if (scene.analysis.integrator == Integrator::kModal) {
    r.Require(scene.model.modes >= 1, "model.modes",
              "analysis.integrator = \"modal\" needs at least one mode");
  } else {
    r.Require(scene.model.modes == 0, "model.modes",
              "modal reduction needs analysis.integrator = \"modal\" (0: the full model)");
  }
  const std::optional<SceneTimeFunction>& f = scene.loads.time_function;
  r.Require(
      scene.analysis.initial != InitialState::kStatic || !f || f->kind == TimeFunctionKind::kStep,
      "loads.time_function",
      "analysis.initial = \"static\" removes the loads at t = 0, so only \"step\" goes with it");
}

// What Newton solves in a transient (`subject`: a nonlinear theory or effect) needs an implicit
// integrator: a Newmark-family member, or modal propagation, which holds the force over each step
// (NonlinearModalIntegrator); not the explicit central difference.
void RequireNewtonIntegrator(const TomlFieldReader& r, const Scene& scene,
                             const std::string& subject) {
  if (scene.analysis.type != AnalysisType::kTransient) return;
  r.Require(scene.analysis.integrator != Integrator::kCentralDifference, "analysis.integrator",
            subject +
                " is solved by Newton: it needs an implicit integrator (\"newmark\", \"hht\", "
                "\"generalized-alpha\" or \"modal\")");
}

// Mid-plane stretching needs both ends held axially, and an integrator with a Newton path.
void CheckStretching(const TomlFieldReader& r, const Scene& scene) {
  if (scene.model.theory != Theory::kStretching) return;
  r.Require(scene.structure.kind == StructureKind::kBridge, "model.theory",
            "\"stretching\" needs both ends held axially: structure.kind = \"bridge\"");
  RequireNewtonIntegrator(r, scene, "model.theory = \"stretching\"");
}

// The Cosserat rod is a 3-D model solved by Newton: no planar form, no modes of its own, no
// explicit or modal stepping, no damping model.
void CheckCosserat(const TomlFieldReader& r, const Scene& scene) {
  if (scene.model.theory != Theory::kCosserat) return;
  r.Require(scene.model.dimension == 3, "model.dimension",
            "model.theory = \"cosserat\" is a 3-D rod: set model.dimension = 3 (planar loads "
            "keep it in the plane)");
  r.Require(scene.analysis.type != AnalysisType::kModal, "analysis.type",
            "\"modal\" is not available for model.theory = \"cosserat\" (\"linear\" gives the "
            "modes of the straight beam, \"stretching\" those of a deflected bridge)");
  r.Require(scene.analysis.type != AnalysisType::kPullin, "analysis.type",
            "\"pullin\" is not available for model.theory = \"cosserat\" (\"linear\", or "
            "\"stretching\" for a bridge)");
  r.Require(scene.analysis.type != AnalysisType::kHaptic, "analysis.type",
            "\"haptic\" is not available for model.theory = \"cosserat\" (\"linear\", or "
            "\"stretching\" for a bridge)");
  RequireNewtonIntegrator(r, scene, "model.theory = \"cosserat\"");
  if (scene.analysis.type != AnalysisType::kTransient) return;
  r.Require(scene.analysis.integrator != Integrator::kModal, "analysis.integrator",
            "model.theory = \"cosserat\" has no modes to propagate: it needs a Newmark-family "
            "integrator (\"newmark\", \"hht\" or \"generalized-alpha\")");
  const std::optional<DampingEffect>& damping = scene.effects.damping;
  r.Require(!IsOn(damping), "effects.damping",
            "not available for model.theory = \"cosserat\" (remove the table or set enabled = "
            "false)");
}

// The effects that act through the substrate, and what each analysis does with them: a pull-in
// needs the electrode; contact and stiction act in static, transient and release analyses, the
// gas film wherever the beam moves; every surface effect needs the gap and its parameters, and
// the beam theories with a Newton path that carries them (not the Cosserat rod, nor explicit
// stepping; modal stepping carries all but the gas film, a velocity-dependent force).
void CheckSurface(const TomlFieldReader& r, const Scene& scene) {
  const SceneEffects& e = scene.effects;
  const bool contact = e.HasContact();
  const AnalysisType type = scene.analysis.type;
  if (type == AnalysisType::kPullin) {
    r.Require(scene.structure.gap.has_value(), "structure.gap",
              "analysis.type = \"pullin\" needs the substrate: give its gap");
    r.Require(IsOn(e.electrostatic), "effects.electrostatic",
              "analysis.type = \"pullin\" needs the electrode: declare [effects.electrostatic]");
    r.Require(!contact, IsOn(e.stiction) ? "effects.stiction" : "effects.contact",
              "not used by analysis.type = \"pullin\", which stops at the fold before contact "
              "(remove the table or set enabled = false)");
  }
  if (type == AnalysisType::kRelease) {
    r.Require(contact, "effects.stiction",
              "analysis.type = \"release\" lets the beam go from the substrate: declare "
              "[effects.stiction] (or [effects.contact])");
  }
  if (!e.HasSurfaceEffect()) return;
  // The declared effect the messages below name.
  const char* first = IsOn(e.contact)         ? "effects.contact"
                      : IsOn(e.stiction)      ? "effects.stiction"
                      : IsOn(e.electrostatic) ? "effects.electrostatic"
                      : IsOn(e.casimir)       ? "effects.casimir"
                      : IsOn(e.van_der_waals) ? "effects.van_der_waals"
                                              : "effects.squeeze_film";
  r.Require(type != AnalysisType::kModal && type != AnalysisType::kBuckling, first,
            std::string("not available for analysis.type = \"") + ToString(type) +
                "\", which linearises about the straight beam (remove the table or set enabled = "
                "false)");
  r.Require(scene.structure.gap.has_value(), "structure.gap",
            std::string(first) + " acts through the substrate: give its gap");
  r.Require(scene.model.theory != Theory::kCosserat, "model.theory",
            std::string(first) +
                " is available for the \"linear\" and \"stretching\" theories, "
                "not \"cosserat\"");
  const std::optional<StictionEffect>& stiction = e.stiction;
  r.Require(!IsOn(stiction) || stiction->adhesion_energy.value_or(0.0) > 0.0,
            "effects.stiction.adhesion_energy",
            "needs the work of adhesion (J/m^2, > 0), e.g. adhesion_energy = 0.02");
  const std::optional<VanDerWaalsEffect>& vdw = e.van_der_waals;
  r.Require(!IsOn(vdw) || vdw->hamaker.has_value(), "effects.van_der_waals",
            "needs its hamaker constant (J), e.g. hamaker = 1e-19");
  const std::optional<ElectrostaticEffect>& electrostatic = e.electrostatic;
  r.Require(
      type == AnalysisType::kPullin || !IsOn(electrostatic) || electrostatic->voltage.has_value(),
      "effects.electrostatic.voltage",
      std::string("needs the voltage (V) for analysis.type = \"") + ToString(type) + "\"");
  if (e.contact && e.contact->separation && scene.structure.gap) {
    r.Require(*e.contact->separation < 0.5 * *scene.structure.gap, "effects.contact.separation",
              "must be less than half the gap");
  }
  RequireNewtonIntegrator(r, scene, first);
  r.Require(type != AnalysisType::kTransient || scene.analysis.integrator != Integrator::kModal ||
                !IsOn(e.squeeze_film),
            "effects.squeeze_film",
            "not available with analysis.integrator = \"modal\": the modes take their damping as "
            "ratios (effects.damping); a gas film needs a Newmark-family integrator");
}

// The haptic analysis touches the full model, or its modes with analysis.integrator = "modal"
// (the Cosserat rod is refused in CheckCosserat).
void CheckHaptic(const TomlFieldReader& r, const Scene& scene) {
  if (scene.analysis.type != AnalysisType::kHaptic) return;
  if (scene.analysis.integrator == Integrator::kModal) {
    r.Require(scene.model.modes >= 1, "model.modes",
              "analysis.integrator = \"modal\" needs at least one mode");
    r.Require(!IsOn(scene.effects.squeeze_film), "effects.squeeze_film",
              "not available with analysis.integrator = \"modal\": a gas film needs the full "
              "model's integrator");
    r.Require(IsOn(scene.effects.damping), "effects.damping",
              "analysis.integrator = \"modal\" touches modes that ring for ever without it: "
              "declare their damping, e.g. { quality_factor = 100.0 }");
  } else {
    r.Require(scene.model.modes == 0, "model.modes",
              "modal reduction of the touched beam needs analysis.integrator = \"modal\" (0: the "
              "full model)");
  }
}

}  // namespace

Scene ReadScene(const toml::table& root, const KeyOrigins& origins) {
  const TomlFieldReader r(root, origins);
  r.RejectUnknownKeys(
      "", {"structure", "material", "model", "loads", "effects", "analysis", "device"}, "table");
  Scene scene;
  scene.structure = ReadStructure(r);
  scene.material = ReadMaterial(r);
  scene.model = ReadModel(r);
  scene.loads = ReadLoads(r);
  scene.effects = ReadEffects(r, scene.structure);
  scene.analysis = ReadAnalysis(r);
  scene.device = ReadDevice(r);
  CheckLoads(r, scene);
  CheckTransient(r, scene);
  CheckStretching(r, scene);
  CheckCosserat(r, scene);
  CheckSurface(r, scene);
  CheckHaptic(r, scene);
  return scene;
}

}  // namespace cosmems::internal
