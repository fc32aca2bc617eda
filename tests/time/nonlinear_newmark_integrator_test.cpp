// The nonlinear Newton path: a Duffing oscillator against a fine Runge-Kutta reference computed
// in the test, agreement with the linear path when r(d) = 0, and step cutting.
#include "cosmems/time/nonlinear_newmark_integrator.hpp"

#include <gtest/gtest.h>

#include "cosmems/time/linear_newmark_integrator.hpp"
#include "no_force.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

// r(d) = k3 d^3 on one degree of freedom (a hardening spring).
class CubicSpring : public NonlinearForce {
 public:
  CubicSpring(int dof, double k3) : dof_(dof), k3_(k3) {}
  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double x = d[dof_];
    force[dof_] += k3_ * x * x * x;
    tangent.band().Add(dof_, dof_, 3 * k3_ * x * x);
    return std::isfinite(x);
  }

 private:
  int dof_;
  double k3_;
};

using test::NoForce;

using test::Scalar;

using test::Vec;

// x'' + x + 4 x^3 = 0.3 sin(2t) from x = 0.8 at rest, to t = 5, by RK4 with 1e5 steps (error
// ~1e-16 of the step's h^4): the reference.
double DuffingReference() {
  auto rhs = [](double t, const Eigen::Vector2d& y) {
    return Eigen::Vector2d(y[1], -y[0] - 4 * y[0] * y[0] * y[0] + 0.3 * std::sin(2 * t));
  };
  Eigen::Vector2d y(0.8, 0.0);
  const int steps = 100000;
  const double h = 5.0 / steps;
  for (int i = 0; i < steps; ++i) {
    const double t = i * h;
    const Eigen::Vector2d k1 = rhs(t, y), k2 = rhs(t + h / 2, y + h / 2 * k1),
                          k3 = rhs(t + h / 2, y + h / 2 * k2), k4 = rhs(t + h, y + h * k3);
    y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return y[0];
}

double Duffing(GeneralizedAlphaParameters p, int steps, NewtonOptions options = {},
               int* cuts = nullptr) {
  const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(1.0);
  CubicSpring spring(0, 4.0);
  const double dt = 5.0 / steps;
  NonlinearNewmarkIntegrator integrator(m, k, {}, spring, p, dt, options);
  EXPECT_EQ(integrator.Initialize(Vec(0.8), Vec(0.0), Vec(0.0)), Status::kOk);
  for (int i = 1; i <= steps; ++i) {
    EXPECT_EQ(integrator.Step(Vec(0.3 * std::sin(2 * i * dt))), Status::kOk);
    if (cuts != nullptr) *cuts += integrator.last_stats().cuts;
  }
  return integrator.displacement()[0];
}

TEST(NonlinearNewmarkIntegratorTest, DuffingOscillatorConvergesAtSecondOrder) {
  const double reference = DuffingReference();
  for (auto p :
       {GeneralizedAlphaParameters::Newmark(0.25, 0.5), GeneralizedAlphaParameters::Hht(0.05),
        GeneralizedAlphaParameters::FromSpectralRadius(0.8)}) {
    const double e1 = std::abs(Duffing(p, 1000) - reference);
    const double e2 = std::abs(Duffing(p, 2000) - reference);
    const double e3 = std::abs(Duffing(p, 4000) - reference);
    EXPECT_NEAR(std::log2(e1 / e2), 2.0, 0.15);
    EXPECT_NEAR(std::log2(e2 / e3), 2.0, 0.15);
    EXPECT_LT(e3, 1e-4);
  }
}

// Newton limited to 2 iterations cannot finish a coarse step of the strongly nonlinear
// oscillator: the step is cut, and the answer is still the converged one.
TEST(NonlinearNewmarkIntegratorTest, FailedStepsAreCutAndStillConverge) {
  NewtonOptions tight;
  tight.max_iterations = 2;
  int cuts = 0;
  const auto p = GeneralizedAlphaParameters::Newmark(0.25, 0.5);
  const double cut = Duffing(p, 20, tight, &cuts);
  EXPECT_GT(cuts, 0);  // measured 305 over 20 steps of dt = 0.25
  // Sub-steps see the load interpolated linearly across the coarse step, an O(dt^2) = 1 %
  // change of the forcing: measured 1.4 % of the amplitude off the reference.
  EXPECT_NEAR(cut, DuffingReference(), 0.02 * 0.8);
}

TEST(NonlinearNewmarkIntegratorTest, WithoutNonlinearForceItIsTheLinearPath) {
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 10, 0));
  const int n = model.FreeDofCount();
  LoadCase loads;
  loads.points.push_back(
      {test::kReferenceLength, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  const Eigen::VectorXd f = AssembleLoads(model, loads);
  const auto p = GeneralizedAlphaParameters::FromSpectralRadius(0.7);
  const RayleighDamping damping{0.01, 1e-4};
  NoForce none;
  NonlinearNewmarkIntegrator nonlinear(model.Mass(0), model.Stiffness(), damping, none, p, 0.05);
  LinearNewmarkIntegrator linear(model.Mass(0), model.Stiffness(), damping, p, 0.05);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  ASSERT_EQ(nonlinear.Initialize(zero, zero, zero), Status::kOk);
  ASSERT_EQ(linear.Initialize(zero, zero, zero), Status::kOk);
  for (int i = 0; i < 200; ++i) {
    ASSERT_EQ(nonlinear.Step(f), Status::kOk);
    ASSERT_EQ(linear.Step(f), Status::kOk);
  }
  // Newton stops at a relative residual of 1e-10; the two paths agree to that order.
  EXPECT_LT((nonlinear.displacement() - linear.displacement()).norm(),
            1e-9 * linear.displacement().norm());
}

// The stretching microbridge of bench/stretching_step_bench.cpp, ringing after a sudden midspan
// load at dt = T1/20: keeping the tangent's factor while it works reaches the states plain
// Newton reaches (both stop at a relative residual of 1e-10; measured 1e-10 apart after 200
// steps) with fewer factorisations (measured 1.18 a step against 3.0), and the predictor keeps
// Newton near 4 iterations a step (measured 4.1 and 4.0; 5.7 with the old a_n extrapolation).
TEST(NonlinearNewmarkIntegratorTest, KeptFactorReachesPlainNewtonsStatesWithFewerFactorisations) {
  const BeamModel<2> model(MakeStructure(StructureKind::kBridge, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 40, 0));
  StretchingForce<2> force(model);
  LoadCase loads;
  loads.points.push_back(
      {test::kReferenceLength / 2, Eigen::Vector3d(0, -1e-4, 0), Eigen::Vector3d::Zero()});
  const Eigen::VectorXd f = AssembleLoads(model, loads);
  const double dt = 2.3e-6 / 20 / model.units().time;  // f1 = 438 kHz
  const auto p = GeneralizedAlphaParameters::Newmark(0.25, 0.5);
  NewtonOptions plain;
  plain.reuse_contraction = 0.0;
  NonlinearNewmarkIntegrator kept(model.Mass(0), model.Stiffness(), {}, force, p, dt);
  NonlinearNewmarkIntegrator newton(model.Mass(0), model.Stiffness(), {}, force, p, dt, plain);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.FreeDofCount());
  ASSERT_EQ(kept.Initialize(zero, zero, f), Status::kOk);
  ASSERT_EQ(newton.Initialize(zero, zero, f), Status::kOk);
  const int steps = 200;
  int kept_iterations = 0, kept_factorizations = 0, newton_iterations = 0,
      newton_factorizations = 0;
  for (int i = 0; i < steps; ++i) {
    ASSERT_EQ(kept.Step(f), Status::kOk);
    ASSERT_EQ(newton.Step(f), Status::kOk);
    kept_iterations += kept.last_stats().evaluations;
    kept_factorizations += kept.last_stats().factorizations;
    newton_iterations += newton.last_stats().evaluations;
    newton_factorizations += newton.last_stats().factorizations;
  }
  EXPECT_LT((kept.displacement() - newton.displacement()).norm(),
            1e-8 * newton.displacement().norm());
  EXPECT_LT(2 * kept_factorizations, newton_factorizations);
  EXPECT_LT(kept_factorizations, 1.5 * steps);
  EXPECT_LT(kept_iterations, 4.5 * steps);
  EXPECT_LT(newton_iterations, 4.5 * steps);
}

// A force whose contact lets go of the prediction (NonlinearForce::LetsGo) has Newton start from
// the step's start: the Duffing spring moving at its start is first evaluated there, not at
// d_n + h v_n + ..., and the step ends where Newton from the prediction ends it (both to
// Newton's tolerance, 1e-10 of the residual's terms: 1e-9 of the state between them).
TEST(NonlinearNewmarkIntegratorTest, APredictionThatLetsGoStartsNewtonAtTheStepsStart) {
  class Recording : public CubicSpring {
   public:
    explicit Recording(bool lets_go) : CubicSpring(0, 4.0), lets_go_(lets_go) {}
    bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force,
                  ForceTangent& tangent) override {
      if (!std::isfinite(first)) first = d[0];
      return CubicSpring::Evaluate(d, force, tangent);
    }
    void StartStep() override { first = std::nan(""); }
    bool LetsGo(const Eigen::VectorXd&, const Eigen::VectorXd&) const override { return lets_go_; }
    double first = std::nan("");  // the step's first evaluated state

   private:
    bool lets_go_;
  };
  const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(1.0);
  const auto p = GeneralizedAlphaParameters::FromSpectralRadius(0.0);
  Recording keeps(false), lets_go(true);
  NonlinearNewmarkIntegrator predicted(m, k, {}, keeps, p, 0.1), started(m, k, {}, lets_go, p, 0.1);
  for (NonlinearNewmarkIntegrator* integrator : {&predicted, &started}) {
    ASSERT_EQ(integrator->Initialize(Vec(0.8), Vec(0.5), Vec(0.0)), Status::kOk);
    ASSERT_EQ(integrator->Step(Vec(0.0)), Status::kOk);
  }
  EXPECT_EQ(lets_go.first, 0.8);
  EXPECT_GT(keeps.first, 0.8 + 0.01);  // moved on by about h v = 0.05 less the deceleration
  EXPECT_NEAR(started.displacement()[0], predicted.displacement()[0], 1e-9);
}

TEST(NonlinearNewmarkIntegratorTest, RefusesAReuseContractionOutsideZeroToOne) {
  const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(1.0);
  CubicSpring spring(0, 4.0);
  for (double bad : {-0.1, 1.0, std::nan("")}) {
    NewtonOptions options;
    options.reuse_contraction = bad;
    EXPECT_THROW(
        NonlinearNewmarkIntegrator(m, k, {}, spring, GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                   0.1, options),
        std::invalid_argument)
        << bad;
  }
}

TEST(NonlinearNewmarkIntegratorTest, AForceOutsideItsDomainFailsTheStepAndKeepsTheState) {
  class Refusing : public NonlinearForce {
   public:
    bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd&, ForceTangent&) override {
      return d[0] < 0.5;  // e.g. a gap closed beyond its tolerance
    }
  } refusing;
  const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(1.0);
  NonlinearNewmarkIntegrator integrator(m, k, {}, refusing,
                                        GeneralizedAlphaParameters::Newmark(0.25, 0.5), 0.1);
  ASSERT_EQ(integrator.Initialize(Vec(0.0), Vec(0.0), Vec(0.0)), Status::kOk);
  Status status = Status::kOk;
  int steps = 0;
  while (status == Status::kOk && steps < 1000) {
    status = integrator.Step(Vec(2.0));  // drives d toward 2, past the domain's edge at 0.5
    ++steps;
  }
  EXPECT_EQ(status, Status::kNonFinite);
  EXPECT_LT(integrator.displacement()[0], 0.5);
  EXPECT_TRUE(integrator.displacement().allFinite());
}

}  // namespace
}  // namespace cosmems
