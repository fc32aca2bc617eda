// NewtonDriver's convergence at the residual's rounding floor, on a scheme written here whose
// floor lies above the tolerance (as a fine mesh's K d does): the solve ends there, the bound is
// formed once a solve, and the factor serves the next solve.
#include "cosmems/time/newton_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cosmems {
namespace newton_driver_test {

// a x = b on one unknown, its residual carrying an error of kFloor of the reference, of
// alternating sign, at every evaluation (the rounding of products that do not cancel exactly):
// no iteration takes the residual below it, and the corrections it drives stay far above the
// increment test's. RoundOff() bounds it by twice that.
class FloorScheme : public PlainNewtonScheme {
 public:
  explicit FloorScheme(double b) : b_(b) {}
  void SetLoad(double b) { b_ = b; }
  double x() const { return x_; }
  int round_offs() const { return round_offs_; }

  bool Evaluate(NewtonResidual& out) {
    out.reference = std::abs(kA * x_) + std::abs(b_);
    sign_ = -sign_;
    residual_ = kA * x_ - b_ + sign_ * kFloor * out.reference;
    out.norm = std::abs(residual_);
    reference_ = out.reference;
    return true;
  }
  double RoundOff() {
    ++round_offs_;
    return 2.0 * kFloor * reference_;
  }
  Status SolveKept() {
    correction_ = residual_ / kA;
    return Status::kOk;
  }
  NewtonFactor Factor(double /*shift*/) {
    NewtonFactor out;
    out.reusable = true;
    out.status = SolveKept();
    return out;
  }
  NewtonCorrection Update() {
    x_ -= correction_;
    NewtonCorrection out;
    out.size = std::abs(correction_);
    out.iterate = std::abs(x_);
    return out;
  }
  Status Finish() { return Status::kOk; }

 private:
  static constexpr double kA = 3.0;
  static constexpr double kFloor = 1e-8;  // of the reference: above residual_tolerance (1e-10)
  double b_, x_ = 0.0, residual_ = 0.0, correction_ = 0.0, reference_ = 0.0, sign_ = 1.0;
  int round_offs_ = 0;
};

}  // namespace newton_driver_test

using newton_driver_test::FloorScheme;

TEST(NewtonDriverTest, ASolveEndsAtTheRoundingFloorAndKeepsItsFactor) {
  NewtonDriver driver;
  FloorScheme scheme(1.0);
  ASSERT_EQ(driver.Solve(scheme, 1.0), Status::kOk);
  EXPECT_NEAR(scheme.x(), 1.0 / 3.0, 1e-7);  // the floor's error, 2e-8 / 3
  // One correction, then the floor: no second, unproductive solve.
  EXPECT_EQ(driver.stats().evaluations, 2);
  EXPECT_EQ(driver.stats().factorizations, 1);
  EXPECT_EQ(scheme.round_offs(), 1);
  // The next solve (a new load, the same matrix) takes the kept factor: a solve stopped by the
  // floor, not by its factor, leaves the factor trusted.
  scheme.SetLoad(2.0);
  ASSERT_EQ(driver.Solve(scheme, 1.0), Status::kOk);
  EXPECT_NEAR(scheme.x(), 2.0 / 3.0, 1e-7);
  EXPECT_EQ(driver.stats().evaluations, 4);
  EXPECT_EQ(driver.stats().factorizations, 1);
  EXPECT_EQ(scheme.round_offs(), 2);
}

// Without a bound (PlainNewtonScheme's 0) the floor ends nothing: the noise it drives keeps the
// corrections above the increment test's, and the solve fails rather than stop at an unproven
// state.
TEST(NewtonDriverTest, WithoutARoundingBoundTheFloorEndsNothing) {
  NewtonDriver driver;
  struct NoBound : FloorScheme {
    using FloorScheme::FloorScheme;
    double RoundOff() { return 0.0; }
  } scheme(1.0);
  EXPECT_EQ(driver.Solve(scheme, 1.0), Status::kNotConverged);
  EXPECT_EQ(driver.stats().evaluations, driver.options().max_iterations);
}

}  // namespace cosmems
