#include "cosmems/scene/scene_conversion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "cosmems/analysis/static_analysis.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/scene/scene_loader.hpp"

namespace cosmems {
namespace {

Scene Load(const std::string& name, const std::vector<std::string>& assignments = {}) {
  std::vector<SceneOverride> overrides;
  for (const std::string& a : assignments) overrides.push_back(SceneOverride::Parse(a));
  return LoadScene(name, overrides);
}

TEST(SceneConversionTest, CantileverIsClampedAtTheRootOnly) {
  const Scene scene = Load("cantilever", {"model.elements=8", "model.series_order=2"});
  const BeamDescription beam = MakeBeamDescription(scene);
  ASSERT_EQ(beam.elements.size(), 8u);
  EXPECT_DOUBLE_EQ(beam.Length(), 200e-6);
  EXPECT_EQ(beam.series_order, 2);
  EXPECT_EQ(beam.supports.front(), Support::kClamped);
  EXPECT_EQ(beam.supports.back(), Support::kFree);
  for (const ElementSpec& element : beam.elements) {
    EXPECT_EQ(element.section.width, 20e-6);
    EXPECT_EQ(element.section.thickness, 2e-6);
    EXPECT_EQ(element.material.young_modulus, 169e9);
    EXPECT_EQ(element.material.density, 2330.0);
    EXPECT_EQ(element.material.poisson_ratio, 0.22);
  }
}

TEST(SceneConversionTest, BridgeIsClampedAtBothEnds) {
  const BeamDescription beam = MakeBeamDescription(Load("microbridge"));
  EXPECT_EQ(beam.supports.front(), Support::kClamped);
  EXPECT_EQ(beam.supports.back(), Support::kClamped);
  for (std::size_t n = 1; n + 1 < beam.supports.size(); ++n) {
    EXPECT_EQ(beam.supports[n], Support::kFree);
  }
}

TEST(SceneConversionTest, PlateModulusDividesByOneMinusNuSquared) {
  SceneMaterial material;
  material.young_modulus = 169e9;
  material.density = 2330.0;
  material.poisson_ratio = 0.28;
  EXPECT_EQ(EffectiveMaterial(material).young_modulus, 169e9);
  material.plate_modulus = true;
  EXPECT_DOUBLE_EQ(EffectiveMaterial(material).young_modulus, 169e9 / (1.0 - 0.28 * 0.28));
  EXPECT_EQ(EffectiveMaterial(material).density, 2330.0);
  EXPECT_EQ(EffectiveMaterial(material).poisson_ratio, 0.28);
}

TEST(SceneConversionTest, TipLoadsActAtTheFreeEnd) {
  const LoadCase loads = MakeLoadCase(Load("cantilever", {"loads.tip_moment=[0, 0, 1e-12]"}));
  ASSERT_EQ(loads.points.size(), 1u);
  EXPECT_EQ(loads.points[0].x, 200e-6);
  EXPECT_EQ(loads.points[0].force, Eigen::Vector3d(0.0, -1e-7, 0.0));
  EXPECT_EQ(loads.points[0].moment, Eigen::Vector3d(0.0, 0.0, 1e-12));
  EXPECT_EQ(loads.distributed, Eigen::Vector3d::Zero());
}

TEST(SceneConversionTest, MidspanAndDistributedLoadsOnABridge) {
  const LoadCase loads = MakeLoadCase(Load("microbridge", {"loads.distributed=[0, -2.0, 0]"}));
  ASSERT_EQ(loads.points.size(), 1u);
  EXPECT_EQ(loads.points[0].x, 50e-6);
  EXPECT_EQ(loads.points[0].force, Eigen::Vector3d(0.0, -1e-5, 0.0));
  EXPECT_EQ(loads.points[0].moment, Eigen::Vector3d::Zero());
  EXPECT_EQ(loads.distributed, Eigen::Vector3d(0.0, -2.0, 0.0));
}

TEST(SceneConversionTest, LeavesOutZeroLoads) {
  const LoadCase loads = MakeLoadCase(Load("cantilever", {"loads.tip_force=[0, 0, 0]"}));
  EXPECT_TRUE(loads.points.empty());
}

// cantilever-release as a run of the full model, by Newmark's rule unless `assignments` say
// otherwise.
Scene FullOrderRelease(const std::vector<std::string>& assignments) {
  std::vector<std::string> all = {"model.modes=0", "analysis.integrator=newmark"};
  all.insert(all.end(), assignments.begin(), assignments.end());
  return Load("cantilever-release", all);
}

void ExpectParameters(const GeneralizedAlphaParameters& actual,
                      const GeneralizedAlphaParameters& expected) {
  EXPECT_EQ(actual.alpha_m, expected.alpha_m);
  EXPECT_EQ(actual.alpha_f, expected.alpha_f);
  EXPECT_EQ(actual.beta, expected.beta);
  EXPECT_EQ(actual.gamma, expected.gamma);
}

TEST(SceneConversionTest, ModalReleaseRecordsTheTip) {
  const TransientOptions o = MakeTransientOptions(Load("cantilever-release"));
  EXPECT_EQ(o.duration, 1e-3);
  EXPECT_EQ(o.time_step, 1e-6);
  EXPECT_EQ(o.path, TimePath::kModal);
  EXPECT_EQ(o.modes, 4);
  EXPECT_TRUE(o.start_static);
  EXPECT_EQ(o.time_function.kind, LoadTimeFunction::Kind::kStep);
  EXPECT_EQ(o.damping.kind, DampingModel::Kind::kQualityFactor);
  EXPECT_EQ(o.damping.quality_factor, 100.0);
  EXPECT_EQ(o.output_x, 200e-6);
}

TEST(SceneConversionTest, EachIntegratorGetsItsGeneralizedAlphaParameters) {
  const TransientOptions newmark = MakeTransientOptions(
      FullOrderRelease({"analysis.integrator=newmark", "analysis.beta=0.3", "analysis.gamma=0.6"}));
  EXPECT_EQ(newmark.path, TimePath::kNewmarkFamily);
  ExpectParameters(newmark.parameters, GeneralizedAlphaParameters::Newmark(0.3, 0.6));
  ExpectParameters(
      MakeTransientOptions(FullOrderRelease({"analysis.integrator=newmark"})).parameters,
      GeneralizedAlphaParameters::Newmark(0.25, 0.5));
  ExpectParameters(
      MakeTransientOptions(FullOrderRelease({"analysis.integrator=hht", "analysis.alpha=0.1"}))
          .parameters,
      GeneralizedAlphaParameters::Hht(0.1));
  ExpectParameters(MakeTransientOptions(FullOrderRelease({"analysis.integrator=hht"})).parameters,
                   GeneralizedAlphaParameters::Hht(0.05));
  ExpectParameters(MakeTransientOptions(FullOrderRelease({"analysis.integrator=generalized-alpha",
                                                          "analysis.rho_inf=0.5"}))
                       .parameters,
                   GeneralizedAlphaParameters::FromSpectralRadius(0.5));
  ExpectParameters(
      MakeTransientOptions(FullOrderRelease({"analysis.integrator=generalized-alpha"})).parameters,
      GeneralizedAlphaParameters::FromSpectralRadius(0.8));
  const TransientOptions explicit_rule =
      MakeTransientOptions(FullOrderRelease({"analysis.integrator=central-difference"}));
  ExpectParameters(explicit_rule.parameters, GeneralizedAlphaParameters::CentralDifference());
  EXPECT_TRUE(explicit_rule.parameters.IsExplicit());
}

TEST(SceneConversionTest, BridgeTransientRecordsTheMidspan) {
  const TransientOptions o =
      MakeTransientOptions(Load("microbridge", {"analysis.type=transient", "analysis.duration=1e-5",
                                                "analysis.time_step=1e-8"}));
  EXPECT_EQ(o.output_x, 50e-6);
  EXPECT_FALSE(o.start_static);
  EXPECT_EQ(o.path, TimePath::kNewmarkFamily);
  EXPECT_EQ(o.damping.kind, DampingModel::Kind::kNone);
}

TEST(SceneConversionTest, TimeFunctionsCarryTheirParameters) {
  const std::vector<std::string> from_rest = {"analysis.initial=rest"};
  EXPECT_EQ(MakeLoadTimeFunction(FullOrderRelease(from_rest)).kind, LoadTimeFunction::Kind::kStep);
  std::vector<std::string> ramp = from_rest;
  ramp.insert(ramp.end(), {"loads.time_function=ramp", "loads.ramp_time=2e-5"});
  const LoadTimeFunction r = MakeLoadTimeFunction(FullOrderRelease(ramp));
  EXPECT_EQ(r.kind, LoadTimeFunction::Kind::kRamp);
  EXPECT_EQ(r.ramp_time, 2e-5);
  EXPECT_EQ(r.Value(1e-5), 0.5);
  std::vector<std::string> sine = from_rest;
  sine.insert(sine.end(), {"loads.time_function=sine", "loads.frequency=5e4"});
  const LoadTimeFunction s = MakeLoadTimeFunction(FullOrderRelease(sine));
  EXPECT_EQ(s.kind, LoadTimeFunction::Kind::kSine);
  EXPECT_EQ(s.frequency, 5e4);
}

TEST(SceneConversionTest, DampingOnlyWhenEnabled) {
  const DampingModel rayleigh =
      MakeDampingModel(Load("cantilever-release", {"effects.damping={ rayleigh = [10.0, 1e-9] }"}));
  EXPECT_EQ(rayleigh.kind, DampingModel::Kind::kRayleigh);
  EXPECT_EQ(rayleigh.rayleigh.mass, 10.0);
  EXPECT_EQ(rayleigh.rayleigh.stiffness, 1e-9);
  EXPECT_EQ(MakeDampingModel(Load("cantilever-release", {"effects.damping.enabled=false"})).kind,
            DampingModel::Kind::kNone);
  EXPECT_EQ(MakeDampingModel(Load("cantilever")).kind, DampingModel::Kind::kNone);
}

// The corners of the length, material and load bounds (src/scene/scene_limits.hpp) are accepted
// and represented: internal units that are normal doubles, finite matrices and a finite static
// deflection under the largest loads. The bounds refuse only what is beyond them.
TEST(SceneConversionTest, TheCornersOfTheBoundsBuildFiniteModels) {
  const std::pair<const char*, const char*> materials[] = {{"1.0", "1e5"}, {"1e13", "0.1"}};
  for (const char* length : {"1e-12", "1.0"}) {
    for (const char* width : {"1e-12", "1.0"}) {
      for (const char* thickness : {"1e-12", "1.0"}) {
        for (const auto& [modulus, density] : materials) {
          const Scene scene = Load(
              "cantilever",
              {std::string("structure.length=") + length, std::string("structure.width=") + width,
               std::string("structure.thickness=") + thickness,
               std::string("material.young_modulus=") + modulus,
               std::string("material.density=") + density, "loads.tip_force=[1e6, -1e6, 1e6]",
               "loads.tip_moment=[1e6, 1e6, 1e6]", "loads.distributed=[-1e6, -1e6, -1e6]"});
          SCOPED_TRACE(std::string(length) + " " + width + " " + thickness + " " + modulus + " " +
                       density);
          const BeamModel<3> model(MakeBeamDescription(scene));
          EXPECT_TRUE(std::isnormal(model.units().force));
          EXPECT_TRUE(std::isnormal(model.units().time));
          EXPECT_TRUE(std::isnormal(model.units().Mass()));
          EXPECT_TRUE(model.Stiffness().data().allFinite());
          EXPECT_TRUE(model.Mass(0).data().allFinite());
          const StaticSolution solution = SolveStatic(model, MakeLoadCase(scene));
          EXPECT_EQ(solution.status, Status::kOk);
          EXPECT_TRUE(solution.displacement.allFinite());
        }
      }
    }
  }
}

}  // namespace
}  // namespace cosmems
