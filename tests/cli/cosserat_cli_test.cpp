// model.theory = "cosserat" through the CLI: the large-deflection scene against the elastica,
// small loads against the linear beam, a bridge against mid-plane stretching, transients and
// buckling. The rod's own accuracy is held by tests/rod; these check the wiring (units, signs,
// which node is the tip, which element is the root) with tolerances from the rod's measured
// discretisation error.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "rod/elastica.hpp"

namespace cosmems {
namespace {

using test::Elastica;
using test::ElasticaTip;
using testing::ExpectContains;
using testing::ReadLines;
using testing::RunJson;
using testing::TempDirectory;

double BendingStiffness(const Scene& scene) {
  return scene.material.young_modulus * scene.structure.width *
         std::pow(scene.structure.thickness, 3) / 12.0;
}

double Component(const nlohmann::json& json, const char* field, int k) {
  return json.at(field).at(k).get<double>();
}

// 50 two-node elements: the rod tests measure 1.3e-4 L against the elastica up to PL^2/EI = 10;
// extension and shear (EI / EA L^2 = 8e-6, EI / kGA L^2 = 2.4e-5 for this section) move the
// tip a further PL^2/EI times their sum, 1e-4 L here.
TEST(CosseratCliTest, LargeDeflectionSceneFollowsTheElastica) {
  const Scene scene = LoadScene("cantilever-large-deflection");
  const double l = scene.structure.length;
  const double alpha = -scene.loads.tip_force.y() * l * l / BendingStiffness(scene);
  ASSERT_NEAR(alpha, 3.0, 1e-3);
  const ElasticaTip tip = Elastica(alpha);
  const nlohmann::json json = RunJson({"cantilever-large-deflection"});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("model").at("theory"), "cosserat");
  EXPECT_EQ(json.at("model").at("dofs"), 50 * 6);
  constexpr double kTolerance = 5e-4;  // of L
  EXPECT_NEAR(Component(json, "tip_displacement", 0) / l, -tip.shortening, kTolerance);
  EXPECT_NEAR(Component(json, "tip_displacement", 1) / l, -tip.deflection, kTolerance);
  EXPECT_EQ(Component(json, "tip_displacement", 2), 0.0);
  EXPECT_NEAR(Component(json, "tip_rotation", 2), -tip.angle, kTolerance);
  EXPECT_NEAR(json.at("max_deflection").get<double>() / l, tip.deflection, kTolerance);
  EXPECT_EQ(json.at("warnings"), nlohmann::json::array());
}

// The default cantilever's 100 nN bends it by 6e-4 of its thickness: the rod must give the
// linear beam's answer. 40 two-node elements are h^2 accurate: 1.5e-4 low at the tip (measured;
// 6.1e-4 at 20, 3.5e-5 at 80), which sets the tolerance. The root stress is the first element's,
// taken at its midpoint where the moment is P (L - h/2): low by h / 2L = 1/80.
TEST(CosseratCliTest, SmallLoadsGiveTheLinearBeam) {
  const std::vector<std::string> args = {"cantilever", "--set", "model.elements=40"};
  std::vector<std::string> rod_args = args;
  rod_args.insert(rod_args.end(), {"--set", "model.theory=cosserat"});
  const nlohmann::json linear = RunJson(args);
  const nlohmann::json rod = RunJson(rod_args);
  EXPECT_EQ(rod.at("status"), "ok");
  constexpr double kTolerance = 3e-4;
  for (const char* field : {"tip_displacement", "midspan_displacement"}) {
    const double expected = Component(linear, field, 1);
    EXPECT_NEAR(Component(rod, field, 1), expected, kTolerance * std::abs(expected)) << field;
  }
  const double rz = Component(linear, "tip_rotation", 2);
  EXPECT_NEAR(Component(rod, "tip_rotation", 2), rz, kTolerance * std::abs(rz));
  const double stress = linear.at("max_stress_pa").get<double>();
  EXPECT_NEAR(rod.at("max_stress_pa").get<double>(), stress * (1.0 - 1.0 / 80.0),
              kTolerance * stress);
  // The root element's axial force is P sin(theta) at its midpoint, below P |theta_tip|.
  const double p = -LoadScene("cantilever").loads.tip_force.y();
  EXPECT_LT(std::abs(rod.at("axial_force_n").get<double>()), p * std::abs(rz));
}

// Pressed to more than a thickness, a bridge stiffens by stretching its axis: the rod holds it
// exactly, the stretching theory to first order in the slopes (w' <= 0.07 here, so the two agree
// within w'^2 = 0.5 %; measured 0.34 % at midspan, 0.05 % in the tension).
TEST(CosseratCliTest, PressedBridgeAgreesWithMidPlaneStretching) {
  const std::vector<std::string> args = {"microbridge", "--set", "loads.midspan_force=[0,-2e-3,0]",
                                         "--set", "structure.gap=1e-4"};
  std::vector<std::string> stretching_args = args, rod_args = args;
  stretching_args.insert(stretching_args.end(), {"--set", "model.theory=stretching"});
  rod_args.insert(rod_args.end(), {"--set", "model.theory=cosserat", "--set", "model.elements=40"});
  const nlohmann::json stretching = RunJson(stretching_args);
  const nlohmann::json rod = RunJson(rod_args);
  EXPECT_EQ(rod.at("status"), "ok");
  EXPECT_FALSE(rod.contains("tip_displacement"));
  const double w = Component(stretching, "midspan_displacement", 1);
  EXPECT_NEAR(Component(rod, "midspan_displacement", 1), w, 5e-3 * std::abs(w));
  const double n = stretching.at("axial_force_n").get<double>();
  EXPECT_NEAR(rod.at("axial_force_n").get<double>(), n, 5e-3 * n);
}

// A suddenly applied small tip force from rest: the rod swings as the linear beam does. Both
// run the same steps (period / 150) with second-order members; the peak agrees within the
// rod's h^2 stiffness error (1.5e-4) plus the two integrators' period errors over one swing
// (~(h omega)^2 / 12 = 1.5e-4 each): 1e-3.
TEST(CosseratCliTest, TransientFollowsTheLinearBeamAtSmallLoads) {
  const std::vector<std::string> args = {"cantilever",
                                         "--set",
                                         "model.elements=40",
                                         "--set",
                                         "analysis.type=transient",
                                         "--set",
                                         "analysis.duration=1e-5",
                                         "--set",
                                         "analysis.time_step=1e-7",
                                         "--set",
                                         "analysis.integrator=generalized-alpha",
                                         "--set",
                                         "analysis.rho_inf=0.9"};
  std::vector<std::string> rod_args = args;
  rod_args.insert(rod_args.end(), {"--set", "model.theory=cosserat"});
  const TempDirectory dir;
  rod_args.insert(rod_args.end(), {"--out", dir.path().string()});
  const nlohmann::json linear = RunJson(args);
  const nlohmann::json rod = RunJson(rod_args);
  EXPECT_EQ(rod.at("status"), "ok");
  EXPECT_EQ(rod.at("steps"), 100);
  EXPECT_EQ(rod.at("warnings"), nlohmann::json::array());
  const double peak = linear.at("tip_displacement_max").get<double>();
  EXPECT_NEAR(rod.at("tip_displacement_max").get<double>(), peak, 1e-3 * peak);
  const std::vector<std::string> lines = ReadLines(dir.path() / "history.csv");
  ASSERT_EQ(lines.size(), 1u + 101u);
  EXPECT_EQ(lines[0], "time_s,tip_uy_m");
}

TEST(CosseratCliTest, WarnsThatAverageAccelerationLeavesTheRodsFastModesUndamped) {
  const nlohmann::json json =
      RunJson({"cantilever", "--set", "model.theory=cosserat", "--set", "analysis.type=transient",
               "--set", "analysis.duration=1e-6", "--set", "analysis.time_step=1e-7"});
  EXPECT_EQ(json.at("status"), "ok");
  ASSERT_EQ(json.at("warnings").size(), 1u);
  ExpectContains(json["warnings"][0], "leaves the rod's axial and shear vibrations undamped");
}

TEST(CosseratCliTest, StaticFilesListTheDeformedNodes) {
  const TempDirectory dir;
  const nlohmann::json json =
      RunJson({"cantilever-large-deflection", "--out", dir.path().string()});
  const std::vector<std::string> lines = ReadLines(dir.path() / "deflection.csv");
  ASSERT_EQ(lines.size(), 1u + 51u);
  EXPECT_EQ(lines[0], "x_m,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  EXPECT_EQ(lines[1].rfind("0,0,0,0,0,0,0", 0), 0u) << lines[1];  // the clamp
  // The last row is the tip of the JSON.
  std::vector<double> last;
  std::size_t start = 0;
  for (std::size_t comma; (comma = lines.back().find(',', start)) != std::string::npos;
       start = comma + 1) {
    last.push_back(std::stod(lines.back().substr(start, comma - start)));
  }
  last.push_back(std::stod(lines.back().substr(start)));
  ASSERT_EQ(last.size(), 7u);
  const double uy = Component(json, "tip_displacement", 1);
  EXPECT_NEAR(last[2], uy, 1e-6 * std::abs(uy));
  const double rz = Component(json, "tip_rotation", 2);
  EXPECT_NEAR(last[6], rz, 1e-6 * std::abs(rz));
}

TEST(CosseratCliTest, BucklingIsTheStraightBeamsInEveryTheory) {
  const nlohmann::json linear = RunJson(
      {"cantilever", "--set", "analysis.type=buckling", "--set", "loads.tip_force=[0, 0, 0]"});
  const nlohmann::json rod =
      RunJson({"cantilever", "--set", "analysis.type=buckling", "--set",
               "loads.tip_force=[0, 0, 0]", "--set", "model.theory=cosserat"});
  EXPECT_EQ(rod.at("critical_load_n"), linear.at("critical_load_n"));
  ASSERT_EQ(rod.at("warnings").size(), 1u);
  ExpectContains(rod["warnings"][0], "model.theory = \"cosserat\" does not change a buckling");
}

}  // namespace
}  // namespace cosmems
