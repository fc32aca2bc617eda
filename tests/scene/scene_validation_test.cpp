#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "cosmems/scene/scene_error.hpp"
#include "cosmems/scene/scene_loader.hpp"

namespace cosmems {
namespace {

// The embedded cantilever as tables of `key = value` lines, so that each case can change,
// add or delete one line of an otherwise valid file.
class SceneText {
 public:
  SceneText() {
    tables_ = {{"", {}},
               {"structure",
                {{"kind", "\"cantilever\""},
                 {"length", "200e-6"},
                 {"width", "20e-6"},
                 {"thickness", "2e-6"},
                 {"gap", "2e-6"}}},
               {"material", {{"young_modulus", "169e9"}, {"density", "2330.0"}}},
               {"model", {{"elements", "20"}}},
               {"loads", {{"tip_force", "[0.0, -1e-7, 0.0]"}}},
               {"analysis", {{"type", "\"static\""}}}};
  }

  // Sets the dotted key ("structure.length", "effects.stiction.adhesion_energy") to `value`,
  // adding its table when missing.
  SceneText& Set(const std::string& key, const std::string& value) {
    const auto [table, name] = Split(key);
    Lines& lines = Table(table);
    for (auto& line : lines) {
      if (line.first == name) {
        line.second = value;
        return *this;
      }
    }
    lines.emplace_back(name, value);
    return *this;
  }

  SceneText& Remove(const std::string& key) {
    const auto [table, name] = Split(key);
    Lines& lines = Table(table);
    for (auto it = lines.begin(); it != lines.end(); ++it) {
      if (it->first == name) {
        lines.erase(it);
        break;
      }
    }
    return *this;
  }

  SceneText& RemoveTable(const std::string& table) {
    for (auto it = tables_.begin(); it != tables_.end(); ++it) {
      if (it->first == table) {
        tables_.erase(it);
        break;
      }
    }
    return *this;
  }

  std::string Render() const {
    std::string text;
    for (const auto& [table, lines] : tables_) {
      if (!table.empty()) text += "[" + table + "]\n";
      for (const auto& [key, value] : lines) text += key + " = " + value + "\n";
    }
    return text;
  }

 private:
  using Lines = std::vector<std::pair<std::string, std::string>>;

  static std::pair<std::string, std::string> Split(const std::string& key) {
    const std::size_t dot = key.rfind('.');
    if (dot == std::string::npos) return {"", key};
    return {key.substr(0, dot), key.substr(dot + 1)};
  }

  Lines& Table(const std::string& table) {
    for (auto& entry : tables_) {
      if (entry.first == table) return entry.second;
    }
    tables_.emplace_back(table, Lines{});
    return tables_.back().second;
  }

  std::vector<std::pair<std::string, Lines>> tables_;
};

struct BadScene {
  const char* name;
  SceneText text;
  std::string prefix;  // "KEY = VALUE" or "KEY" as the message must name them after "x.toml: "
  std::string reason;  // a substring of what follows
};

void PrintTo(const BadScene& c, std::ostream* out) { *out << c.name; }

std::string CaseName(const ::testing::TestParamInfo<BadScene>& c) { return c.param.name; }

class SceneValidationTest : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneValidationTest, RefusesWithOneLineNamingFileKeyAndValue) {
  const BadScene& c = GetParam();
  try {
    LoadSceneText(c.text.Render(), "x.toml");
    FAIL() << "accepted:\n" << c.text.Render();
  } catch (const SceneError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("x.toml: " + c.prefix + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.reason), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(error.source(), "x.toml");
  }
}

SceneText With(const std::string& key, const std::string& value) {
  return SceneText().Set(key, value);
}

SceneText Without(const std::string& key) { return SceneText().Remove(key); }

INSTANTIATE_TEST_SUITE_P(
    MissingKeys, SceneValidationTest,
    ::testing::Values(
        BadScene{"kind", Without("structure.kind"), "structure.kind", "missing required key"},
        BadScene{"length", Without("structure.length"), "structure.length", "missing required key"},
        BadScene{"width", Without("structure.width"), "structure.width", "missing required key"},
        BadScene{"thickness", Without("structure.thickness"), "structure.thickness",
                 "missing required key"},
        BadScene{"modulus", Without("material.young_modulus"), "material.young_modulus",
                 "missing required key"},
        BadScene{"density", Without("material.density"), "material.density",
                 "missing required key"},
        BadScene{"type", Without("analysis.type"), "analysis.type", "missing required key"},
        BadScene{"structure", SceneText().RemoveTable("structure"), "structure",
                 "missing required table"},
        BadScene{"material", SceneText().RemoveTable("material"), "material",
                 "missing required table"},
        BadScene{"analysis", SceneText().RemoveTable("analysis"), "analysis",
                 "missing required table"}),
    CaseName);

INSTANTIATE_TEST_SUITE_P(
    WrongTypes, SceneValidationTest,
    ::testing::Values(
        BadScene{"elements_string", With("model.elements", "\"ten\""), "model.elements = \"ten\"",
                 "expected an integer"},
        BadScene{"elements_float", With("model.elements", "20.0"), "model.elements = 20.0",
                 "expected an integer"},
        BadScene{"elements_huge", With("model.elements", "9999999999"),
                 "model.elements = 9999999999", "out of range"},
        BadScene{"length_string", With("structure.length", "\"long\""),
                 "structure.length = \"long\"", "expected a number"},
        BadScene{"kind_number", With("structure.kind", "3"), "structure.kind = 3",
                 "expected a string"},
        BadScene{"plate_modulus_number", With("material.plate_modulus", "1"),
                 "material.plate_modulus = 1", "expected a boolean"},
        BadScene{"structure_scalar", SceneText().RemoveTable("structure").Set("structure", "5"),
                 "structure = 5", "expected a table"},
        BadScene{"effects_scalar", With("effects", "true"), "effects = true", "expected a table"},
        BadScene{"effect_scalar", With("effects.contact", "true"), "effects.contact = true",
                 "expected a table"},
        BadScene{"enabled_string", With("effects.contact.enabled", "\"no\""),
                 "effects.contact.enabled = \"no\"", "expected a boolean"},
        BadScene{"voltage_string",
                 With("effects.electrostatic.voltage", "\"high\"")
                     .Set("effects.electrostatic.enabled", "false"),
                 "effects.electrostatic.voltage = \"high\"", "expected a number"},
        BadScene{"trajectory_number", With("device.trajectory", "1"), "device.trajectory = 1",
                 "expected a string"}),
    CaseName);

INSTANTIATE_TEST_SUITE_P(
    OutOfRange, SceneValidationTest,
    ::testing::Values(
        BadScene{"negative_length", With("structure.length", "-2e-6"), "structure.length = -2e-06",
                 "must be positive"},
        BadScene{"zero_width", With("structure.width", "0"), "structure.width = 0",
                 "must be positive"},
        BadScene{"zero_thickness", With("structure.thickness", "0.0"), "structure.thickness = 0.0",
                 "must be positive"},
        BadScene{"zero_gap", With("structure.gap", "0.0"), "structure.gap = 0.0",
                 "must be positive"},
        BadScene{"negative_modulus", With("material.young_modulus", "-169e9"),
                 "material.young_modulus = -1.69e+11", "must be positive"},
        BadScene{"zero_density", With("material.density", "0"), "material.density = 0",
                 "must be positive"},
        BadScene{"infinite_length", With("structure.length", "inf"), "structure.length = inf",
                 "must be finite"},
        BadScene{"nan_axial_load", With("structure.axial_load", "nan"),
                 "structure.axial_load = nan", "must be finite"},
        BadScene{"poisson_half", With("material.poisson_ratio", "0.5"),
                 "material.poisson_ratio = 0.5", "must lie in (-1, 0.5)"},
        BadScene{"poisson_minus_one", With("material.poisson_ratio", "-1"),
                 "material.poisson_ratio = -1", "must lie in (-1, 0.5)"},
        BadScene{"zero_elements", With("model.elements", "0"), "model.elements = 0",
                 "must be at least 1"},
        BadScene{"too_many_elements", With("model.elements", "100001"), "model.elements = 100001",
                 "must be at most 100000"},
        BadScene{"dimension_one", With("model.dimension", "1"), "model.dimension = 1",
                 "must be 2 or 3"},
        BadScene{"series_order_negative", With("model.series_order", "-1"),
                 "model.series_order = -1", "must be non-negative"},
        BadScene{"series_order_seven", With("model.series_order", "7"), "model.series_order = 7",
                 "must be at most 6"},
        BadScene{"negative_modes", With("model.modes", "-1"), "model.modes = -1",
                 "must be non-negative"},
        BadScene{"zero_modal_count", With("analysis.type", "\"modal\"").Set("analysis.count", "0"),
                 "analysis.count = 0", "must be at least 1"},
        BadScene{"short_vector", With("loads.tip_force", "[0.0, 1.0]"),
                 "loads.tip_force = [0.0, 1.0]", "expected an array of 3 numbers"},
        BadScene{"long_vector", With("loads.midspan_force", "[0, 0, 0, 0]"),
                 "loads.midspan_force = [0, 0, 0, 0]", "expected an array of 3 numbers"},
        BadScene{"vector_of_strings", With("loads.distributed", "[0, \"a\", 0]"),
                 "loads.distributed = [0, \"a\", 0]", "expected an array of 3 numbers"},
        BadScene{"scalar_vector", With("loads.tip_moment", "1.0"), "loads.tip_moment = 1.0",
                 "expected an array of 3 numbers"},
        BadScene{"nan_component", With("loads.tip_force", "[0.0, nan, 0.0]"),
                 "loads.tip_force[1] = nan", "must be finite"},
        BadScene{"negative_adhesion",
                 With("effects.stiction.enabled", "false")
                     .Set("effects.stiction.adhesion_energy", "-0.02"),
                 "effects.stiction.adhesion_energy = -0.02", "must be non-negative"},
        BadScene{"electrode_off_the_beam",
                 With("effects.electrostatic.enabled", "false")
                     .Set("effects.electrostatic.electrode_end", "3e-4"),
                 "effects.electrostatic.electrode_end = 3e-04",
                 "must lie on the beam, in [0, 2e-04]"},
        BadScene{"electrode_reversed",
                 With("effects.electrostatic.enabled", "false")
                     .Set("effects.electrostatic.electrode_start", "1e-4")
                     .Set("effects.electrostatic.electrode_end", "5e-5"),
                 "effects.electrostatic.electrode_end = 5e-05", "must exceed electrode_start"},
        BadScene{"zero_hamaker",
                 With("effects.van_der_waals.enabled", "false")
                     .Set("effects.van_der_waals.hamaker", "0.0"),
                 "effects.van_der_waals.hamaker = 0.0", "must be positive"},
        BadScene{"two_dampings",
                 With("effects.damping.enabled", "false")
                     .Set("effects.damping.quality_factor", "100.0")
                     .Set("effects.damping.rayleigh", "[1.0, 0.0]"),
                 "effects.damping.rayleigh = [1.0, 0.0]", "not both"}),
    CaseName);

INSTANTIATE_TEST_SUITE_P(
    UnknownNames, SceneValidationTest,
    ::testing::Values(
        BadScene{"kind", With("structure.kind", "\"plate\""), "structure.kind = \"plate\"",
                 "unknown structure kind (expected \"cantilever\", \"bridge\", \"frame\", "
                 "\"folded_flexure\", \"crab_leg\", \"serpentine\", "
                 "\"torsional_micromirror\" or \"accelerometer\")"},
        BadScene{"theory", With("model.theory", "\"foo\""), "model.theory = \"foo\"",
                 "unknown theory (expected \"linear\", \"stretching\" or \"cosserat\")"},
        BadScene{"analysis", With("analysis.type", "\"harmonic\""), "analysis.type = \"harmonic\"",
                 "unknown analysis type (expected \"static\","},
        BadScene{"backend", With("device.backend", "\"phantom\""), "device.backend = \"phantom\"",
                 "unknown device backend (expected \"scripted\" or \"openhaptics\")"},
        BadScene{"effect", With("effects.magnetic", "{}"), "effects.magnetic = {}",
                 "unknown effect (expected contact, stiction, electrostatic, casimir, "
                 "van_der_waals, damping, squeeze_film or combs)"},
        BadScene{"table", With("substrate.gap", "1e-6"), "substrate = { gap = 1e-06 }",
                 "unknown table (expected structure, material,"},
        BadScene{"root_key", With("title", "\"my beam\""), "title = \"my beam\"", "unknown table"},
        BadScene{"structure_typo", With("structure.lenght", "2e-4"), "structure.lenght = 2e-04",
                 "unknown key (expected kind, thickness, gap, length, width or axial_load)"},
        BadScene{"material_typo", With("material.poisson", "0.3"), "material.poisson = 0.3",
                 "unknown key"},
        BadScene{"model_typo", With("model.element", "10"), "model.element = 10", "unknown key"},
        BadScene{"loads_typo", With("loads.tip_forces", "[0, 0, 0]"),
                 "loads.tip_forces = [0, 0, 0]", "unknown key"},
        BadScene{"analysis_typo", With("analysis.cont", "4"), "analysis.cont = 4", "unknown key"},
        BadScene{"effect_typo", With("effects.stiction.adhesion", "0.02"),
                 "effects.stiction.adhesion = 0.02", "unknown key"},
        BadScene{"device_typo", With("device.speed", "1.0"), "device.speed = 1.0", "unknown key"},
        BadScene{"quoted_key", With("structure.\"a b\"", "1"), "structure.\"a b\" = 1",
                 "unknown key"}),
    CaseName);

// Contact, stiction and the surface pressures: what each needs, and where they act.
INSTANTIATE_TEST_SUITE_P(
    SurfaceEffects, SceneValidationTest,
    ::testing::Values(
        BadScene{"release_without_stiction", With("analysis.type", "\"release\""),
                 "effects.stiction", "declare [effects.stiction]"},
        BadScene{"stiction_without_adhesion", With("effects.stiction.enabled", "true"),
                 "effects.stiction.adhesion_energy", "needs the work of adhesion"},
        BadScene{"zero_adhesion", With("effects.stiction.adhesion_energy", "0.0"),
                 "effects.stiction.adhesion_energy = 0.0", "needs the work of adhesion"},
        BadScene{"contact_without_gap", With("effects.contact", "{}").Remove("structure.gap"),
                 "structure.gap", "effects.contact acts through the substrate"},
        BadScene{"voltage_missing", With("effects.electrostatic.fringing", "false"),
                 "effects.electrostatic.voltage", "needs the voltage (V)"},
        BadScene{"hamaker_missing", With("effects.van_der_waals.enabled", "true"),
                 "effects.van_der_waals = { enabled = true }", "needs its hamaker constant"},
        BadScene{"contact_in_modal",
                 With("effects.contact", "{}").Set("analysis.type", "\"modal\""),
                 "effects.contact = {}", "not available for analysis.type = \"modal\""},
        BadScene{"casimir_in_buckling",
                 With("effects.casimir", "{}").Set("analysis.type", "\"buckling\""),
                 "effects.casimir = {}", "linearises about the straight beam"},
        BadScene{"contact_with_cosserat",
                 With("effects.contact", "{}")
                     .Set("model.theory", "\"cosserat\"")
                     .Set("model.dimension", "3"),
                 "model.theory = \"cosserat\"", "not \"cosserat\""},
        BadScene{"separation_too_large", With("effects.contact.separation", "1.5e-6"),
                 "effects.contact.separation = 1.5e-06", "less than half the gap"},
        BadScene{"negative_tolerance", With("effects.contact.tolerance", "-1e-9"),
                 "effects.contact.tolerance = -1e-09", "must be positive"},
        BadScene{"squeeze_film_without_gap",
                 With("effects.squeeze_film", "{}").Remove("structure.gap"), "structure.gap",
                 "effects.squeeze_film acts through the substrate"},
        BadScene{"squeeze_film_viscosity", With("effects.squeeze_film.viscosity", "0.0"),
                 "effects.squeeze_film.viscosity = 0.0", "must be positive"},
        BadScene{"squeeze_film_mean_free_path",
                 With("effects.squeeze_film.mean_free_path", "-1e-9"),
                 "effects.squeeze_film.mean_free_path = -1e-09", "must be non-negative"},
        BadScene{"squeeze_film_in_modal",
                 With("effects.squeeze_film", "{}").Set("analysis.type", "\"modal\""),
                 "effects.squeeze_film = {}", "not available for analysis.type = \"modal\""},
        BadScene{"squeeze_film_in_modal_transient",
                 With("effects.squeeze_film", "{}")
                     .Set("analysis.type", "\"transient\"")
                     .Set("analysis.duration", "1e-5")
                     .Set("analysis.time_step", "1e-7")
                     .Set("analysis.integrator", "\"modal\"")
                     .Set("model.modes", "2"),
                 "effects.squeeze_film = {}",
                 "not available with analysis.integrator = \"modal\""}),
    CaseName);

// The haptic analysis: its rate, the model it touches, and the [device] keys.
INSTANTIATE_TEST_SUITE_P(
    Haptic, SceneValidationTest,
    ::testing::Values(
        BadScene{"rate", With("analysis.type", "\"haptic\"").Set("analysis.rate", "750.0"),
                 "analysis.rate = 750.0", "must be 500, 1000 or 2000"},
        BadScene{"modes", With("analysis.type", "\"haptic\"").Set("model.modes", "4"),
                 "model.modes = 4", "needs analysis.integrator = \"modal\""},
        BadScene{"integrator",
                 With("analysis.type", "\"haptic\"").Set("analysis.integrator", "\"hht\""),
                 "analysis.integrator = \"hht\"",
                 "unknown haptic integrator (expected \"generalized-alpha\" or \"modal\")"},
        BadScene{"modal_without_modes",
                 With("analysis.type", "\"haptic\"").Set("analysis.integrator", "\"modal\""),
                 "model.modes", "needs at least one mode"},
        BadScene{"modal_squeeze_film",
                 With("analysis.type", "\"haptic\"")
                     .Set("analysis.integrator", "\"modal\"")
                     .Set("model.modes", "4")
                     .Set("effects.squeeze_film", "{}"),
                 "effects.squeeze_film = {}", "a gas film needs the full model's integrator"},
        BadScene{"modal_undamped",
                 With("analysis.type", "\"haptic\"")
                     .Set("analysis.integrator", "\"modal\"")
                     .Set("model.modes", "4"),
                 "effects.damping", "modes that ring for ever without it"},
        BadScene{"cosserat",
                 With("analysis.type", "\"haptic\"")
                     .Set("model.theory", "\"cosserat\"")
                     .Set("model.dimension", "3"),
                 "analysis.type = \"haptic\"", "not available for model.theory = \"cosserat\""},
        BadScene{"position_scale",
                 With("analysis.type", "\"haptic\"").Set("device.position_scale", "-1.0"),
                 "device.position_scale = -1.0", "must be positive"}),
    CaseName);

// The cantilever as a pull-in analysis over its 2 um gap.
SceneText Pullin() {
  return With("analysis.type", "\"pullin\"").Set("effects.electrostatic.fringing", "false");
}

INSTANTIATE_TEST_SUITE_P(
    Pullin, SceneValidationTest,
    ::testing::Values(
        BadScene{"no_electrode", With("analysis.type", "\"pullin\""), "effects.electrostatic",
                 "needs the electrode: declare [effects.electrostatic]"},
        BadScene{"no_gap", Pullin().Remove("structure.gap"), "structure.gap",
                 "needs the substrate: give its gap"},
        BadScene{"van_der_waals_without_hamaker", Pullin().Set("effects.van_der_waals", "{}"),
                 "effects.van_der_waals = {}", "needs its hamaker constant"},
        BadScene{"negative_voltage_max", Pullin().Set("analysis.voltage_max", "-1.0"),
                 "analysis.voltage_max = -1.0", "must be positive"},
        BadScene{"cosserat", Pullin().Set("model.theory", "\"cosserat\""),
                 "analysis.type = \"pullin\"", "not available for model.theory = \"cosserat\""}),
    CaseName);

SceneText StretchingBridge() {
  return With("structure.kind", "\"bridge\"")
      .Remove("loads.tip_force")
      .Set("model.theory", "\"stretching\"");
}

INSTANTIATE_TEST_SUITE_P(
    Stretching, SceneValidationTest,
    ::testing::Values(BadScene{"cantilever", With("model.theory", "\"stretching\""),
                               "model.theory = \"stretching\"", "needs both ends held axially"},
                      BadScene{"explicit_integrator",
                               StretchingBridge()
                                   .Set("analysis.type", "\"transient\"")
                                   .Set("analysis.duration", "1e-5")
                                   .Set("analysis.time_step", "1e-7")
                                   .Set("analysis.integrator", "\"central-difference\""),
                               "analysis.integrator = \"central-difference\"",
                               "needs an implicit integrator"}),
    CaseName);

INSTANTIATE_TEST_SUITE_P(
    LoadsTheModelCannotTake, SceneValidationTest,
    ::testing::Values(
        BadScene{"planar_tip_force_z",
                 With("model.dimension", "2").Set("loads.tip_force", "[0.0, 0.0, 1e-6]"),
                 "loads.tip_force[2] = 1e-06", "out of plane for model.dimension = 2"},
        BadScene{"planar_midspan_force_z",
                 With("model.dimension", "2").Set("loads.midspan_force", "[0.0, 0.0, 1e-6]"),
                 "loads.midspan_force[2] = 1e-06", "out of plane for model.dimension = 2"},
        BadScene{"planar_distributed_z",
                 With("model.dimension", "2").Set("loads.distributed", "[0.0, 0.0, 1.0]"),
                 "loads.distributed[2] = 1.0", "out of plane for model.dimension = 2"},
        BadScene{"planar_tip_moment_x",
                 With("model.dimension", "2").Set("loads.tip_moment", "[1e-9, 0.0, 0.0]"),
                 "loads.tip_moment[0] = 1e-09", "out of plane for model.dimension = 2"},
        BadScene{"planar_tip_moment_y",
                 With("model.dimension", "2").Set("loads.tip_moment", "[0.0, 1e-9, 0.0]"),
                 "loads.tip_moment[1] = 1e-09", "out of plane for model.dimension = 2"},
        BadScene{"bridge_tip_force", With("structure.kind", "\"bridge\""),
                 "loads.tip_force = [0.0, -1e-07, 0.0]", "a bridge has no free end"},
        BadScene{"bridge_tip_moment",
                 With("structure.kind", "\"bridge\"")
                     .Remove("loads.tip_force")
                     .Set("loads.tip_moment", "[0, 0, 1e-9]"),
                 "loads.tip_moment = [0, 0, 1e-09]", "a bridge has no free end"}),
    CaseName);

// The cantilever as a valid transient analysis: 1000 steps of the default Newmark rule.
SceneText Transient() {
  return SceneText()
      .Set("analysis.type", "\"transient\"")
      .Set("analysis.duration", "1e-3")
      .Set("analysis.time_step", "1e-6");
}

SceneText TransientWith(const std::string& key, const std::string& value) {
  return Transient().Set(key, value);
}

SceneText CosseratTransient() { return Transient().Set("model.theory", "\"cosserat\""); }

INSTANTIATE_TEST_SUITE_P(
    Cosserat, SceneValidationTest,
    ::testing::Values(
        BadScene{"planar", With("model.theory", "\"cosserat\"").Set("model.dimension", "2"),
                 "model.dimension = 2", "is a 3-D rod: set model.dimension = 3"},
        BadScene{"modal", With("model.theory", "\"cosserat\"").Set("analysis.type", "\"modal\""),
                 "analysis.type = \"modal\"", "not available for model.theory = \"cosserat\""},
        BadScene{
            "modal_integrator",
            CosseratTransient().Set("analysis.integrator", "\"modal\"").Set("model.modes", "2"),
            "analysis.integrator = \"modal\"", "has no modes to propagate"},
        BadScene{"explicit_integrator",
                 CosseratTransient().Set("analysis.integrator", "\"central-difference\""),
                 "analysis.integrator = \"central-difference\"", "needs an implicit integrator"},
        BadScene{"damping", CosseratTransient().Set("effects.damping.quality_factor", "100.0"),
                 "effects.damping = { quality_factor = 100.0 }",
                 "not available for model.theory = \"cosserat\""}),
    CaseName);

INSTANTIATE_TEST_SUITE_P(
    Transient, SceneValidationTest,
    ::testing::Values(
        BadScene{"no_duration", Transient().Remove("analysis.duration"), "analysis.duration",
                 "missing required key"},
        BadScene{"no_time_step", Transient().Remove("analysis.time_step"), "analysis.time_step",
                 "missing required key"},
        BadScene{"zero_duration", TransientWith("analysis.duration", "0.0"),
                 "analysis.duration = 0.0", "must be positive"},
        BadScene{"zero_time_step", TransientWith("analysis.time_step", "0"),
                 "analysis.time_step = 0", "must be positive"},
        BadScene{"negative_time_step", TransientWith("analysis.time_step", "-1e-6"),
                 "analysis.time_step = -1e-06", "must be positive"},
        BadScene{"time_step_beyond_duration", TransientWith("analysis.time_step", "2e-3"),
                 "analysis.time_step = 0.002", "must not exceed analysis.duration = 0.001"},
        BadScene{"too_many_steps",
                 TransientWith("analysis.duration", "1.0").Set("analysis.time_step", "1e-9"),
                 "analysis.time_step = 1e-09", "more than 1e8 steps over analysis.duration = 1"},
        BadScene{"duration_string", TransientWith("analysis.duration", "\"1 ms\""),
                 "analysis.duration = \"1 ms\"", "expected a number"},
        BadScene{"unknown_integrator", TransientWith("analysis.integrator", "\"rk4\""),
                 "analysis.integrator = \"rk4\"",
                 "unknown integrator (expected \"newmark\", \"hht\", \"generalized-alpha\", "
                 "\"central-difference\" or \"modal\")"},
        BadScene{"integrator_number", TransientWith("analysis.integrator", "1"),
                 "analysis.integrator = 1", "expected a string"},
        BadScene{"alpha_for_newmark", TransientWith("analysis.alpha", "0.1"),
                 "analysis.alpha = 0.1", "only the \"hht\" integrator takes it"},
        BadScene{"beta_for_hht",
                 TransientWith("analysis.integrator", "\"hht\"").Set("analysis.beta", "0.3"),
                 "analysis.beta = 0.3", "only the \"newmark\" integrator takes it"},
        BadScene{"gamma_for_central_difference",
                 TransientWith("analysis.integrator", "\"central-difference\"")
                     .Set("analysis.gamma", "0.5"),
                 "analysis.gamma = 0.5", "only the \"newmark\" integrator takes it"},
        BadScene{"rho_inf_for_hht",
                 TransientWith("analysis.integrator", "\"hht\"").Set("analysis.rho_inf", "0.5"),
                 "analysis.rho_inf = 0.5", "only the \"generalized-alpha\" integrator takes it"},
        BadScene{"alpha_for_modal",
                 TransientWith("analysis.integrator", "\"modal\"")
                     .Set("model.modes", "4")
                     .Set("analysis.alpha", "0.1"),
                 "analysis.alpha = 0.1", "only the \"hht\" integrator takes it"},
        BadScene{"beta_above_half", TransientWith("analysis.beta", "0.6"), "analysis.beta = 0.6",
                 "must lie in [0, 0.5]"},
        BadScene{"negative_beta", TransientWith("analysis.beta", "-0.1"), "analysis.beta = -0.1",
                 "must lie in [0, 0.5]"},
        BadScene{"gamma_below_half", TransientWith("analysis.gamma", "0.4"), "analysis.gamma = 0.4",
                 "must lie in [0.5, 1]"},
        BadScene{"alpha_above_third",
                 TransientWith("analysis.integrator", "\"hht\"").Set("analysis.alpha", "0.34"),
                 "analysis.alpha = 0.34", "must lie in [0, 1/3]"},
        BadScene{"negative_alpha",
                 TransientWith("analysis.integrator", "\"hht\"").Set("analysis.alpha", "-0.05"),
                 "analysis.alpha = -0.05", "must lie in [0, 1/3]"},
        BadScene{"rho_inf_above_one",
                 TransientWith("analysis.integrator", "\"generalized-alpha\"")
                     .Set("analysis.rho_inf", "1.5"),
                 "analysis.rho_inf = 1.5", "must lie in [0, 1]"},
        BadScene{"rho_inf_negative",
                 TransientWith("analysis.integrator", "\"generalized-alpha\"")
                     .Set("analysis.rho_inf", "-0.5"),
                 "analysis.rho_inf = -0.5", "must lie in [0, 1]"},
        BadScene{"unknown_initial", TransientWith("analysis.initial", "\"deflected\""),
                 "analysis.initial = \"deflected\"",
                 "unknown initial state (expected \"rest\" or \"static\")"},
        BadScene{"modal_without_modes", TransientWith("analysis.integrator", "\"modal\""),
                 "model.modes", "analysis.integrator = \"modal\" needs at least one mode"},
        BadScene{"modal_with_zero_modes",
                 TransientWith("analysis.integrator", "\"modal\"").Set("model.modes", "0"),
                 "model.modes = 0", "analysis.integrator = \"modal\" needs at least one mode"},
        BadScene{"modes_without_modal", TransientWith("model.modes", "4"), "model.modes = 4",
                 "modal reduction needs analysis.integrator = \"modal\""},
        BadScene{"static_start_with_ramp",
                 TransientWith("analysis.initial", "\"static\"")
                     .Set("loads.time_function", "\"ramp\"")
                     .Set("loads.ramp_time", "1e-5"),
                 "loads.time_function = \"ramp\"",
                 "analysis.initial = \"static\" removes the loads at t = 0"},
        BadScene{"static_start_with_sine",
                 TransientWith("analysis.initial", "\"static\"")
                     .Set("loads.time_function", "\"sine\"")
                     .Set("loads.frequency", "1e4"),
                 "loads.time_function = \"sine\"", "only \"step\" goes with it"}),
    CaseName);

INSTANTIATE_TEST_SUITE_P(
    TimeFunctions, SceneValidationTest,
    ::testing::Values(
        BadScene{"unknown", TransientWith("loads.time_function", "\"square\""),
                 "loads.time_function = \"square\"",
                 "unknown time function (expected \"step\", \"ramp\" or \"sine\")"},
        BadScene{"ramp_without_ramp_time", TransientWith("loads.time_function", "\"ramp\""),
                 "loads.time_function = \"ramp\"", "needs loads.ramp_time (s, > 0)"},
        BadScene{"sine_without_frequency", TransientWith("loads.time_function", "\"sine\""),
                 "loads.time_function = \"sine\"", "needs loads.frequency (Hz, > 0)"},
        BadScene{"zero_ramp_time",
                 TransientWith("loads.time_function", "\"ramp\"").Set("loads.ramp_time", "0.0"),
                 "loads.ramp_time = 0.0", "must be positive"},
        BadScene{"negative_frequency",
                 TransientWith("loads.time_function", "\"sine\"").Set("loads.frequency", "-1e3"),
                 "loads.frequency = -1000.0", "must be positive"},
        BadScene{"ramp_time_for_a_step", TransientWith("loads.ramp_time", "1e-5"),
                 "loads.ramp_time = 1e-05", "only the \"ramp\" time function takes it"},
        BadScene{"frequency_for_a_ramp",
                 TransientWith("loads.time_function", "\"ramp\"")
                     .Set("loads.ramp_time", "1e-5")
                     .Set("loads.frequency", "1e4"),
                 "loads.frequency = 10000.0", "only the \"sine\" time function takes it"},
        // The loads' time history is checked in every analysis: it describes the loads.
        BadScene{"ramp_without_ramp_time_in_a_static_analysis",
                 With("loads.time_function", "\"ramp\""), "loads.time_function = \"ramp\"",
                 "needs loads.ramp_time"}),
    CaseName);

INSTANTIATE_TEST_SUITE_P(
    Damping, SceneValidationTest,
    ::testing::Values(
        BadScene{"empty", TransientWith("effects.damping", "{}"), "effects.damping = {}",
                 "needs quality_factor or rayleigh = [alpha, beta]"},
        BadScene{"only_enabled", TransientWith("effects.damping.enabled", "true"),
                 "effects.damping = { enabled = true }", "needs quality_factor or rayleigh"},
        BadScene{"both",
                 TransientWith("effects.damping.quality_factor", "100.0")
                     .Set("effects.damping.rayleigh", "[1.0, 0.0]"),
                 "effects.damping.rayleigh = [1.0, 0.0]",
                 "give quality_factor or rayleigh, not both"},
        BadScene{"zero_quality_factor", TransientWith("effects.damping.quality_factor", "0.0"),
                 "effects.damping.quality_factor = 0.0", "must be positive"},
        BadScene{"negative_rayleigh", TransientWith("effects.damping.rayleigh", "[-1.0, 0.0]"),
                 "effects.damping.rayleigh = [-1.0, 0.0]", "must be non-negative"},
        BadScene{"short_rayleigh", TransientWith("effects.damping.rayleigh", "[1.0]"),
                 "effects.damping.rayleigh = [1.0]", "expected an array of 2 numbers"}),
    CaseName);

// Every bound of scene_limits.hpp, just beyond it: the message names the key and the limit.
INSTANTIATE_TEST_SUITE_P(
    Limits, SceneValidationTest,
    ::testing::Values(
        BadScene{"length_tiny", With("structure.length", "1e-13"), "structure.length = 1e-13",
                 "must lie in [1e-12, 1] m"},
        BadScene{"length_huge", With("structure.length", "1e300"), "structure.length = 1e+300",
                 "must lie in [1e-12, 1] m"},
        BadScene{"width_tiny", With("structure.width", "1e-13"), "structure.width = 1e-13",
                 "must lie in [1e-12, 1] m"},
        // b t^3 / 12 would underflow to 0, and the internal units divide by EI.
        BadScene{"thickness_underflowing", With("structure.thickness", "1e-120"),
                 "structure.thickness = 1e-120", "must lie in [1e-12, 1] m"},
        BadScene{"thickness_huge", With("structure.thickness", "2.0"), "structure.thickness = 2.0",
                 "must lie in [1e-12, 1] m"},
        BadScene{"gap_huge", With("structure.gap", "1.5"), "structure.gap = 1.5",
                 "must lie in [1e-12, 1] m"},
        BadScene{"axial_load_huge", With("structure.axial_load", "-2e6"),
                 "structure.axial_load = -2e+06", "must lie in [-1e+06, 1e+06] N"},
        BadScene{"modulus_tiny", With("material.young_modulus", "1e-300"),
                 "material.young_modulus = 1e-300", "must lie in [1, 1e+13] Pa"},
        BadScene{"modulus_huge", With("material.young_modulus", "1e14"),
                 "material.young_modulus = 1e+14", "must lie in [1, 1e+13] Pa"},
        BadScene{"density_tiny", With("material.density", "0.01"), "material.density = 0.01",
                 "must lie in [0.1, 1e+05] kg/m^3"},
        BadScene{"density_huge", With("material.density", "1e6"), "material.density = 1e+06",
                 "must lie in [0.1, 1e+05] kg/m^3"},
        BadScene{"tip_force", With("loads.tip_force", "[0.0, -1e7, 0.0]"),
                 "loads.tip_force[1] = -1e+07", "must lie in [-1e+06, 1e+06] N"},
        BadScene{"midspan_force", With("loads.midspan_force", "[2e6, 0.0, 0.0]"),
                 "loads.midspan_force[0] = 2e+06", "must lie in [-1e+06, 1e+06] N"},
        BadScene{"distributed", With("loads.distributed", "[0.0, -1e300, 0.0]"),
                 "loads.distributed[1] = -1e+300", "must lie in [-1e+06, 1e+06] N/m"},
        BadScene{"tip_moment", With("loads.tip_moment", "[0.0, 0.0, 1e7]"),
                 "loads.tip_moment[2] = 1e+07", "must lie in [-1e+06, 1e+06] N m"},
        BadScene{"modes", With("model.modes", "101"), "model.modes = 101", "must be at most 100"},
        BadScene{"modal_count", With("analysis.type", "\"modal\"").Set("analysis.count", "101"),
                 "analysis.count = 101", "must be at most 100"},
        BadScene{"modal_count_huge",
                 With("analysis.type", "\"modal\"").Set("analysis.count", "2000000000"),
                 "analysis.count = 2000000000", "must be at most 100"},
        BadScene{"haptic_duration",
                 With("analysis.type", "\"haptic\"").Set("analysis.duration", "3601.0"),
                 "analysis.duration = 3601.0", "must lie in [1e-15, 3600] s"},
        BadScene{"haptic_duration_huge",
                 With("analysis.type", "\"haptic\"").Set("analysis.duration", "1e300"),
                 "analysis.duration = 1e+300", "must lie in [1e-15, 3600] s"},
        // Named before the step count they would make.
        BadScene{"transient_duration", TransientWith("analysis.duration", "2e6"),
                 "analysis.duration = 2e+06", "must lie in [1e-15, 1e+06] s"},
        BadScene{"transient_time_step", TransientWith("analysis.time_step", "1e-16"),
                 "analysis.time_step = 1e-16", "must lie in [1e-15, 1e+06] s"},
        BadScene{"ramp_time",
                 TransientWith("loads.time_function", "\"ramp\"").Set("loads.ramp_time", "1e-16"),
                 "loads.ramp_time = 1e-16", "must lie in [1e-15, 1e+06] s"},
        BadScene{"frequency",
                 TransientWith("loads.time_function", "\"sine\"").Set("loads.frequency", "1e16"),
                 "loads.frequency = 1e+16", "must lie in [1e-06, 1e+15] Hz"},
        BadScene{"separation", With("effects.contact.separation", "2.0"),
                 "effects.contact.separation = 2.0", "must lie in [0, 1] m"},
        BadScene{"tolerance", With("effects.contact.tolerance", "1e-13"),
                 "effects.contact.tolerance = 1e-13", "must lie in [1e-12, 1] m"},
        BadScene{"proximity", With("effects.contact.proximity", "2.0"),
                 "effects.contact.proximity = 2.0", "must lie in [1e-12, 1] m"},
        BadScene{"adhesion_energy", With("effects.stiction.adhesion_energy", "1e4"),
                 "effects.stiction.adhesion_energy = 10000.0", "must lie in [0, 1000] J/m^2"},
        BadScene{"voltage", With("effects.electrostatic.voltage", "-2e6"),
                 "effects.electrostatic.voltage = -2e+06", "must lie in [-1e+06, 1e+06] V"},
        BadScene{"voltage_max", Pullin().Set("analysis.voltage_max", "2e6"),
                 "analysis.voltage_max = 2e+06", "must lie in [1e-06, 1e+06] V"},
        BadScene{"hamaker", With("effects.van_der_waals.hamaker", "1e-10"),
                 "effects.van_der_waals.hamaker = 1e-10", "must lie in [1e-25, 1e-15] J"},
        BadScene{"quality_factor", TransientWith("effects.damping.quality_factor", "1e-4"),
                 "effects.damping.quality_factor = 1e-04", "must lie in [0.001, 1e+12]"},
        BadScene{"rayleigh_alpha", TransientWith("effects.damping.rayleigh", "[1e13, 0.0]"),
                 "effects.damping.rayleigh[0] = 1e+13", "must lie in [0, 1e+12] 1/s"},
        BadScene{"rayleigh_beta", TransientWith("effects.damping.rayleigh", "[0.0, 2.0]"),
                 "effects.damping.rayleigh[1] = 2.0", "must lie in [0, 1] s"},
        BadScene{"viscosity", With("effects.squeeze_film.viscosity", "1e4"),
                 "effects.squeeze_film.viscosity = 10000.0", "must lie in [1e-08, 1000] Pa s"},
        BadScene{"mean_free_path", With("effects.squeeze_film.mean_free_path", "2.0"),
                 "effects.squeeze_film.mean_free_path = 2.0", "must lie in [0, 1] m"},
        BadScene{"position_scale", With("device.position_scale", "1e13"),
                 "device.position_scale = 1e+13", "must lie in [1e-12, 1e+12]"},
        BadScene{"force_scale", With("device.force_scale", "1e-13"), "device.force_scale = 1e-13",
                 "must lie in [1e-12, 1e+12]"},
        BadScene{"coupling_stiffness", With("device.coupling_stiffness", "1e13"),
                 "device.coupling_stiffness = 1e+13", "must lie in [1e-12, 1e+12] N/m"},
        BadScene{"probe_radius", With("device.probe_radius", "2.0"), "device.probe_radius = 2.0",
                 "must lie in [1e-12, 1] m"}),
    CaseName);

TEST(SceneValidationAcceptanceTest, AcceptsWhatThePlanarModelRepresents) {
  const Scene scene = LoadSceneText(SceneText()
                                        .Set("model.dimension", "2")
                                        .Set("loads.tip_force", "[1e-7, -1e-7, 0.0]")
                                        .Set("loads.tip_moment", "[0.0, 0.0, 1e-12]")
                                        .Render(),
                                    "x.toml");
  EXPECT_EQ(scene.model.dimension, 2);
}

TEST(SceneValidationAcceptanceTest, AcceptsDisabledEffectsAndZeroTipLoadsOnABridge) {
  const Scene scene = LoadSceneText(SceneText()
                                        .Set("structure.kind", "\"bridge\"")
                                        .Set("loads.tip_force", "[0, 0, 0]")
                                        .Set("effects.contact.enabled", "false")
                                        .Render(),
                                    "x.toml");
  EXPECT_EQ(scene.structure.kind, StructureKind::kBridge);
  EXPECT_FALSE(scene.effects.contact->enabled);
}

TEST(SceneValidationAcceptanceTest, TransientDefaults) {
  const Scene scene = LoadSceneText(Transient().Render(), "x.toml");
  const SceneAnalysis& a = scene.analysis;
  EXPECT_EQ(a.type, AnalysisType::kTransient);
  EXPECT_EQ(a.duration, 1e-3);
  EXPECT_EQ(a.time_step, 1e-6);
  EXPECT_EQ(a.integrator, Integrator::kNewmark);
  EXPECT_EQ(a.beta, 0.25);
  EXPECT_EQ(a.gamma, 0.5);
  EXPECT_EQ(a.alpha, 0.05);
  EXPECT_EQ(a.rho_inf, 0.8);
  EXPECT_EQ(a.initial, InitialState::kRest);
  EXPECT_FALSE(scene.loads.time_function.has_value());
  EXPECT_FALSE(scene.effects.damping.has_value());
  EXPECT_EQ(scene.model.modes, 0);
}

TEST(SceneValidationAcceptanceTest, ReadsEachIntegratorsOwnParameter) {
  const Scene newmark = LoadSceneText(
      Transient().Set("analysis.beta", "0.0").Set("analysis.gamma", "0.6").Render(), "x.toml");
  EXPECT_EQ(newmark.analysis.beta, 0.0);
  EXPECT_EQ(newmark.analysis.gamma, 0.6);
  const Scene hht = LoadSceneText(
      TransientWith("analysis.integrator", "\"hht\"").Set("analysis.alpha", "0.3").Render(),
      "x.toml");
  EXPECT_EQ(hht.analysis.integrator, Integrator::kHht);
  EXPECT_EQ(hht.analysis.alpha, 0.3);
  const Scene alpha = LoadSceneText(TransientWith("analysis.integrator", "\"generalized-alpha\"")
                                        .Set("analysis.rho_inf", "0")
                                        .Render(),
                                    "x.toml");
  EXPECT_EQ(alpha.analysis.integrator, Integrator::kGeneralizedAlpha);
  EXPECT_EQ(alpha.analysis.rho_inf, 0.0);
  const Scene explicit_rule = LoadSceneText(
      TransientWith("analysis.integrator", "\"central-difference\"").Render(), "x.toml");
  EXPECT_EQ(explicit_rule.analysis.integrator, Integrator::kCentralDifference);
  const Scene modal = LoadSceneText(TransientWith("analysis.integrator", "\"modal\"")
                                        .Set("model.modes", "4")
                                        .Set("analysis.initial", "\"static\"")
                                        .Render(),
                                    "x.toml");
  EXPECT_EQ(modal.analysis.integrator, Integrator::kModal);
  EXPECT_EQ(modal.model.modes, 4);
  EXPECT_EQ(modal.analysis.initial, InitialState::kStatic);
}

TEST(SceneValidationAcceptanceTest, ReadsTimeFunctionsAndTheirParameters) {
  const Scene ramp = LoadSceneText(
      TransientWith("loads.time_function", "\"ramp\"").Set("loads.ramp_time", "2e-5").Render(),
      "x.toml");
  ASSERT_TRUE(ramp.loads.time_function.has_value());
  EXPECT_EQ(ramp.loads.time_function->kind, TimeFunctionKind::kRamp);
  EXPECT_EQ(ramp.loads.time_function->ramp_time, 2e-5);
  const Scene sine = LoadSceneText(
      TransientWith("loads.time_function", "\"sine\"").Set("loads.frequency", "5e4").Render(),
      "x.toml");
  EXPECT_EQ(sine.loads.time_function->kind, TimeFunctionKind::kSine);
  EXPECT_EQ(sine.loads.time_function->frequency, 5e4);
  // A release from the static deflection goes with an explicit step.
  const Scene step = LoadSceneText(TransientWith("loads.time_function", "\"step\"")
                                       .Set("analysis.initial", "\"static\"")
                                       .Render(),
                                   "x.toml");
  EXPECT_EQ(step.loads.time_function->kind, TimeFunctionKind::kStep);
}

// Accepted in static and modal analyses, where they change nothing (the CLI warns).
TEST(SceneValidationAcceptanceTest, AcceptsDampingModesAndTimeFunctionsOutsideTransients) {
  for (const char* type : {"\"static\"", "\"modal\""}) {
    SCOPED_TRACE(type);
    const Scene scene = LoadSceneText(With("analysis.type", type)
                                          .Set("model.modes", "4")
                                          .Set("effects.damping.rayleigh", "[10.0, 1e-9]")
                                          .Set("loads.time_function", "\"sine\"")
                                          .Set("loads.frequency", "1e4")
                                          .Render(),
                                      "x.toml");
    EXPECT_EQ(scene.model.modes, 4);
    EXPECT_TRUE(scene.effects.damping->enabled);
    EXPECT_EQ(scene.loads.time_function->kind, TimeFunctionKind::kSine);
  }
}

// A disabled damping table need not name a model: it only switches damping off.
TEST(SceneValidationAcceptanceTest, AcceptsADisabledDampingTableWithoutParameters) {
  const Scene scene =
      LoadSceneText(TransientWith("effects.damping.enabled", "false").Render(), "x.toml");
  EXPECT_FALSE(scene.effects.damping->enabled);
}

}  // namespace
}  // namespace cosmems
