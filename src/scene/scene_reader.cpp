#include "scene_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cosmems/scene/frame_conversion.hpp"
#include "device_checks.hpp"
#include "key_reader.hpp"
#include "scene_keys.hpp"
#include "scene_limits.hpp"
#include "toml_field_reader.hpp"
#include "toml_format.hpp"

namespace cosmems::internal {
namespace {

// Reads `table` by `visit` (scene_keys.hpp), then refuses the keys it does not name.
template <class Visit>
void ReadTable(const TomlFieldReader& r, const std::string& table, Visit visit,
               double length = 0.0) {
  KeyReader reader(r, table, length);
  visit(reader);
  r.RejectUnknownKeys(table, reader.names(), reader.chosen());
}

SceneStructure ReadStructure(const TomlFieldReader& r) {
  r.RequireTable("structure");
  SceneStructure s;
  ReadTable(r, "structure", [&](auto& v) { VisitStructure(v, s); });
  return s;
}

// [material]: required of a beam; a frame whose entries all name a material may leave it out
// (CheckNetlist).
SceneMaterial ReadMaterial(const TomlFieldReader& r, StructureKind kind) {
  if (kind != StructureKind::kFrame) r.RequireTable("material");
  SceneMaterial m;
  if (r.HasTable("material")) ReadTable(r, "material", [&](auto& v) { VisitMaterial(v, m); });
  return m;
}

// [materials.NAME]: a frame's named materials, each with the keys of [material].
std::map<std::string, SceneMaterial> ReadMaterials(const TomlFieldReader& r, StructureKind kind) {
  std::map<std::string, SceneMaterial> materials;
  if (!r.HasTable("materials")) return materials;
  r.Require(kind == StructureKind::kFrame, "materials",
            "named materials are for structure.kind = \"frame\" (a beam takes [material])");
  for (const std::string& name : r.Keys("materials")) {
    const std::string table = "materials." + name;
    r.RequireTable(table);
    ReadTable(r, table, [&](auto& v) { VisitMaterial(v, materials[name]); });
  }
  return materials;
}

SceneModel ReadModel(const TomlFieldReader& r) {
  SceneModel m;
  if (r.HasTable("model")) ReadTable(r, "model", [&](auto& v) { VisitModel(v, m); });
  return m;
}

SceneLoads ReadLoads(const TomlFieldReader& r, StructureKind structure) {
  SceneLoads l;
  if (!r.HasTable("loads")) return l;
  // The time function first: its choice decides which of its parameters the loads may carry.
  const std::optional<TimeFunctionKind> kind =
      r.OptionalChoice("loads.time_function", kTimeFunctions, "time function");
  // Named at the choice, where the scene (or --set) asked for the function.
  if (kind == TimeFunctionKind::kRamp) {
    r.Require(r.Find("loads.ramp_time") != nullptr, "loads.time_function",
              "needs loads.ramp_time (s, > 0)");
  }
  if (kind == TimeFunctionKind::kSine) {
    r.Require(r.Find("loads.frequency") != nullptr, "loads.time_function",
              "needs loads.frequency (Hz, > 0)");
  }
  SceneTimeFunction f;
  ReadTable(r, "loads", [&](auto& v) {
    VisitLoads(v, l, f, kind.value_or(TimeFunctionKind::kStep), structure);
  });
  if (kind) l.time_function = f;
  return l;
}

// An effect table: present (as a table) or not, read by its visit when present.
template <class Effect, class Visit>
std::optional<Effect> ReadEffect(const TomlFieldReader& r, const char* name, Visit visit,
                                 double length = 0.0) {
  const std::string table = std::string("effects.") + name;
  if (!r.HasTable(table)) return std::nullopt;
  Effect effect;
  ReadTable(
      r, table, [&](auto& v) { visit(v, effect); }, length);
  return effect;
}

SceneEffects ReadEffects(const TomlFieldReader& r, const SceneStructure& structure) {
  SceneEffects e;
  if (!r.HasTable("effects")) return e;
  r.RejectUnknownKeys("effects",
                      {"contact", "stiction", "electrostatic", "casimir", "van_der_waals",
                       "damping", "squeeze_film", "combs"},
                      "effect");
  KeyReader effects(r, "effects");
  VisitEffects(effects, e, structure.kind);
  e.contact = ReadEffect<ContactEffect>(r, "contact",
                                        [](auto& v, ContactEffect& c) { VisitContact(v, c); });
  e.stiction = ReadEffect<StictionEffect>(r, "stiction",
                                          [](auto& v, StictionEffect& s) { VisitStiction(v, s); });
  e.electrostatic = ReadEffect<ElectrostaticEffect>(
      r, "electrostatic",
      [&](auto& v, ElectrostaticEffect& s) { VisitElectrostatic(v, s, structure.kind); },
      structure.length);
  if (e.electrostatic) {
    const ElectrostaticEffect& s = *e.electrostatic;
    r.Require(!s.electrode_start || !s.electrode_end || *s.electrode_start < *s.electrode_end,
              "effects.electrostatic.electrode_end", "must exceed electrode_start");
    for (std::size_t i = 0; i < s.electrodes.size(); ++i) {
      for (std::size_t j = 0; j < i; ++j) {
        const SceneElectrode &a = s.electrodes[i], &b = s.electrodes[j];
        const bool overlap =
            a.x[0] < b.x[1] && b.x[0] < a.x[1] && a.z[0] < b.z[1] && b.z[0] < a.z[1];
        r.Require(!overlap, "effects.electrostatic.electrodes[" + std::to_string(i) + "]",
                  "overlaps electrodes[" + std::to_string(j) + "]: their pressures would add");
      }
    }
  }
  e.casimir = ReadEffect<CasimirEffect>(r, "casimir",
                                        [](auto& v, CasimirEffect& c) { VisitCasimir(v, c); });
  e.van_der_waals = ReadEffect<VanDerWaalsEffect>(
      r, "van_der_waals", [](auto& v, VanDerWaalsEffect& w) { VisitVanDerWaals(v, w); });
  e.damping = ReadEffect<DampingEffect>(r, "damping",
                                        [](auto& v, DampingEffect& d) { VisitDamping(v, d); });
  if (e.damping) {
    const DampingEffect& d = *e.damping;
    r.Require(!d.rayleigh || !d.quality_factor, "effects.damping.rayleigh",
              "give quality_factor or rayleigh, not both");
    // An enabled table that names no model would run undamped while the scene says otherwise.
    r.Require(!d.enabled || d.quality_factor || d.rayleigh, "effects.damping",
              "needs quality_factor or rayleigh = [alpha, beta]");
  }
  e.squeeze_film = ReadEffect<SqueezeFilmEffect>(
      r, "squeeze_film", [](auto& v, SqueezeFilmEffect& s) { VisitSqueezeFilm(v, s); });
  return e;
}

SceneAnalysis ReadAnalysis(const TomlFieldReader& r, StructureKind kind) {
  r.RequireTable("analysis");
  // The type and the integrator first: they decide which parameters are read and which refused.
  const AnalysisType type = r.RequiredChoice("analysis.type", kAnalysisTypes, "analysis type");
  const Integrator integrator =
      type == AnalysisType::kTransient
          ? r.OptionalChoice("analysis.integrator", kIntegrators, "integrator")
                .value_or(Integrator::kNewmark)
          : Integrator::kNewmark;
  SceneAnalysis a;
  // The parameters of every analysis are known keys, so that a scene can carry them while it
  // runs another type (switching with --set analysis.type=...); only the chosen type reads its
  // own.
  ReadTable(r, "analysis", [&](auto& v) { VisitAnalysis(v, a, type, integrator, kind); });
  if (type == AnalysisType::kTransient) {
    r.Require(a.time_step <= a.duration, "analysis.time_step",
              "must not exceed analysis.duration = " + FormatNumber(a.duration));
    r.Require(std::round(a.duration / a.time_step) <= kMaxSteps, "analysis.time_step",
              "more than 1e8 steps over analysis.duration = " + FormatNumber(a.duration));
  }
  if (type == AnalysisType::kHaptic) {
    r.Require(a.rate == 500.0 || a.rate == 1000.0 || a.rate == 2000.0, "analysis.rate",
              "must be 500, 1000 or 2000 (Hz: the rates haptic devices run at)");
  }
  return a;
}

std::optional<SceneDevice> ReadDevice(const TomlFieldReader& r) {
  if (!r.HasTable("device")) return std::nullopt;
  SceneDevice d;
  ReadTable(r, "device", [&](auto& v) { VisitDevice(v, d); });
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

// Mid-plane stretching of one beam needs both ends held axially (a device's members stretch
// wherever their ends are held), and an integrator with a Newton path.
void CheckStretching(const TomlFieldReader& r, const Scene& scene) {
  if (scene.model.theory != Theory::kStretching) return;
  r.Require(scene.structure.kind != StructureKind::kCantilever, "model.theory",
            "\"stretching\" needs both ends held axially: structure.kind = \"bridge\", or a "
            "device");
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
    // A device's combs alone pull in sideways, in the plane: no substrate needed.
    const bool combs_alone = !IsOn(e.electrostatic) && !e.combs.empty();
    r.Require(scene.structure.gap.has_value() || combs_alone, "structure.gap",
              "analysis.type = \"pullin\" needs the substrate: give its gap");
    r.Require(IsOn(e.electrostatic) || combs_alone, "effects.electrostatic",
              "analysis.type = \"pullin\" needs the electrode: declare [effects.electrostatic] "
              "(or, on a device, [[effects.combs]] for their side instability)");
    r.Require(!contact, IsOn(e.stiction) ? "effects.stiction" : "effects.contact",
              "not used by analysis.type = \"pullin\", which stops at the fold before contact "
              "(remove the table or set enabled = false)");
  }
  if (type == AnalysisType::kRelease) {
    r.Require(contact, "effects.stiction",
              "analysis.type = \"release\" lets the structure go from the substrate: declare "
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
// (the Cosserat rod is refused in CheckCosserat); a device is pressed at its device.target
// (CheckDevice).
void CheckHaptic(const TomlFieldReader& r, const Scene& scene) {
  if (scene.analysis.type != AnalysisType::kHaptic) return;
  r.Require(IsDevice(scene.structure.kind) || !scene.device || !scene.device->target,
            "device.target",
            "names a device's node or body; a beam is pressed at its tip or its midspan");
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

// An alternating voltage drives a transient, at a frequency.
void CheckAlternatingVoltage(const TomlFieldReader& r, const std::string& table, double ac_voltage,
                             const std::optional<double>& frequency, AnalysisType type) {
  if (ac_voltage == 0.0) return;
  r.Require(type == AnalysisType::kTransient, table + ".ac_voltage",
            "an alternating voltage drives a \"transient\" analysis");
  r.Require(frequency.has_value(), table + ".frequency",
            "needs the alternating voltage's frequency (Hz, > 0)");
}

// A frame's netlist names nodes, bodies and materials that must exist.
void CheckNetlist(const TomlFieldReader& r, const Scene& scene) {
  const SceneStructure& s = scene.structure;
  const std::string kind = "structure.kind = \"frame\"";
  r.Require(!s.nodes.empty(), "structure.nodes", kind + " needs [[structure.nodes]]");
  r.Require(!s.beams.empty(), "structure.beams", kind + " needs [[structure.beams]]");
  auto node_named = [&](const std::string& name) {
    return std::any_of(s.nodes.begin(), s.nodes.end(),
                       [&](const SceneNode& n) { return n.name == name; });
  };
  auto check_material = [&](const std::string& entry, const std::optional<std::string>& name) {
    if (name) {
      r.Require(scene.materials.count(*name) > 0, entry + ".material",
                "no [materials." + *name + "] table");
    } else {
      r.Require(r.HasTable("material"), entry + ".material",
                "none named and no [material] table to default to");
    }
  };
  for (std::size_t i = 0; i < s.beams.size(); ++i) {
    const std::string entry = "structure.beams[" + std::to_string(i) + "]";
    for (const std::string& name : s.beams[i].nodes) {
      r.Require(node_named(name), entry + ".nodes", "no node \"" + name + "\"");
    }
    check_material(entry, s.beams[i].material);
  }
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const std::string entry = "structure.bodies[" + std::to_string(i) + "]";
    for (const std::string& name : s.bodies[i].nodes) {
      r.Require(node_named(name), entry + ".nodes", "no node \"" + name + "\"");
    }
    for (std::size_t j = 0; j < i; ++j) {
      r.Require(s.bodies[j].name != s.bodies[i].name, entry + ".name",
                "already the name of structure.bodies[" + std::to_string(j) + "]");
    }
    check_material(entry, s.bodies[i].material);
  }
}

// A device (a frame, or a parametric device's netlist) runs every analysis, linear or with its
// members' stretching, and every effect through the substrate where CheckSurface lets it act
// (stiction off the modal time path). Its netlist must be sound, and its loads and recorded
// points must name its nodes and bodies.
void CheckDevice(const TomlFieldReader& r, const Scene& scene) {
  if (!IsDevice(scene.structure.kind)) return;
  const std::string kind =
      std::string("structure.kind = \"") + ToString(scene.structure.kind) + "\"";
  const AnalysisType type = scene.analysis.type;
  r.Require(type != AnalysisType::kBuckling || !scene.loads.points.empty() ||
                !scene.loads.distributed.isZero(0.0),
            "analysis.type",
            "\"buckling\" of " + kind +
                " finds the factor of its loads that buckles it: give [[loads.points]] or "
                "loads.distributed");
  r.Require(scene.model.theory != Theory::kCosserat, "model.theory",
            kind +
                " takes the \"linear\" or \"stretching\" theory (the Cosserat rod is a "
                "single-member theory)");
  r.Require(scene.model.dimension == 3, "model.dimension", kind + " is a 3-D model");
  const SceneEffects& e = scene.effects;
  // Measured (doc/frames.md): with the shuttle of the folded flexure stuck, every modal step
  // fails Newton and is cut 15 times, 61 ms a 1 ms tick.
  r.Require(!IsOn(e.stiction) || type == AnalysisType::kRelease ||
                scene.analysis.integrator != Integrator::kModal,
            "effects.stiction",
            "on " + kind +
                " it needs the full model's steps: analysis.integrator = \"modal\" takes no "
                "adhesion on a device (use \"generalized-alpha\")");
  if (IsOn(e.electrostatic)) {
    r.Require(type != AnalysisType::kModal && type != AnalysisType::kBuckling,
              "effects.electrostatic",
              "on " + kind + " it acts in the \"static\", \"pullin\" and \"transient\" analyses");
    CheckAlternatingVoltage(r, "effects.electrostatic", e.electrostatic->ac_voltage,
                            e.electrostatic->frequency, type);
  }
  if (scene.structure.kind == StructureKind::kFrame) CheckNetlist(r, scene);
  // The netlist's geometry (a member of zero length, a node on two bodies, a design parameter
  // the generator cannot build), named at its key in the scene.
  StructureDescription structure;
  try {
    structure = MakeStructureDescription(scene);
  } catch (const FieldError& error) {
    r.Fail(error.field(), error.reason());
  }
  CheckDeviceSize(r, scene, structure);
  // The generators hold what they make; a netlist holds what its supports hold.
  if (scene.structure.kind == StructureKind::kFrame) CheckFrameSupports(r, structure);
  for (std::size_t i = 0; i < scene.loads.points.size(); ++i) {
    const ScenePointLoad& p = scene.loads.points[i];
    const std::string entry = "loads.points[" + std::to_string(i) + "]";
    r.Require(p.node.has_value() != p.body.has_value(), entry,
              "give the node or the body the load acts at (one of them)");
    if (p.node) {
      r.Require(structure.FindNode(*p.node) >= 0, entry + ".node", "no node \"" + *p.node + "\"");
    }
    if (p.body) {
      r.Require(structure.FindBody(*p.body) >= 0, entry + ".body", "no body \"" + *p.body + "\"");
    }
  }
  for (std::size_t i = 0; i < scene.effects.combs.size(); ++i) {
    const SceneComb& comb = scene.effects.combs[i];
    const std::string entry = "effects.combs[" + std::to_string(i) + "]";
    r.Require(type == AnalysisType::kStatic || type == AnalysisType::kPullin ||
                  type == AnalysisType::kTransient || type == AnalysisType::kHaptic,
              entry,
              "a comb drive acts in the \"static\" and \"pullin\" analyses (its force, "
              "capacitance and side instability), drives a \"transient\" and pulls under the "
              "stylus in a \"haptic\" one");
    CheckAlternatingVoltage(r, entry, comb.ac_voltage, comb.frequency, type);
    r.Require(structure.FindBody(comb.body) >= 0, entry + ".body", "no body \"" + comb.body + "\"");
    r.Require(comb.direction.y() == 0.0 && !comb.direction.isZero(0.0), entry + ".direction",
              "must be a non-zero direction in the substrate plane (y = 0)");
  }
  if (type == AnalysisType::kHaptic) {
    const std::optional<std::string> target = scene.device ? scene.device->target : std::nullopt;
    r.Require(target.has_value() || !structure.bodies.empty(), "device.target",
              kind + " has no body: name the node the built-in motions press");
    if (target) {
      r.Require(structure.FindNode(*target) >= 0 || structure.FindBody(*target) >= 0,
                "device.target", "no node or body \"" + *target + "\"");
    }
  }
  if (type != AnalysisType::kTransient) return;
  const std::vector<std::string>& record = scene.analysis.record;
  for (std::size_t i = 0; i < record.size(); ++i) {
    r.Require(structure.FindNode(record[i]) >= 0 || structure.FindBody(record[i]) >= 0,
              "analysis.record", "no node or body \"" + record[i] + "\"");
  }
  r.Require(!record.empty() || !structure.bodies.empty(), "analysis.record",
            kind + " has no body: name the nodes whose motion the transient records");
}

}  // namespace

Scene ReadScene(const toml::table& root, const KeyOrigins& origins) {
  const TomlFieldReader r(root, origins);
  // [sweep] belongs to `cosmems sweep` (doc/sweeps.md), which reads it; a run ignores it.
  r.RejectUnknownKeys("",
                      {"structure", "material", "materials", "model", "loads", "effects",
                       "analysis", "device", "sweep"},
                      "table");
  Scene scene;
  scene.structure = ReadStructure(r);
  scene.material = ReadMaterial(r, scene.structure.kind);
  scene.materials = ReadMaterials(r, scene.structure.kind);
  scene.model = ReadModel(r);
  scene.loads = ReadLoads(r, scene.structure.kind);
  scene.effects = ReadEffects(r, scene.structure);
  scene.analysis = ReadAnalysis(r, scene.structure.kind);
  scene.device = ReadDevice(r);
  CheckDevice(r, scene);
  CheckLoads(r, scene);
  CheckTransient(r, scene);
  CheckStretching(r, scene);
  CheckCosserat(r, scene);
  CheckSurface(r, scene);
  CheckHaptic(r, scene);
  return scene;
}

}  // namespace cosmems::internal
