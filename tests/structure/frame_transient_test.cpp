// Transients of frames against the exact response of the oracle's dense model (frame_oracle.hpp:
// every mode superposed, written independently of the library) and against the single beam.
//
// At series order 0 the frame's matrices are the oracle's, so what separates the two is the time
// integration alone: modal propagation is exact, and the Newmark family errs by its period
// error and numerical damping on the shuttle's mode and by its handling of the fast modes the
// step excites (each tolerance below says which).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "device_checks.hpp"
#include "test_beams.hpp"
#include "test_frames.hpp"

namespace cosmems {
namespace {

constexpr double kBeam = 100e-6;
constexpr double kForce = 1e-6;  // N along x on the shuttle

struct Flexure {
  StructureDescription structure;
  int shuttle = 2;  // the shuttle's body index
  FrameLoadCase loads;
  double period = 0.0;  // s, of the lowest mode

  explicit Flexure(int elements) : structure(test::FoldedFlexure(kBeam, elements)) {
    structure.series_order = 0;
    loads.points.push_back({-1, shuttle, {kForce, 0, 0}, {0, 0, 0}});
    period = 1.0 / SolveModal(FrameModel(structure)).modes.at(0).frequency_hz;
  }

  // The shuttle's ux among the oracle's reported dofs, and the load there.
  int ShuttleUx() const { return 6 * (static_cast<int>(structure.nodes.size()) + shuttle); }
  Eigen::VectorXd OracleLoads() const {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(ShuttleUx() + 6);
    f[ShuttleUx()] = kForce;
    return f;
  }

  // The oracle's shuttle ux at `times`.
  std::vector<double> Exact(const std::vector<double>& times, int dynamic = 0) const {
    const Eigen::MatrixXd u =
        test::oracle::StepResponse(test::ToOracle(structure), OracleLoads(), times, dynamic);
    std::vector<double> out;
    for (Eigen::Index t = 0; t < u.rows(); ++t) out.push_back(u(t, ShuttleUx()));
    return out;
  }
};

TransientOptions Span(double duration, double time_step) {
  TransientOptions options;
  options.duration = duration;
  options.time_step = time_step;
  return options;
}

// The largest difference of the recorded shuttle ux from the oracle's, over its largest |ux|.
double HistoryError(const Flexure& flexure, const FrameTransientResult& run, int dynamic = 0) {
  const std::vector<double> exact = flexure.Exact(run.run.time_s, dynamic);
  double error = 0.0, peak = 0.0;
  for (std::size_t t = 0; t < exact.size(); ++t) {
    error = std::max(error, std::abs(run.history(static_cast<Eigen::Index>(t), 0) - exact[t]));
    peak = std::max(peak, std::abs(exact[t]));
  }
  return error / peak;
}

TEST(FrameTransientTest, ModalPropagationIsTheTruncatedExpansionWithItsStaticCorrection) {
  const Flexure flexure(4);
  const FrameModel model(flexure.structure);
  TransientOptions options = Span(1.5 * flexure.period, flexure.period / 37);
  options.path = TimePath::kModal;
  options.modes = 6;
  const FrameTransientResult run =
      RunFrameTransient(model, flexure.loads, options, {{-1, flexure.shuttle}});
  ASSERT_EQ(run.run.status, Status::kOk);
  EXPECT_EQ(run.watched_component, 0);  // the load moves the shuttle along x
  ASSERT_EQ(run.history.cols(), 3);
  // Exact propagation of the same six modes with the other modes static: round-off of the
  // eigenvectors and solves (the frame's frequencies match the oracle's to 4e-14).
  EXPECT_LT(HistoryError(flexure, run, 6), 1e-9);
  // Every mode oscillating: the six modes miss the fast modes' ringing about their static
  // share. The beams weigh as much as the shuttle, and their own modes, which the step load
  // excites, ring at a hundredth of the shuttle's motion (measured 9.7e-3).
  EXPECT_LT(HistoryError(flexure, run), 1.5e-2);
  // The step load's response overshoots to twice the static deflection F / k (k the flexure's
  // 24 E I / L^3): within the fast modes' hundredth and the sampling of the peak (37 steps a
  // period: 2e-3).
  const double statics = kForce / FoldedFlexureDesign{}.Stiffness();
  EXPECT_NEAR(run.run.max_abs_output, 2 * statics, 0.02 * 2 * statics);
}

// A comb of 20 fingers on the flexure's shuttle, engaging along x.
CombDrive ShuttleComb(const Flexure& flexure, double dc, double ac = 0.0, double hz = 0.0) {
  CombDrive comb;
  comb.body = flexure.shuttle;
  comb.fingers = 20;
  comb.gap = 2e-6;
  comb.overlap = 10e-6;
  comb.thickness = flexure.structure.bodies[flexure.shuttle].size.y();
  comb.voltage = dc;
  comb.ac_voltage = ac;
  comb.frequency_hz = hz;
  return comb;
}

// A comb at a constant voltage is a step load N eps0 t V^2 / g on its body: the run equals the
// one with that force as the load, to round-off.
TEST(FrameTransientTest, ACombAtAConstantVoltageDrivesAsItsForceAppliedAtRest) {
  const Flexure flexure(4);
  const FrameModel model(flexure.structure);
  const TransientOptions options = Span(1.5 * flexure.period, flexure.period / 37);
  CombDrive comb = ShuttleComb(flexure, 0.0);
  comb.voltage = std::sqrt(kForce / comb.ForcePerVoltSquared());
  const FrameTransientResult loaded =
      RunFrameTransient(model, flexure.loads, options, {{-1, flexure.shuttle}});
  const FrameTransientResult driven = RunFrameTransient(model, {}, options, {{-1, flexure.shuttle}},
                                                        nullptr, CombDriveLoads(model, {comb}));
  ASSERT_EQ(driven.run.status, Status::kOk);
  EXPECT_EQ(driven.watched_component, 0);  // the comb moves the shuttle along x
  ASSERT_EQ(driven.history.rows(), loaded.history.rows());
  const double peak = loaded.history.col(0).cwiseAbs().maxCoeff();
  EXPECT_LT((driven.history - loaded.history).cwiseAbs().maxCoeff(), 1e-12 * peak);
}

// The shuttle driven at its mode's frequency by V = V_dc + V_ac sin(w t), which pushes at w
// with 2 N eps0 t V_dc V_ac / g, against the oracle's steady response of every mode (the six
// lowest damped at the run's ratio 1 / 2Q, the others static, as the run's modal model with its
// static correction): the shuttle's amplitude at w, and the power balance over a period (the
// comb's work, the sum of F dx over the run's steps, against the work of the damping).
// Measured over the last ten of 150 periods, after the start's transient has decayed to
// exp(-2 pi 150 / 2Q) = 8e-5; the Fourier coefficient over whole periods leaves out the mean
// force's offset and the 2w push exactly; the load, linear over each of 400 steps a period, errs
// by (w h)^2 / 12 = 2e-5. 1e-3 asserted for both.
TEST(FrameTransientTest, ACombDrivenAtResonancePutsInWhatDampingTakesOut) {
  const Flexure flexure(4);
  const FrameModel model(flexure.structure);
  const test::oracle::Frame oracle = test::ToOracle(flexure.structure);
  // The shuttle's mode along x (the square beams' out-of-plane mode lies just below it).
  ModalOptions count;
  count.count = 6;
  const FrameModalResult modes = SolveFrameModal(model, count);
  ASSERT_EQ(modes.modal.status, Status::kOk);
  const double period = 1.0 / modes.modal.modes[test::ModeAlong(modes, 0)].frequency_hz;
  const double omega = 2 * kPi / period;
  const double quality = 50.0, dc = 20.0, ac = 1.0;
  const CombDrive comb = ShuttleComb(flexure, dc, ac, 1.0 / period);
  constexpr int kPerPeriod = 400, kPeriods = 150, kMeasured = 10;
  TransientOptions options = Span(kPeriods * period, period / kPerPeriod);
  options.path = TimePath::kModal;
  options.modes = 6;
  options.damping = DampingModel::QualityFactor(quality);
  options.max_history = kPerPeriod * kPeriods + 10;
  const FrameTransientResult run = RunFrameTransient(model, {}, options, {{-1, flexure.shuttle}},
                                                     nullptr, CombDriveLoads(model, {comb}));
  ASSERT_EQ(run.run.status, Status::kOk);
  const Eigen::Index last = run.history.rows() - 1, first = last - kPerPeriod * kMeasured;
  double sine = 0.0, cosine = 0.0, work = 0.0;
  for (Eigen::Index k = first; k < last; ++k) {
    const double t = run.run.time_s[static_cast<std::size_t>(k)];
    const double t1 = run.run.time_s[static_cast<std::size_t>(k) + 1];
    sine += run.history(k, 0) * std::sin(omega * t);
    cosine += run.history(k, 0) * std::cos(omega * t);
    const double force = 0.5 * (comb.Force(comb.Drive().At(t)) + comb.Force(comb.Drive().At(t1)));
    work += force * (run.history(k + 1, 0) - run.history(k, 0));
  }
  const double amplitude = 2.0 * std::hypot(sine, cosine) / static_cast<double>(last - first);
  Eigen::VectorXd push = Eigen::VectorXd::Zero(flexure.ShuttleUx() + 6);
  push[flexure.ShuttleUx()] = 2.0 * comb.ForcePerVoltSquared() * dc * ac;
  const test::oracle::HarmonicResponse steady =
      test::oracle::SteadyHarmonic(oracle, push, omega, 0.5 / quality, 6);
  const double expected = steady.amplitude[flexure.ShuttleUx()];
  std::printf(
      "comb at resonance: amplitude %.6e m against %.6e m (%.1e), work per period %.6e J "
      "against %.6e J (%.1e)\n",
      amplitude, expected, std::abs(amplitude / expected - 1.0), work / kMeasured,
      steady.dissipated, std::abs(work / kMeasured / steady.dissipated - 1.0));
  EXPECT_NEAR(amplitude, expected, 1e-3 * expected);
  EXPECT_NEAR(work / kMeasured, steady.dissipated, 1e-3 * steady.dissipated);
}

TEST(FrameTransientTest, TheNewmarkFamilyFollowsTheExactResponse) {
  const Flexure flexure(4);
  const FrameModel model(flexure.structure);
  struct Case {
    const char* name;
    GeneralizedAlphaParameters parameters;
  };
  // 200 steps per period of the shuttle's mode: the trapezoidal rule's period error (w dt)^2/12
  // = 8e-5 per radian, over the 9.4 radians run, about 8e-4 of the amplitude (measured 7.2e-4);
  // HHT and generalised-alpha add their damping of that mode, of the same order at this step
  // (measured 8.0e-4 and 7.6e-4).
  const Case cases[] = {
      {"average acceleration", GeneralizedAlphaParameters::Newmark(0.25, 0.5)},
      {"hht", GeneralizedAlphaParameters::Hht(0.05)},
      {"generalized-alpha", GeneralizedAlphaParameters::FromSpectralRadius(0.8)},
  };
  for (const Case& c : cases) {
    TransientOptions options = Span(1.5 * flexure.period, flexure.period / 200);
    options.parameters = c.parameters;
    const FrameTransientResult run =
        RunFrameTransient(model, flexure.loads, options, {{-1, flexure.shuttle}});
    ASSERT_EQ(run.run.status, Status::kOk) << c.name;
    EXPECT_LT(HistoryError(flexure, run), 2e-3) << c.name;
  }
}

TEST(FrameTransientTest, CentralDifferenceIsStableBelowItsLimitAndAccurate) {
  const Flexure flexure(2);
  const FrameModel model(flexure.structure);
  const int n = model.FreeDofCount();
  const Eigen::VectorXd highest = test::oracle::Frequencies(test::ToOracle(flexure.structure), n);
  double fastest = 0.0;
  for (int i = 0; i < highest.size(); ++i) {
    if (std::isfinite(highest[i])) fastest = std::max(fastest, highest[i]);
  }
  const double limit = 2.0 / (2 * kPi * fastest);  // dt < 2 / w_max
  TransientOptions options = Span(1.2 * flexure.period, 0.9 * limit);
  options.parameters = GeneralizedAlphaParameters::CentralDifference();
  const FrameTransientResult run =
      RunFrameTransient(model, flexure.loads, options, {{-1, flexure.shuttle}});
  ASSERT_EQ(run.run.status, Status::kOk);
  // So small a step (2400 of them) leaves a period error of (w dt)^2/24 on every mode the
  // oracle rings exactly: measured 7.2e-6.
  EXPECT_LT(HistoryError(flexure, run), 1e-4);
  options.time_step = 1.1 * limit;
  options.duration = 2000 * options.time_step;
  const FrameTransientResult unstable =
      RunFrameTransient(model, flexure.loads, options, {{-1, flexure.shuttle}});
  EXPECT_NE(unstable.run.status, Status::kOk);  // grows until declared diverged, no NaN kept
}

TEST(FrameTransientTest, AReleaseFromTheStaticDeflectionSwingsAboutRest) {
  const Flexure flexure(4);
  const FrameModel model(flexure.structure);
  TransientOptions options = Span(1.5 * flexure.period, flexure.period / 37);
  options.path = TimePath::kModal;
  options.modes = 6;
  options.start_static = true;
  const FrameTransientResult run =
      RunFrameTransient(model, flexure.loads, options, {{-1, flexure.shuttle}, {0, -1}});
  ASSERT_EQ(run.run.status, Status::kOk);
  ASSERT_EQ(run.history.cols(), 6);  // the shuttle, then node 0 (an anchor: still)
  // The six modes swing about rest from their share of the static deflection, and the others
  // are gone from the start (a modal state holds its modes alone): the static deflection less
  // the truncated step response (see StepResponse), to round-off.
  const std::vector<double> step = flexure.Exact(run.run.time_s, 6);
  const double statics = test::oracle::SolveStatic(test::ToOracle(flexure.structure),
                                                   flexure.OracleLoads())[flexure.ShuttleUx()];
  for (Eigen::Index t = 0; t < run.history.rows(); ++t) {
    EXPECT_NEAR(run.history(t, 0), statics - step[static_cast<std::size_t>(t)], 1e-9 * statics)
        << "sample " << t;
  }
  EXPECT_EQ(run.history.col(3).cwiseAbs().maxCoeff(), 0.0);
}

TEST(FrameTransientTest, ANetlistCantileverStepsLikeTheBeam) {
  StructureDescription s;
  test::AddNode(s, "root", {0, 0, 0}, Support::kClamped);
  test::AddNode(s, "tip", {test::kReferenceLength, 0, 0});
  s.members.push_back({0, 1, test::Silicon(), test::ReferenceSection(), 12, {0, 1, 0}});
  const FrameModel frame(s);
  const BeamModel<3> beam(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                        test::Silicon(), test::ReferenceSection(), 12, 1));
  const double period = 1.0 / SolveModal(beam).modes.at(0).frequency_hz;
  FrameLoadCase frame_loads;
  frame_loads.points.push_back({1, -1, {0, -1e-7, 0}, {0, 0, 0}});
  LoadCase beam_loads;
  beam_loads.points.push_back({test::kReferenceLength, {0, -1e-7, 0}, {0, 0, 0}});
  for (const TimePath path : {TimePath::kNewmarkFamily, TimePath::kModal}) {
    TransientOptions options = Span(2 * period, period / 50);
    options.path = path;
    options.modes = 4;
    options.output_x = test::kReferenceLength;
    const FrameTransientResult netlist = RunFrameTransient(frame, frame_loads, options, {{1, -1}});
    const TransientResult chain = RunTransient(beam, beam_loads, options);
    ASSERT_EQ(netlist.run.status, Status::kOk);
    ASSERT_EQ(chain.status, Status::kOk);
    EXPECT_EQ(netlist.watched_component, 1);
    ASSERT_EQ(netlist.run.output_m.size(), chain.output_m.size());
    // The same matrices in another numbering: the same steps to round-off.
    const double peak = chain.max_abs_output;
    for (std::size_t t = 0; t < chain.output_m.size(); ++t) {
      EXPECT_NEAR(netlist.run.output_m[t], chain.output_m[t], 1e-10 * peak) << "sample " << t;
      EXPECT_NEAR(netlist.history(static_cast<Eigen::Index>(t), 1), chain.output_m[t],
                  1e-10 * peak);
    }
  }
}

TEST(FrameTransientTest, BadRecordsAndMechanismsAreReported) {
  const Flexure flexure(2);
  const FrameModel model(flexure.structure);
  const TransientOptions options = Span(1e-6, 1e-8);
  EXPECT_THROW(RunFrameTransient(model, flexure.loads, options, {}), std::invalid_argument);
  EXPECT_THROW(RunFrameTransient(model, flexure.loads, options, {{-1, 7}}), std::invalid_argument);
  EXPECT_THROW(RunFrameTransient(model, flexure.loads, options, {{999, -1}}),
               std::invalid_argument);
  // A beam held at both ends by its translations alone twists freely: a mechanism.
  StructureDescription loose;
  test::AddNode(loose, "a", {0, 0, 0});
  test::AddNode(loose, "b", {kBeam, 0, 0});
  for (StructureNode& node : loose.nodes) node.anchor = {true, true, true, false, false, false};
  test::AddBeam(loose, 0, 1, 2);
  FrameLoadCase push;
  push.points.push_back({1, -1, {0, 1e-6, 0}, {0, 0, 0}});
  EXPECT_EQ(RunFrameTransient(FrameModel(loose), push, options, {{1, -1}}).run.status,
            Status::kNotPositiveDefinite);
}

}  // namespace
}  // namespace cosmems
