// The Newmark family on a single-degree-of-freedom oscillator (a 1 x 1 band system) against
// its closed-form algorithmic properties, and on the reference cantilever against modal
// superposition of the same semi-discrete system.
#include "cosmems/time/linear_newmark_integrator.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <deque>
#include <limits>

#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::Scalar;

using test::Vec;

// Free vibration of q'' + w^2 q = 0 from q = 1; the period is measured from the upward zero
// crossings (linearly interpolated) over 60 cycles.
double MeasuredPeriod(GeneralizedAlphaParameters p, double omega, double dt) {
  const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(omega * omega);
  LinearNewmarkIntegrator integrator(m, k, {}, p, dt);
  EXPECT_EQ(integrator.Initialize(Vec(1.0), Vec(0.0), Vec(0.0)), Status::kOk);
  std::vector<double> crossings;
  double previous = 1.0;
  while (crossings.size() < 61) {
    EXPECT_EQ(integrator.Step(Vec(0.0)), Status::kOk);
    const double q = integrator.displacement()[0];
    if (previous < 0.0 && q >= 0.0) {
      crossings.push_back(integrator.time() - dt * q / (q - previous));
    }
    previous = q;
  }
  return (crossings.back() - crossings.front()) / 60.0;
}

// Newmark with gamma = 1/2 has a unit-modulus amplification pair e^(+-i w_bar dt) with
// cos(w_bar dt) = (1 - (1/2 - beta) W^2) / (1 + beta W^2), W = w dt.
TEST(LinearNewmarkIntegratorTest, PeriodMatchesTheAlgorithmicPeriodOfEachMember) {
  const double omega = 2.0 * kPi;  // period 1
  for (double beta : {0.25, 1.0 / 6.0, 1.0 / 12.0, 0.0}) {
    for (double w_dt : {0.1, 0.5, 1.0}) {
      const double dt = w_dt / omega;
      const double c = (1.0 - (0.5 - beta) * w_dt * w_dt) / (1.0 + beta * w_dt * w_dt);
      const double expected = 2.0 * kPi / (std::acos(c) / dt);
      const auto p = GeneralizedAlphaParameters::Newmark(beta, 0.5);
      // Interpolated crossings carry an O(dt^2) error at each end, averaged over 60 cycles.
      EXPECT_NEAR(MeasuredPeriod(p, omega, dt), expected, 2e-3 * dt)
          << "beta " << beta << " W " << w_dt;
    }
  }
}

TEST(LinearNewmarkIntegratorTest, AverageAccelerationConservesEnergy) {
  const double omega = 3.0, dt = 0.37;  // a coarse step: energy is conserved regardless
  const SymmetricBandMatrix m = Scalar(2.0), k = Scalar(2.0 * omega * omega);
  LinearNewmarkIntegrator integrator(m, k, {}, GeneralizedAlphaParameters::Newmark(0.25, 0.5), dt);
  ASSERT_EQ(integrator.Initialize(Vec(0.3), Vec(-1.1), Vec(0.0)), Status::kOk);
  auto energy = [&] {
    const double d = integrator.displacement()[0], v = integrator.velocity()[0];
    return 0.5 * 2.0 * v * v + 0.5 * 2.0 * omega * omega * d * d;
  };
  const double e0 = energy();
  for (int i = 0; i < 10000; ++i) {
    ASSERT_EQ(integrator.Step(Vec(0.0)), Status::kOk);
    // Round-off accumulates as a random walk: 1e-12 relative after 1e4 steps.
    ASSERT_NEAR(energy(), e0, 1e-12 * e0) << "step " << i;
  }
}

// The 3 x 3 amplification matrix of (d, v, a) built column by column from unit states; its
// spectral radius at W = w dt -> infinity is (1 - alpha)/(1 + alpha) for HHT and rho_inf for
// generalised-alpha. The matrix is taken in the balanced variables (W^2 d, W v, a) (dt = 1):
// a similarity, so the same eigenvalues, without entries spanning 1e-10 ... 1e10.
double SpectralRadius(GeneralizedAlphaParameters p, double w_dt) {
  const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(w_dt * w_dt);
  LinearNewmarkIntegrator integrator(m, k, {}, p, 1.0);
  const Eigen::Vector3d scale(w_dt * w_dt, w_dt, 1.0);
  Eigen::Matrix3d a;
  for (int c = 0; c < 3; ++c) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(c).cwiseQuotient(scale);
    integrator.SetState(Vec(e[0]), Vec(e[1]), Vec(e[2]), Vec(0.0));
    EXPECT_EQ(integrator.Step(Vec(0.0)), Status::kOk);
    a.col(c) << integrator.displacement()[0], integrator.velocity()[0],
        integrator.acceleration()[0];
    a.col(c) = a.col(c).cwiseProduct(scale).eval();
  }
  return a.eigenvalues().cwiseAbs().maxCoeff();
}

TEST(LinearNewmarkIntegratorTest, SpectralRadiiMatchTheory) {
  // HHT's roots at infinity are simple: rho(W) approaches its limit as W^-2 (measured 2e-8
  // at W = 1e4 for alpha = 0.1, 1.5e-6 for alpha = 0.3).
  for (double alpha : {0.0, 0.1, 0.3}) {
    EXPECT_NEAR(SpectralRadius(GeneralizedAlphaParameters::Hht(alpha), 1e4),
                (1 - alpha) / (1 + alpha), 1e-5)
        << "HHT alpha " << alpha;
  }
  // Generalised-alpha's optimal parameters make -rho_inf a triple root at infinity, so
  // rho(W) - rho_inf falls as W^(-2/3); Richardson extrapolation over W and 8 W removes that
  // term (8^(-2/3) = 1/4), leaving O(W^(-4/3)) = 1e-4 at W = 1e3.
  for (double rho : {0.0, 0.5, 0.8, 1.0}) {
    const auto p = GeneralizedAlphaParameters::FromSpectralRadius(rho);
    const double limit = (4 * SpectralRadius(p, 8e3) - SpectralRadius(p, 1e3)) / 3;
    EXPECT_NEAR(limit, rho, 2e-4) << "rho_inf " << rho;
  }
  // Low frequencies are barely touched: second-order accurate dissipation.
  EXPECT_GT(SpectralRadius(GeneralizedAlphaParameters::FromSpectralRadius(0.5), 0.01), 1 - 1e-6);
}

// The error at t = 1 of q'' + 4 pi^2 q = sin(t) from rest, against the closed form
// q = (sin t - sin(w t) / w) / (w^2 - 1), halves the step twice.
TEST(LinearNewmarkIntegratorTest, SecondOrderConvergenceInTimeStep) {
  const double w = 2.0 * kPi;
  const double exact = (std::sin(1.0) - std::sin(w) / w) / (w * w - 1.0);
  for (auto p :
       {GeneralizedAlphaParameters::Newmark(0.25, 0.5), GeneralizedAlphaParameters::Hht(0.1),
        GeneralizedAlphaParameters::FromSpectralRadius(0.6)}) {
    std::vector<double> errors;
    for (int steps : {200, 400, 800}) {
      const double dt = 1.0 / steps;
      const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(w * w);
      LinearNewmarkIntegrator integrator(m, k, {}, p, dt);
      ASSERT_EQ(integrator.Initialize(Vec(0.0), Vec(0.0), Vec(0.0)), Status::kOk);
      for (int i = 1; i <= steps; ++i)
        ASSERT_EQ(integrator.Step(Vec(std::sin(i * dt))), Status::kOk);
      errors.push_back(std::abs(integrator.displacement()[0] - exact));
    }
    EXPECT_NEAR(std::log2(errors[0] / errors[1]), 2.0, 0.1);
    EXPECT_NEAR(std::log2(errors[1] / errors[2]), 2.0, 0.1);
  }
}

struct Cantilever {
  BeamModel<2> model{MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                   test::Silicon(), test::ReferenceSection(), 10, 0)};
  // A tip load of 0.1 uN.
  Eigen::VectorXd TipLoad() const {
    LoadCase loads;
    loads.points.push_back(
        {test::kReferenceLength, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
    return AssembleLoads(model, loads);
  }
  double OmegaMax() const {
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(model.Stiffness().ToDense(),
                                                                  model.Mass(0).ToDense());
    return std::sqrt(eig.eigenvalues().maxCoeff());
  }
};

// Central difference is stable for w_max dt <= 2 (w_max of the discrete K, M_0, computed
// here by a dense eigen solve): 1 % below it stays bounded, 1 % above it blows up.
TEST(LinearNewmarkIntegratorTest, CentralDifferenceStabilityLimit) {
  const Cantilever beam;
  const double critical = 2.0 / beam.OmegaMax();
  const int n = beam.model.FreeDofCount();
  const Eigen::VectorXd d0 = Eigen::VectorXd::LinSpaced(n, 0.0, 1e-3);
  for (double factor : {0.99, 1.01}) {
    LinearNewmarkIntegrator integrator(beam.model.Mass(0), beam.model.Stiffness(), {},
                                       GeneralizedAlphaParameters::CentralDifference(),
                                       factor * critical);
    ASSERT_EQ(integrator.Initialize(d0, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)),
              Status::kOk);
    double largest = 0.0;
    for (int i = 0; i < 5000; ++i) {
      if (integrator.Step(Eigen::VectorXd::Zero(n)) != Status::kOk) break;
      largest = std::max(largest, integrator.displacement().cwiseAbs().maxCoeff());
    }
    if (factor < 1.0) {
      EXPECT_LT(largest, 10.0 * d0.cwiseAbs().maxCoeff());
    } else {
      EXPECT_GT(largest, 1e6 * d0.cwiseAbs().maxCoeff());
    }
  }
}

// Release of the statically deflected cantilever: the semi-discrete system's exact solution is
// d(t) = sum_i phi_i cos(w_i t) phi_i^T M d0 (all modes, by a dense eigen solve here). Average
// acceleration is time-symmetric and conserves each mode's energy, so from rest it gives
// exactly q_i0 cos(w_bar_i n dt) with the algorithmic frequency cos(w_bar dt) =
// (1 - W^2/4)/(1 + W^2/4): against that the full path must agree to round-off, and against the
// physical frequencies within the phase error of the unresolved modes.
TEST(LinearNewmarkIntegratorTest, ReleaseFollowsModalSuperposition) {
  const Cantilever beam;
  const BeamModel<2>& model = beam.model;
  const int n = model.FreeDofCount();
  const Eigen::VectorXd d0 = BandCholesky(model.Stiffness()).Solve(beam.TipLoad());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(model.Stiffness().ToDense(),
                                                                model.Mass(0).ToDense());
  const Eigen::VectorXd modal0 = eig.eigenvectors().transpose() * (model.Mass(0) * d0);
  const Eigen::VectorXd omega = eig.eigenvalues().cwiseSqrt();
  const int tip = model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy);
  const double dt = 2 * kPi / omega[0] / 400;
  Eigen::VectorXd omega_bar(n);
  for (int m = 0; m < n; ++m) {
    const double w2 = omega[m] * omega[m] * dt * dt;
    omega_bar[m] = std::acos((1 - w2 / 4) / (1 + w2 / 4)) / dt;
  }
  LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {},
                                     GeneralizedAlphaParameters::Newmark(0.25, 0.5), dt);
  ASSERT_EQ(integrator.Initialize(d0, Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)),
            Status::kOk);
  double worst_algorithmic = 0.0, worst_physical = 0.0;
  for (int i = 1; i <= 800; ++i) {
    ASSERT_EQ(integrator.Step(Eigen::VectorXd::Zero(n)), Status::kOk);
    const double t = integrator.time();
    double algorithmic = 0.0, physical = 0.0;
    for (int m = 0; m < n; ++m) {
      algorithmic += eig.eigenvectors()(tip, m) * std::cos(omega_bar[m] * i * dt) * modal0[m];
      physical += eig.eigenvectors()(tip, m) * std::cos(omega[m] * t) * modal0[m];
    }
    worst_algorithmic =
        std::max(worst_algorithmic, std::abs(integrator.displacement()[tip] - algorithmic));
    worst_physical = std::max(worst_physical, std::abs(integrator.displacement()[tip] - physical));
  }
  // Round-off over 800 steps of a system with condition number ~1e8.
  EXPECT_LT(worst_algorithmic, 1e-8 * std::abs(d0[tip]));
  // Mode 1's phase error after two periods is (w dt)^2/12 * w t = 1e-3 of the amplitude; the
  // unresolved modes, 3 % of the tip's static deflection, can be wholly out of phase.
  EXPECT_LT(worst_physical, 0.04 * std::abs(d0[tip]));
}

// The cantilever rung by a tip load under generalised-alpha with Rayleigh damping, so that every
// term of the step enters (f_n, M x_m, K x_k), stepped by each factorisation. The band factor
// makes the products and the updates inside its sweeps; the dense and CHOLMOD factors solve,
// then update. Same equations, different rounding: 200 steps agree to 6e-15 of the largest
// displacement (measured); 1e-12 leaves room for another compiler's rounding.
TEST(LinearNewmarkIntegratorTest, EverySolverTakesTheSameSteps) {
  const Cantilever beam;
  const BeamModel<2>& model = beam.model;
  const int n = model.FreeDofCount();
  const Eigen::VectorXd f = beam.TipLoad();
  const double dt = 2 * kPi / beam.OmegaMax();
  const auto parameters = GeneralizedAlphaParameters::FromSpectralRadius(0.6);
  const RayleighDamping damping{0.01 / dt, 0.01 * dt};
  std::deque<LinearNewmarkIntegrator> runs;  // emplaced in place: a factor does not move
  for (SpdSolverKind kind :
       {SpdSolverKind::kBand, SpdSolverKind::kDense, SpdSolverKind::kCholmod}) {
    runs.emplace_back(model.Mass(0), model.Stiffness(), damping, parameters, dt, kind);
    ASSERT_EQ(runs.back().solver_kind(), kind);
    ASSERT_EQ(runs.back().Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), f),
              Status::kOk);
  }
  double worst = 0.0, largest = 0.0;
  for (int i = 0; i < 200; ++i) {
    for (LinearNewmarkIntegrator& run : runs) ASSERT_EQ(run.Step(f), Status::kOk);
    for (int r = 1; r < 3; ++r) {
      worst =
          std::max(worst, (runs[r].displacement() - runs[0].displacement()).cwiseAbs().maxCoeff());
    }
    largest = std::max(largest, runs[0].displacement().cwiseAbs().maxCoeff());
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(worst, 1e-12 * largest);
}

// Undo() returns to the step's start bit for bit; a load that makes the step non-finite leaves
// the state as it was; and the steps after both are bit for bit those of a run that took
// neither. On the band factor (whose sweeps write the products' vectors as they go) and on the
// dense one.
TEST(LinearNewmarkIntegratorTest, UndoAndAFailedStepLeaveTheStateAsItWas) {
  const Cantilever beam;
  const BeamModel<2>& model = beam.model;
  const int n = model.FreeDofCount();
  const Eigen::VectorXd f = Eigen::VectorXd::Constant(n, 1e-4);
  Eigen::VectorXd poisoned = f;
  poisoned[n / 2] = std::numeric_limits<double>::quiet_NaN();
  const double dt = 2 * kPi / beam.OmegaMax();
  const auto parameters = GeneralizedAlphaParameters::FromSpectralRadius(0.6);
  const RayleighDamping damping{0.01 / dt, 0.01 * dt};
  for (SpdSolverKind kind : {SpdSolverKind::kBand, SpdSolverKind::kDense}) {
    LinearNewmarkIntegrator run(model.Mass(0), model.Stiffness(), damping, parameters, dt, kind),
        reference(model.Mass(0), model.Stiffness(), damping, parameters, dt, kind);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    ASSERT_EQ(run.Initialize(zero, zero, f), Status::kOk);
    ASSERT_EQ(reference.Initialize(zero, zero, f), Status::kOk);
    for (int i = 0; i < 20; ++i) {
      ASSERT_EQ(run.Step(f), Status::kOk);
      ASSERT_EQ(reference.Step(f), Status::kOk);
    }
    const Eigen::VectorXd d = run.displacement(), v = run.velocity(), a = run.acceleration();
    const double t = run.time();
    ASSERT_EQ(run.Step(2.0 * f), Status::kOk);
    run.Undo();
    EXPECT_EQ(run.displacement(), d);
    EXPECT_EQ(run.velocity(), v);
    EXPECT_EQ(run.acceleration(), a);
    EXPECT_EQ(run.time(), t);
    EXPECT_EQ(run.Step(poisoned), Status::kNonFinite);
    EXPECT_EQ(run.displacement(), d);
    EXPECT_EQ(run.velocity(), v);
    EXPECT_EQ(run.acceleration(), a);
    EXPECT_EQ(run.time(), t);
    for (int i = 0; i < 20; ++i) {
      ASSERT_EQ(run.Step(f), Status::kOk);
      ASSERT_EQ(reference.Step(f), Status::kOk);
      ASSERT_EQ(run.displacement(), reference.displacement()) << i;
      ASSERT_EQ(run.velocity(), reference.velocity()) << i;
    }
  }
}

TEST(LinearNewmarkIntegratorTest, RejectsANonPositiveTimeStep) {
  const SymmetricBandMatrix m = Scalar(1.0), k = Scalar(1.0);
  EXPECT_THROW(
      LinearNewmarkIntegrator(m, k, {}, GeneralizedAlphaParameters::Newmark(0.25, 0.5), 0.0),
      std::invalid_argument);
  EXPECT_THROW(GeneralizedAlphaParameters::Newmark(0.6, 0.5), std::invalid_argument);
  EXPECT_THROW(GeneralizedAlphaParameters::Hht(0.5), std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
