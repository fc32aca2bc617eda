// Damping as scenes declare it: quality factor and Rayleigh, and their conversions.
#include "cosmems/time/damping_model.hpp"

#include <gtest/gtest.h>

namespace cosmems {
namespace {

// zeta(w) = alpha / (2 w) + beta w / 2 evaluated independently of the library's formula.
double Zeta(RayleighDamping r, double w) { return r.mass / (2 * w) + r.stiffness * w / 2; }

TEST(DampingModelTest, QualityFactorDampsTheTwoReferenceModesExactly) {
  const double q = 50.0, w1 = 4.3e5, w2 = 2.7e6;
  const RayleighDamping r = RayleighDamping::FromQualityFactor(q, w1, w2);
  EXPECT_NEAR(Zeta(r, w1), 0.5 / q, 1e-15);
  EXPECT_NEAR(Zeta(r, w2), 0.5 / q, 1e-15);
  EXPECT_LT(Zeta(r, std::sqrt(w1 * w2)), 0.5 / q);  // modes between are damped less
  EXPECT_EQ(DampingModel::QualityFactor(q).ModalRatio(123.0), 0.5 / q);
}

TEST(DampingModelTest, RayleighRatioAndInternalUnits) {
  const DampingModel d = DampingModel::Rayleigh(1e3, 2e-9);
  EXPECT_DOUBLE_EQ(d.ModalRatio(4e5), Zeta({1e3, 2e-9}, 4e5));
  UnitSystem units;
  units.time = 3e-6;
  // alpha [1/s] times the time unit and beta [s] over it keep zeta(w) invariant.
  const RayleighDamping internal = d.ForFullModel(1.0, 2.0, units);
  EXPECT_NEAR(Zeta(internal, 4e5 * units.time), d.ModalRatio(4e5), 1e-15);
}

TEST(DampingModelTest, RejectsNonPhysicalValuesNamingTheKey) {
  try {
    DampingModel::QualityFactor(-1.0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("effects.damping.quality_factor = -1"), std::string::npos);
  }
  EXPECT_THROW(DampingModel::Rayleigh(-1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(DampingModel::Rayleigh(0.0, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
