// The geometric stiffness against the exact solutions of the beam under a constant axial force,
// EI w'''' - N w'' - rho A w^2 w = 0, solved in the test (characteristic determinant, bisection)
// and the second-order closed form of a cantilever's tip deflection under tension or
// compression; the element's K_NL against the textbook matrix.
#include <gtest/gtest.h>

#include "prestressed_beam_exact.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::Eiz;
using test::kReferenceLength;
using test::RhoA;

double Frequency(StructureKind kind, double tau, int elements, int order, int mode) {
  BeamDescription beam = MakeStructure(kind, kReferenceLength, test::Silicon(),
                                       test::ReferenceSection(), elements, order);
  beam.axial_load = tau * Eiz() / (kReferenceLength * kReferenceLength);
  ModalOptions options;
  options.count = mode;
  const ModalResult result = SolveModal(BeamModel<2>(beam), options);
  EXPECT_EQ(result.status, Status::kOk);
  return result.modes.at(mode - 1).frequency_hz;
}

double ExactFrequency(StructureKind kind, double tau, int mode) {
  return std::sqrt(test::ExactPrestressedLambda(kind == StructureKind::kBridge, tau, mode)) /
         (2 * kPi * kReferenceLength * kReferenceLength) * std::sqrt(Eiz() / RhoA());
}

struct Prestress {
  StructureKind kind;
  double tau;  // N L^2 / EI: cantilever buckles at pi^2/4 = 2.47, the bridge at 4 pi^2 = 39.5
};

class PrestressedFrequencyTest : public ::testing::TestWithParam<Prestress> {};

// Under an axial force the exact mode is no longer a power series in w about the cubic, so the
// error falls as h^4 at every series order (the frequency terms G_j still cut the error of
// modes 2 and 3 by 3-6x). Asserted: the observed order between 20 and 40 elements within 0.3
// of 4 for modes 1-3, and 40 elements within 2e-5 of the exact frequency (measured 5.7e-6 at
// the string-like tau = 400, below 1e-7 for |tau| <= 30).
TEST_P(PrestressedFrequencyTest, ConvergesAsH4ToTheExactSolution) {
  const auto [kind, tau] = GetParam();
  for (int mode = 1; mode <= 3; ++mode) {
    const double exact = ExactFrequency(kind, tau, mode);
    const double e20 = std::abs(Frequency(kind, tau, 20, 1, mode) / exact - 1);
    const double e40 = std::abs(Frequency(kind, tau, 40, 1, mode) / exact - 1);
    EXPECT_LT(e40, 2e-5) << "mode " << mode;
    EXPECT_NEAR(std::log2(e20 / e40), 4.0, 0.3) << "mode " << mode << ": " << e20 << " " << e40;
  }
}

INSTANTIATE_TEST_SUITE_P(Loads, PrestressedFrequencyTest,
                         ::testing::Values(Prestress{StructureKind::kCantilever, -2.0},
                                           Prestress{StructureKind::kCantilever, 30.0},
                                           Prestress{StructureKind::kBridge, -30.0},
                                           Prestress{StructureKind::kBridge, 10.0},
                                           Prestress{StructureKind::kBridge, 400.0}));

TEST(AxialLoadTest, TensionStiffensAndCompressionSoftensUnloadedFrequency) {
  const double f0 = Frequency(StructureKind::kBridge, 0.0, 20, 1, 1);
  EXPECT_GT(Frequency(StructureKind::kBridge, 10.0, 20, 1, 1), f0);
  EXPECT_LT(Frequency(StructureKind::kBridge, -10.0, 20, 1, 1), f0);
}

// Second-order theory of a cantilever with a dead axial force N and a tip force P:
// delta = P / (N k) (k L - tanh k L), k^2 = N / EI, and (tan k L - k L) in compression. Hermite
// elements are no longer nodally exact under N (the exact field is not cubic): 40 elements leave
// 4e-7 (measured 1.1e-7 at tau = 50), converging as h^4.
TEST(AxialLoadTest, CantileverTipDeflectionMatchesSecondOrderTheory) {
  const double p = -1e-7;
  for (double tau : {-2.0, 5.0, 50.0}) {
    const double n = tau * Eiz() / (kReferenceLength * kReferenceLength);
    const double kl = std::sqrt(std::abs(tau));
    const double exact = tau > 0 ? p * kReferenceLength / (n * kl) * (kl - std::tanh(kl))
                                 : p * kReferenceLength / (-n * kl) * (std::tan(kl) - kl);
    for (int dim : {2, 3}) {
      BeamDescription beam = MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                           test::Silicon(), test::ReferenceSection(), 40, 1);
      beam.axial_load = n;
      LoadCase loads;
      loads.points.push_back({kReferenceLength, {0, p, 0}, Eigen::Vector3d::Zero()});
      double tip = 0;
      if (dim == 2) {
        const BeamModel<2> model(beam);
        tip = BeamField<2>(model, SolveStatic(model, loads).displacement).At(kReferenceLength)[1];
      } else {
        const BeamModel<3> model(beam);
        tip = BeamField<3>(model, SolveStatic(model, loads).displacement).At(kReferenceLength)[1];
      }
      EXPECT_NEAR(tip, exact, 4e-7 * std::abs(exact)) << "tau " << tau << " dim " << dim;
    }
  }
}

TEST(AxialLoadTest, CompressionBeyondBucklingIsReportedNotSolved) {
  BeamDescription beam = MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                       test::Silicon(), test::ReferenceSection(), 10, 1);
  beam.axial_load = -3.0 * Eiz() / (kReferenceLength * kReferenceLength);  // beyond pi^2/4
  LoadCase loads;
  loads.points.push_back({kReferenceLength, {0, -1e-7, 0}, Eigen::Vector3d::Zero()});
  EXPECT_EQ(SolveStatic(BeamModel<2>(beam), loads).status, Status::kNotPositiveDefinite);
}

// The classical consistent geometric stiffness of a Hermite element, N / (30 l) times
// [36, 3l, -36, 3l; 3l, 4l^2, -3l, -l^2; -36, -3l, 36, -3l; 3l, -l^2, -3l, 4l^2].
TEST(AxialLoadTest, ElementGeometricStiffnessIsTheTextbookMatrix) {
  const FrameBases bases(2);
  ElementProperties p;
  p.length = 0.3;
  p.young_modulus = 2.0;
  p.area = 1.5;
  p.density = 1.0;
  p.second_moment_z = 0.7;
  const FrameElement<2>::Matrix g = FrameElement<2>(p).Geometric(bases, 0);
  const double l = p.length;
  Eigen::Matrix4d textbook;
  textbook << 36, 3 * l, -36, 3 * l, 3 * l, 4 * l * l, -3 * l, -l * l, -36, -3 * l, 36, -3 * l,
      3 * l, -l * l, -3 * l, 4 * l * l;
  textbook /= 30 * l;
  const int idx[4] = {1, 2, 4, 5};  // uy, rz at both nodes
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) EXPECT_NEAR(g(idx[a], idx[b]), textbook(a, b), 1e-13);
  }
  EXPECT_EQ(g.row(0).norm() + g.row(3).norm(), 0.0);  // the axial field takes none
}

}  // namespace
}  // namespace cosmems
