// Exact modal propagation against closed-form oscillator responses, and the modal model of the
// reference cantilever against the full semi-discrete system.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/modal_model.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

ModalPropagator Oscillator(double omega, double zeta, double dt) {
  return ModalPropagator({{omega, zeta}}, Eigen::MatrixXd::Ones(1, 1), Eigen::MatrixXd::Ones(1, 1),
                         Eigen::MatrixXd(), dt);
}

using test::Vec;

// Damped free vibration from q = 1: q = e^(-z w t) (cos(wd t) + z w / wd sin(wd t)). The step
// is 1/3 of a period: exact propagation does not care.
TEST(ModalPropagatorTest, FreeVibrationIsExactAtAnyStep) {
  const double w = 5.0, z = 0.05, dt = 0.4;
  ModalPropagator p = Oscillator(w, z, dt);
  p.Initialize(Vec(1.0), Vec(0.0), Vec(0.0));
  const double wd = w * std::sqrt(1 - z * z);
  for (int i = 1; i <= 200; ++i) {
    ASSERT_EQ(p.Step(Vec(0.0)), Status::kOk);
    const double t = i * dt;
    const double exact = std::exp(-z * w * t) * (std::cos(wd * t) + z * w / wd * std::sin(wd * t));
    ASSERT_NEAR(p.DisplacementAt(0), exact, 1e-12) << "t = " << t;
  }
}

// An undamped oscillator under a ramp g = t from rest: q = (t - sin(w t)/w) / w^2, exact for a
// load linear over each step.
TEST(ModalPropagatorTest, RampLoadIsExact) {
  const double w = 3.0, dt = 0.7;
  ModalPropagator p = Oscillator(w, 0.0, dt);
  p.Initialize(Vec(0.0), Vec(0.0), Vec(0.0));
  for (int i = 1; i <= 100; ++i) {
    ASSERT_EQ(p.Step(Vec(i * dt)), Status::kOk);
    const double t = i * dt;
    ASSERT_NEAR(p.DisplacementAt(0), (t - std::sin(w * t) / w) / (w * w), 1e-12 * t);
  }
}

// A sine load is interpolated linearly over a step: second order in dt.
TEST(ModalPropagatorTest, SineLoadConvergesAtSecondOrder) {
  const double w = 2 * kPi;
  const double exact = (std::sin(1.0) - std::sin(w) / w) / (w * w - 1);
  std::vector<double> errors;
  for (int steps : {50, 100, 200}) {
    const double dt = 1.0 / steps;
    ModalPropagator p = Oscillator(w, 0.0, dt);
    p.Initialize(Vec(0.0), Vec(0.0), Vec(0.0));
    for (int i = 1; i <= steps; ++i) ASSERT_EQ(p.Step(Vec(std::sin(i * dt))), Status::kOk);
    errors.push_back(std::abs(p.DisplacementAt(0) - exact));
  }
  EXPECT_NEAR(std::log2(errors[0] / errors[1]), 2.0, 0.1);
  EXPECT_NEAR(std::log2(errors[1] / errors[2]), 2.0, 0.1);
}

struct ReferenceBeam {
  BeamModel<2> model{MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                   test::Silicon(), test::ReferenceSection(), 20, 0)};
  Eigen::MatrixXd TipForce() const {
    LoadCase loads;
    loads.points.push_back(
        {test::kReferenceLength, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
    return AssembleLoads(model, loads);
  }
  int Tip() const { return model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy); }
};

// A step load with k = 4 modes and the static correction: at every instant the modal path
// equals the exact semi-discrete response of the first four modes plus the static response of
// the rest, d = sum_(i<=4) phi_i (1 - cos w_i t) phi_i^T f / w_i^2 + R f, computed here from a
// dense eigen solve; and it settles exactly on the static deflection K^-1 f.
TEST(ModalPropagatorTest, StaticCorrectionRestoresTheTruncatedModesStatically) {
  const ReferenceBeam beam;
  const BeamModel<2>& model = beam.model;
  const Eigen::MatrixXd f = beam.TipForce();
  ModalOptions options;
  options.count = 4;
  const ModalModel modal = MakeModalModel(model, SolveModal(model, options), DampingModel{});
  const double period = 2 * kPi / modal.coordinates[0].omega;
  ModalPropagator p(modal.coordinates, modal.shapes, f, modal.ResidualFlexibility(model, f),
                    period / 7);
  const int n = model.FreeDofCount();
  p.Initialize(Eigen::VectorXd::Zero(4), Eigen::VectorXd::Zero(4), Vec(1.0));
  // A physical state in place of the modal one is refused by name.
  EXPECT_THROW(p.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(4), Vec(1.0)),
               std::invalid_argument);

  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(model.Stiffness().ToDense(),
                                                                model.Mass(0).ToDense());
  const Eigen::VectorXd statics = BandCholesky(model.Stiffness()).Solve(f.col(0));
  const int tip = beam.Tip();
  double worst = 0.0;
  for (int i = 1; i <= 70; ++i) {
    ASSERT_EQ(p.Step(Vec(1.0)), Status::kOk);
    double exact = statics[tip];
    for (int m = 0; m < 4; ++m) {
      const double w = std::sqrt(eig.eigenvalues()[m]);
      exact -= eig.eigenvectors()(tip, m) * std::cos(w * p.time()) *
               eig.eigenvectors().col(m).dot(f.col(0)) / (w * w);
    }
    worst = std::max(worst, std::abs(p.DisplacementAt(tip) - exact));
  }
  // Propagation itself is exact (1e-13 against its own modes' closed form); the two eigen
  // solutions differ by ~1e-11 in frequency (the eps * cond(K) floor), which over w_4 t = 2000 rad
  // is a phase error of 2e-8.
  EXPECT_LT(worst, 1e-7 * std::abs(statics[tip]));
}

// The full-order Newmark path and the modal path agree on the resolved modes: releasing the
// static deflection projected on the first six modes (so the full path holds no others),
// average acceleration with 100 steps per period of mode 6 against exact propagation.
TEST(ModalPropagatorTest, FullAndModalPathsAgreeOnTheResolvedModes) {
  const ReferenceBeam beam;
  const BeamModel<2>& model = beam.model;
  const int n = model.FreeDofCount();
  ModalOptions options;
  options.count = 6;
  const ModalModel modal = MakeModalModel(model, SolveModal(model, options), DampingModel{});
  const Eigen::VectorXd statics = BandCholesky(model.Stiffness()).Solve(beam.TipForce().col(0));
  const Eigen::VectorXd d0 = modal.shapes * (modal.shapes.transpose() * (model.Mass(0) * statics));
  const double dt = 2 * kPi / modal.coordinates[5].omega / 100;
  ModalPropagator reduced(modal.coordinates, modal.shapes, Eigen::MatrixXd::Zero(n, 1),
                          Eigen::MatrixXd(), dt);
  reduced.Initialize(modal.Project(model, d0), Eigen::VectorXd::Zero(6), Vec(0.0));
  LinearNewmarkIntegrator full(model.Mass(0), model.Stiffness(), {},
                               GeneralizedAlphaParameters::Newmark(0.25, 0.5), dt);
  ASSERT_EQ(full.Initialize(d0, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)), Status::kOk);
  const int tip = beam.Tip();
  const int steps = static_cast<int>(2 * kPi / modal.coordinates[0].omega / dt);
  double worst = 0.0;
  for (int i = 1; i <= steps; ++i) {
    ASSERT_EQ(reduced.Step(Vec(0.0)), Status::kOk);
    ASSERT_EQ(full.Step(Eigen::VectorXd::Zero(n)), Status::kOk);
    worst = std::max(worst, std::abs(reduced.DisplacementAt(tip) - full.displacement()[tip]));
  }
  // Over one period of mode 1 the Newmark phase error of mode k is (W_k^2 / 12) w_k t: 2e-6 rad
  // for mode 1 and 0.18 rad for mode 6, whose share of the tip deflection is 7e-5; modes 2-5
  // add less than that together. 1e-4 of the amplitude bounds the sum.
  EXPECT_LT(worst, 1e-4 * std::abs(d0[tip]));
}

// A state made of the modes projects back onto its modal coordinates at every series order.
// At order >= 1 the shapes have unit modal mass in the polynomial's sense, not Phi^T M_0 Phi =
// I, so Phi^T M_0 d alone is off by the modes' M_0 masses (3e-4 to 2e-3 here); the least-squares
// projection is exact up to the rounding of the 8 x 8 Gram matrix (1e-12 of the largest
// coordinate).
TEST(ModalPropagatorTest, ProjectionRecoversModalCoordinatesAtEveryOrder) {
  for (int order = 0; order <= 3; ++order) {
    const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                           test::Silicon(), test::ReferenceSection(), 20, order));
    ModalOptions options;
    options.count = 8;
    const ModalModel modal = MakeModalModel(model, SolveModal(model, options), DampingModel{});
    Eigen::VectorXd q(8);
    q << 1.0, -0.5, 0.25, 0.125, -0.0625, 0.03, -0.02, 0.01;
    const Eigen::VectorXd d = modal.shapes * q;
    EXPECT_LT((modal.Project(model, d) - q).cwiseAbs().maxCoeff(), 1e-12) << "order " << order;
    const Eigen::VectorXd plain = modal.shapes.transpose() * (model.Mass(0) * d);
    if (order >= 1) {
      EXPECT_GT((plain - q).cwiseAbs().maxCoeff(), 1e-5) << "order " << order;
    }
  }
}

}  // namespace
}  // namespace cosmems
