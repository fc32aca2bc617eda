// Transient runs of the reference cantilever: release, damping, step load, both paths.
#include "cosmems/analysis/transient_analysis.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::kReferenceLength;

BeamModel<2> Reference() {
  return BeamModel<2>(MakeStructure(StructureKind::kCantilever, kReferenceLength, test::Silicon(),
                                    test::ReferenceSection(), 20, 0));
}

LoadCase TipForce() {
  LoadCase loads;
  loads.points.push_back({kReferenceLength, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  return loads;
}

double Period1() {
  const double ei = test::Silicon().young_modulus * test::ReferenceSection().SecondMomentZ();
  const double rho_a = test::Silicon().density * test::ReferenceSection().Area();
  return 1.0 / test::BendingFrequency(test::FrequencyRoot(1, -1), kReferenceLength, ei, rho_a);
}

double StaticTip() {
  return -1e-7 * kReferenceLength * kReferenceLength * kReferenceLength /
         (3 * test::Silicon().young_modulus * test::ReferenceSection().SecondMomentZ());
}

TransientOptions Release(TimePath path, int modes, double periods, int steps_per_period) {
  TransientOptions o;
  o.duration = periods * Period1();
  o.time_step = Period1() / steps_per_period;
  o.path = path;
  o.modes = modes;
  o.parameters = GeneralizedAlphaParameters::Newmark(0.25, 0.5);
  o.start_static = true;
  o.output_x = kReferenceLength;
  return o;
}

// Release with 4 modes: the tip follows sum_(i<=4) phi_i(tip) cos(w_i t) phi_i^T M d0 of the
// semi-discrete system, computed here from a dense eigen solve. Tolerance as in the modal
// propagator's test: eigen-solver round-off turned into phase.
TEST(TransientAnalysisTest, ModalReleaseFollowsItsModes) {
  const BeamModel<2> model = Reference();
  const TransientResult r = RunTransient(model, TipForce(), Release(TimePath::kModal, 4, 3, 40));
  ASSERT_EQ(r.status, Status::kOk);
  const Eigen::VectorXd d0 =
      BandCholesky(model.Stiffness()).Solve(AssembleLoads(model, TipForce()));
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(model.Stiffness().ToDense(),
                                                                model.Mass(0).ToDense());
  const Eigen::VectorXd q0 = eig.eigenvectors().transpose() * (model.Mass(0) * d0);
  const int tip = model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy);
  const double time_unit = model.units().time;
  for (std::size_t k = 0; k < r.time_s.size(); ++k) {
    double exact = 0.0;
    for (int m = 0; m < 4; ++m) {
      exact += eig.eigenvectors()(tip, m) *
               std::cos(std::sqrt(eig.eigenvalues()[m]) * r.time_s[k] / time_unit) * q0[m];
    }
    ASSERT_NEAR(r.output_m[k], exact * model.units().length, 1e-7 * std::abs(StaticTip()))
        << "t = " << r.time_s[k];
  }
  EXPECT_EQ(r.steps, 120);
}

// With a quality factor Q every mode decays at zeta = 1/(2Q): successive maxima of the
// one-mode release shrink by exp(-2 pi zeta / sqrt(1 - zeta^2)).
TEST(TransientAnalysisTest, QualityFactorSetsTheLogarithmicDecrement) {
  const BeamModel<2> model = Reference();
  TransientOptions o = Release(TimePath::kModal, 1, 10, 2000);
  o.damping = DampingModel::QualityFactor(20.0);
  const TransientResult r = RunTransient(model, TipForce(), o);
  ASSERT_EQ(r.status, Status::kOk);
  std::vector<double> minima;  // the tip starts at its most negative: track the troughs
  for (std::size_t k = 1; k + 1 < r.output_m.size(); ++k) {
    if (r.output_m[k] < r.output_m[k - 1] && r.output_m[k] <= r.output_m[k + 1])
      minima.push_back(r.output_m[k]);
  }
  ASSERT_GE(minima.size(), 8u);
  const double zeta = 1.0 / 40.0;
  const double expected = std::exp(-2 * kPi * zeta / std::sqrt(1 - zeta * zeta));
  // Troughs are sampled at 2000 points a period: a timing error of 1/4000 of a period moves a
  // trough by (2 pi / 4000)^2 / 2 = 1.2e-6 of itself.
  for (std::size_t k = 1; k < minima.size(); ++k)
    EXPECT_NEAR(minima[k] / minima[k - 1], expected, 1e-5);
}

// A suddenly applied tip force from rest: an undamped structure overshoots to twice its static
// deflection at most, and nearly that (mode 1 carries 97 % of the tip's static deflection).
// The full path resolves the modes, the modal path (4 modes + static correction) holds the rest
// statically: they agree on the peak.
TEST(TransientAnalysisTest, StepLoadOvershootsToTwiceTheStaticDeflection) {
  const BeamModel<2> model = Reference();
  TransientOptions o;
  o.duration = 2 * Period1();
  o.time_step = Period1() / 400;
  o.output_x = kReferenceLength;
  o.parameters = GeneralizedAlphaParameters::Newmark(0.25, 0.5);
  const TransientResult full = RunTransient(model, TipForce(), o);
  o.path = TimePath::kModal;
  o.modes = 4;
  const TransientResult modal = RunTransient(model, TipForce(), o);
  ASSERT_EQ(full.status, Status::kOk);
  ASSERT_EQ(modal.status, Status::kOk);
  const double statics = std::abs(StaticTip());
  for (const TransientResult* r : {&full, &modal}) {
    EXPECT_GT(r->max_abs_output, 1.9 * statics);
    EXPECT_LT(r->max_abs_output, 2.0 * statics * (1 + 1e-9));
  }
  EXPECT_NEAR(full.max_abs_output, modal.max_abs_output, 0.01 * statics);
  EXPECT_GT(full.step_time.max_us, 0.0);
  EXPECT_GE(full.step_time.max_us, full.step_time.p99_us);
  EXPECT_GE(full.step_time.p99_us, full.step_time.median_us);
}

// Central difference just above its stability limit 2 / w_max (w_max from a dense eigen solve
// here) grows geometrically but stays finite for many steps: the run must end as diverged,
// not report ok with a deflection of 1e200 m; just below the limit it runs to the end.
TEST(TransientAnalysisTest, ExplicitStepAboveItsLimitIsReportedAsDiverged) {
  const BeamModel<2> model = Reference();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(model.Stiffness().ToDense(),
                                                                model.Mass(0).ToDense());
  const double critical = 2.0 / std::sqrt(eig.eigenvalues().maxCoeff()) * model.units().time;
  TransientOptions o;
  o.parameters = GeneralizedAlphaParameters::CentralDifference();
  o.output_x = kReferenceLength;
  o.time_step = 1.01 * critical;
  o.duration = 20000 * o.time_step;
  const TransientResult unstable = RunTransient(model, TipForce(), o);
  EXPECT_EQ(unstable.status, Status::kDiverged);
  EXPECT_LT(unstable.steps, 20000);
  o.time_step = 0.99 * critical;
  o.duration = 20000 * o.time_step;
  const TransientResult stable = RunTransient(model, TipForce(), o);
  EXPECT_EQ(stable.status, Status::kOk);
  EXPECT_EQ(stable.steps, 20000);
  EXPECT_LT(stable.max_abs_output, 3 * std::abs(StaticTip()));
}

TEST(TransientAnalysisTest, RejectsInconsistentOptionsNamingTheKey) {
  const BeamModel<2> model = Reference();
  TransientOptions o = Release(TimePath::kModal, 0, 1, 10);
  try {
    RunTransient(model, TipForce(), o);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("model.modes = 0"), std::string::npos) << e.what();
  }
  o = Release(TimePath::kNewmarkFamily, 0, 1, 10);
  o.time_step = 2 * o.duration;
  EXPECT_THROW(RunTransient(model, TipForce(), o), std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
