// Surface forces on devices: the Casimir and van der Waals pressures under a plate on four beams
// against the roots and folds of its one-degree-of-freedom balance, solved here; the gas film
// under a plate (PlateSqueezeFactors) against Reynolds' equation solved here by finite
// differences, and a plate ringing down on its film against the oscillator integrated here; the
// film's tangents against differences of its force; the gap-adaptive quadrature of a member and
// a plate nearly touching against the energy's gradient and closed forms.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "force_differences.hpp"
#include "plate_on_four_beams.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

// Reynolds' equation for a unit film (mu / h^3 = 1) under the plate a x b moving with unit
// velocity in `shape` (0: translation, 1: tilt about z, lever x; 2: tilt about x, lever z),
// -lap q = 12 v with q = 0 on the edges, by the five-point Laplacian on an n x (n b / a) grid;
// returns the shape factor int q v dA (trapezoid rule, the edges contributing nothing).
double ReynoldsByDifferences(double a, double b, int shape, int n) {
  const int nx = n, nz = static_cast<int>(std::lround(n * b / a));
  const double hx = a / nx, hz = b / nz;
  const int ix = nx - 1, iz = nz - 1;  // interior points
  const auto index = [&](int i, int j) { return (i - 1) * iz + (j - 1); };
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs(ix * iz), velocity(ix * iz);
  for (int i = 1; i <= ix; ++i) {
    for (int j = 1; j <= iz; ++j) {
      const int k = index(i, j);
      const double x = i * hx - 0.5 * a, z = j * hz - 0.5 * b;
      velocity[k] = shape == 0 ? 1.0 : shape == 1 ? x : z;
      rhs[k] = 12.0 * velocity[k];
      entries.emplace_back(k, k, 2.0 / (hx * hx) + 2.0 / (hz * hz));
      if (i > 1) entries.emplace_back(k, index(i - 1, j), -1.0 / (hx * hx));
      if (i < ix) entries.emplace_back(k, index(i + 1, j), -1.0 / (hx * hx));
      if (j > 1) entries.emplace_back(k, index(i, j - 1), -1.0 / (hz * hz));
      if (j < iz) entries.emplace_back(k, index(i, j + 1), -1.0 / (hz * hz));
    }
  }
  Eigen::SparseMatrix<double> laplacian(ix * iz, ix * iz);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  const Eigen::VectorXd q =
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(laplacian).solve(rhs);
  return q.dot(velocity) * hx * hz;
}

// The differences' error falls as h^2, so two grids extrapolate it away (Richardson): what is
// left, ~h^4 at n = 160, is below 1e-6.
double Reynolds(double a, double b, int shape) {
  return (4.0 * ReynoldsByDifferences(a, b, shape, 160) - ReynoldsByDifferences(a, b, shape, 80)) /
         3.0;
}

// The series against the differences: 1e-5 asserted (the extrapolated differences' error).
TEST(PlateSqueezeFactorsTest, MatchReynoldsEquationSolvedByDifferences) {
  for (const double aspect : {1.0, 3.0}) {
    const double a = 1.0, b = aspect;
    const PlateSqueezeFactors f = PlateSqueezeFactors::Of(a, b);
    const double expected[3] = {Reynolds(a, b, 0), Reynolds(a, b, 1), Reynolds(a, b, 2)};
    const double got[3] = {f.translation, f.tilt_z, f.tilt_x};
    for (int shape = 0; shape < 3; ++shape) {
      std::printf("plate 1 x %g, shape %d: series %.9g, differences %.9g\n", aspect, shape,
                  got[shape], expected[shape]);
      EXPECT_NEAR(got[shape], expected[shape], 1e-5 * expected[shape]);
    }
  }
}

// Published values and limits: a square plate's translation 0.4217 a^4 (Blech 1983; Bao 2005's
// beta(1)), and a long plate's film tends to the strip's, a b^3 for translation and a^5 b / 60
// for the tilt across it, short by 0.63 b / a at the plate's ends (1e-3 at 1000 : 1).
TEST(PlateSqueezeFactorsTest, MatchTheSquaresPublishedFactorAndTheStripsLimits) {
  EXPECT_NEAR(PlateSqueezeFactors::Of(1.0, 1.0).translation, 0.4217, 1e-4);
  const PlateSqueezeFactors long_plate = PlateSqueezeFactors::Of(1000.0, 1.0);
  EXPECT_NEAR(long_plate.translation / 1000.0, 1.0 - 0.63e-3, 2e-5);
  EXPECT_NEAR(long_plate.tilt_x * 60.0 / 1000.0, 1.0, 1e-3);
  // Turning the plate swaps the tilts.
  const PlateSqueezeFactors wide = PlateSqueezeFactors::Of(2.0, 1.0);
  const PlateSqueezeFactors deep = PlateSqueezeFactors::Of(1.0, 2.0);
  EXPECT_NEAR(wide.tilt_z, deep.tilt_x, 1e-14 * wide.tilt_z);
  EXPECT_NEAR(wide.translation, deep.translation, 1e-14 * wide.translation);
}

// A thick plate (10 um) on 300 um beams, 0.25 um over the substrate: the beams' faces lie 4 um
// higher, where the pressures are 1e-5 (Casimir, 1/g^4) and 2e-4 (van der Waals, 1/g^3) of the
// plate's, on 24 % of its area. Half of a clamped-guided beam's uniform load reaches its guided
// end (q L^4 / 24 E I = (q L / 2) L^3 / 12 E I), so the plate balances
//   k x = p(g - x) A + p(g + 4 um) A_beams / 2,
// the beams' own deflection (up to 2.4e-3 of their gap) changing their share (5e-5 of the whole
// for van der Waals) by ~2e-7 of the whole.
constexpr double kCasimirGap = 0.25e-6;
constexpr double kBeamsAbove = 4e-6;
constexpr double kBeamsArea = 4 * 300e-6 * 2e-6;
test::PlateOnFourBeams ThickPlate() { return test::PlateOnFourBeams(300e-6, 10e-6); }

// The stable root of that balance below the fold, by bisection on [0, x_max] where the excess is
// negative at 0 and positive at x_max.
template <class Pressure>
double RestUnder(const test::PlateOnFourBeams& device, Pressure pressure, double x_max) {
  const double beams = 0.5 * pressure.Value(kCasimirGap + kBeamsAbove) * kBeamsArea;
  const auto excess = [&](double x) {
    return device.k * x - pressure.Value(kCasimirGap - x) * device.area - beams;
  };
  double lo = 0.0, hi = x_max;
  for (int i = 0; i < 200; ++i) ((excess(0.5 * (lo + hi)) < 0.0) ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

// The device rests where its springs hold the surface force: ~4 % of the gap down, 15 % beyond
// the linear estimate p(g) A / k; the anchors carry the whole pressure. The beams' deflection
// leaves ~2e-7 (van der Waals; Casimir's 1e-8): 1e-6 asserted.
TEST(FrameSurfaceForceTest, CasimirAndVanDerWaalsHoldThePlateWhereItsSpringsBalanceThem) {
  const test::PlateOnFourBeams device = ThickPlate();
  const FrameModel model(device.structure);
  const FrameGapOptions under{kCasimirGap};
  // Casimir's fold lies at g / 5, van der Waals' at g / 4: the stable roots lie below both.
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{}, under);
  const VanDerWaalsPressure vdw_pressure{1e-19};
  FrameGapForce<VanDerWaalsPressure> vdw(model, vdw_pressure, under);
  const double x_casimir = RestUnder(device, CasimirPressure{}, kCasimirGap / 5.0);
  const double x_vdw = RestUnder(device, vdw_pressure, kCasimirGap / 4.0);
  const double beams_casimir = CasimirPressure{}.Value(kCasimirGap + kBeamsAbove) * kBeamsArea;
  const double beams_vdw = vdw_pressure.Value(kCasimirGap + kBeamsAbove) * kBeamsArea;
  const auto plate_casimir = [&](double x) { return CasimirPressure{}.Value(kCasimirGap - x); };
  const auto plate_vdw = [&](double x) { return vdw_pressure.Value(kCasimirGap - x); };
  struct Case {
    FrameElementForce* force;
    double x, beams;
    std::function<double(double)> plate;
  };
  for (const Case& c : {Case{&casimir, x_casimir, beams_casimir, plate_casimir},
                        Case{&vdw, x_vdw, beams_vdw, plate_vdw}}) {
    const FrameStaticSolution s = SolveFrameNonlinearStatic(model, {c.force}, {});
    ASSERT_EQ(s.status, Status::kOk);
    const double x = -s.bodies[0][1];
    std::printf("plate at %.6g of the gap, error %.1e\n", x / kCasimirGap, std::abs(x / c.x - 1.0));
    EXPECT_GT(c.x, 0.03 * kCasimirGap);
    EXPECT_NEAR(x, c.x, 1e-6 * c.x);
    double lift = 0.0;
    for (const FrameReaction& r : s.reactions) lift += r.force.y();
    const double pull = c.plate(x) * device.area + c.beams;
    EXPECT_NEAR(lift, pull, 1e-6 * pull);
  }
}

// With the contact's separation the gap is held there from below, as on the beam: the plate
// pushed a tenth of the gap through the contact plane meets Casimir's pressure at the plane,
// p(s) A on its face, and no stiffness; without it the same state has closed no gap and takes
// the pressure at its own, 1e-12 (round-off: every point of the flat plate at one gap).
TEST(FrameSurfaceForceTest, TheSeparationHoldsTheGapUnderASurfacePressure) {
  const test::PlateOnFourBeams device = ThickPlate();
  const FrameModel model(device.structure);
  FrameGapOptions under{kCasimirGap, {device.plate}};
  under.separation = 0.1 * kCasimirGap;
  FrameGapForce<CasimirPressure> held(model, CasimirPressure{}, under);
  under.separation = 0.0;
  FrameGapForce<CasimirPressure> free(model, CasimirPressure{}, under);
  const int uy = model.CarrierDof(model.mesh().body_carrier[0], 1);
  const auto pull = [&](FrameGapForce<CasimirPressure>& force, double down, double& slope) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
    d[uy] = -down / model.units().length;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(model.FreeDofCount());
    ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
    EXPECT_TRUE(force.Evaluate(d, r, tangent));
    slope = tangent.band()(uy, uy);
    return r[uy] * model.units().force;
  };
  double slope = 0.0;
  const double through = pull(held, 0.95 * kCasimirGap, slope);
  const double at_plane = CasimirPressure{}.Value(0.1 * kCasimirGap) * device.area;
  EXPECT_NEAR(through, at_plane, 1e-12 * at_plane);
  EXPECT_EQ(slope, 0.0);
  const double own = pull(free, 0.95 * kCasimirGap, slope);
  const double at_own = CasimirPressure{}.Value(0.05 * kCasimirGap) * device.area;
  EXPECT_NEAR(own, at_own, 1e-12 * at_own);
  EXPECT_LT(slope, 0.0);
}

// A member or a plate with 1 % of its gap left at one end: the Casimir pressure (1/g^4) varies
// there over a fiftieth of the element or plate, where a fixed Gauss rule loses percents. The
// quadrature halves each face until its gap varies by at most 1.25 (FrameGapIntegral); what is
// left is the 4-point rule's error on such intervals, ~1e-8 of the force (as on the beam).

// The netlist cantilever of the reference beam (20 elements), 2 um over the substrate.
StructureDescription NetlistCantilever() {
  StructureDescription s;
  s.series_order = 1;
  s.nodes.push_back({"root", Eigen::Vector3d::Zero(), AnchorOf(Support::kClamped)});
  s.nodes.push_back({"tip", {test::kReferenceLength, 0.0, 0.0}, AnchorOf(Support::kFree)});
  s.members.push_back(
      {0, 1, test::Silicon(), test::ReferenceSection(), 20, Eigen::Vector3d::UnitY()});
  return s;
}

// The member's deflection toward +y [m] for the state x (internal units) at t in [0, 1] along
// its element: the Hermite cubic of the element's end values and slopes, written here.
double MemberDeflection(const FrameModel& model, const Eigen::VectorXd& x,
                        const FrameMesh::Element& element, double t) {
  const FrameMesh& mesh = model.mesh();
  const auto at = [&](int node, int k) {
    const int dof = model.CarrierDof(mesh.nodes[node].carrier, k);
    return dof >= 0 ? x[dof] : 0.0;
  };
  const double l = model.units().length, h = element.length;
  const double t2 = t * t, t3 = t2 * t;
  return (1 - 3 * t2 + 2 * t3) * at(element.from, 1) * l +
         (t - 2 * t2 + t3) * h * at(element.from, 5) + (3 * t2 - 2 * t3) * at(element.to, 1) * l +
         (t3 - t2) * h * at(element.to, 5);
}

// The integral of f(gap [m], deflection of y [m], m) over the member's lower face (width b),
// by 4 Gauss points on each of 400 intervals of each element (2.5 % of the shortest length over
// which the gap varies in these tests).
template <typename F>
double OverTheMember(const FrameModel& model, const Eigen::VectorXd& d, const Eigen::VectorXd& y,
                     double gap, F&& f) {
  const GaussLegendre rule = GaussLegendre::Of(4);
  double sum = 0.0;
  for (const FrameMesh::Element& element : model.mesh().elements) {
    constexpr int kIntervals = 400;
    for (int i = 0; i < kIntervals; ++i) {
      for (std::size_t k = 0; k < rule.points.size(); ++k) {
        const double t = (i + rule.points[k]) / kIntervals;
        const double g = gap + MemberDeflection(model, d, element, t);
        sum += rule.weights[k] * element.length / kIntervals * test::kReferenceWidth *
               f(g, MemberDeflection(model, y, element, t));
      }
    }
  }
  return sum;
}

// The member bent to the tip-load shape with its tip 1 % of the gap from the substrate.
// - Casimir: its force against the gradient of the energy -int C b / (3 g^3) dx; central
//   differences leave ~1e-7: 1e-5 asserted. The same force by the fixed rule (gap_ratio 100: no
//   halving at these gaps) is 1 % off or more.
// - The gas film, moving in that shape: the power it takes, v^T r, against
//   int mu b^3 v_y^2 / g^3 dx (no rarefaction); the quadrature's ~1e-8: 1e-7 asserted.
TEST(FrameGapIntegralTest, AMemberNearlyTouchingTakesTheForceOfItsEnergy) {
  const FrameModel model(NetlistCantilever());
  const double l = model.units().length, gap = test::kReferenceGap, tip = 0.99 * gap;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (const FrameMesh::Node& node : model.mesh().nodes) {
    const double xi = node.position.x() / test::kReferenceLength;
    const int uy = model.CarrierDof(node.carrier, 1), rz = model.CarrierDof(node.carrier, 5);
    if (uy >= 0) d[uy] = -tip * xi * xi * (3.0 - xi) / 2.0 / l;
    if (rz >= 0) d[rz] = -tip * 3.0 * xi * (2.0 - xi) / 2.0 / test::kReferenceLength;
  }
  const auto energy = [&](const Eigen::VectorXd& state) {
    const double sum = OverTheMember(model, state, state, gap,
                                     [](double g, double) { return 1.0 / (3.0 * g * g * g); });
    return -CasimirPressure::Coefficient() * sum / (model.units().force * l);
  };
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{}, FrameGapOptions{gap});
  test::ExpectForceAndTangentMatchDifferences(casimir, d, model.Stiffness().bandwidth(), energy,
                                              1e-6 * gap / l, 1e-5);

  FrameGapOptions fixed{gap};
  fixed.gap_ratio = 100.0;
  FrameGapForce<CasimirPressure> coarse(model, CasimirPressure{}, fixed);
  Eigen::VectorXd adaptive_r = Eigen::VectorXd::Zero(d.size()), fixed_r = adaptive_r;
  ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
  ASSERT_TRUE(casimir.Evaluate(d, adaptive_r, tangent));
  ASSERT_TRUE(coarse.Evaluate(d, fixed_r, tangent));
  const double miss = (fixed_r - adaptive_r).norm() / adaptive_r.norm();
  std::printf("member at 1 %% of its gap: the fixed rule misses the force by %.2g\n", miss);
  EXPECT_GT(miss, 1e-2);

  // The capacitance, a sum over the halved strips' points: against eps0 int b / g dx by the fine
  // rule (the two agree to ~3e-11, 1/g varying less than the pressures: 1e-9 asserted).
  const FrameGapForce<ElectrostaticPressure> electrode(model, ElectrostaticPressure{1.0},
                                                       FrameGapOptions{gap});
  const double capacitance =
      OverTheMember(model, d, d, gap, [](double g, double) { return kVacuumPermittivity / g; });
  std::printf("member at 1 %% of its gap: capacitance error %.1e\n",
              std::abs(electrode.Capacitance(d) / capacitance - 1.0));
  EXPECT_NEAR(electrode.Capacitance(d), capacitance, 1e-9 * capacitance);

  constexpr double kAir = 1.81e-5;  // Pa s
  FrameSqueezeFilm film(model, SqueezeFilmOptions{kAir, 0.0}, gap);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(d.size());
  tangent.Clear();
  ASSERT_TRUE(film.EvaluateViscous(d, d, 0.0, r, tangent));
  const UnitSystem& u = model.units();
  const double power = d.dot(r) * u.force * u.length / u.time;
  const double b3 = std::pow(test::kReferenceWidth, 3);
  const double expected = OverTheMember(model, d, d, gap, [&](double g, double y) {
    const double vy = y / u.time;
    return kAir * b3 * vy * vy / (g * g * g) / test::kReferenceWidth;
  });
  std::printf("film on the member at 1 %% of its gap: power error %.1e\n",
              std::abs(power / expected - 1.0));
  EXPECT_NEAR(power, expected, 1e-7 * expected);
}

// A plate tilted so that its gap runs from 1 % to 150 % of the nominal gap along x, then along z,
// then along the diagonal, then along x with the contact's separation holding the gap over an
// eighth of the plate: its Casimir force and moments against the closed forms of the integrals of
// C / g^4 over the rectangle for a gap linear in x (or z, or both). Each case takes a branch of
// the quadrature along the gap's level lines (FrameGapIntegral): chords across the whole plate,
// chords along x, chords whose ends turn the plate's corners, a range of the gap broken where the
// separation starts to hold it. The quadrature's ~1e-8: 1e-7 asserted. The fixed rule misses the
// force by percents.
TEST(FrameGapIntegralTest, ATiltedPlateNearlyTouchingTakesItsClosedFormForce) {
  const test::PlateOnFourBeams device;
  const FrameModel model(device.structure);
  const double l = model.units().length, f = model.units().force, gap = 2e-6, side = device.side;
  const double c = CasimirPressure::Coefficient();
  const int plate = model.mesh().body_carrier[0];
  const int uy = model.CarrierDof(plate, 1), tx = model.CarrierDof(plate, 3),
            tz = model.CarrierDof(plate, 5);
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{},
                                         FrameGapOptions{gap, {device.plate}});
  FrameGapOptions fixed{gap, {device.plate}};
  fixed.gap_ratio = 100.0;
  FrameGapForce<CasimirPressure> coarse(model, CasimirPressure{}, fixed);
  const auto evaluate = [&](FrameGapForce<CasimirPressure>& force, const Eigen::VectorXd& d) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(d.size());
    ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
    EXPECT_TRUE(force.Evaluate(d, r, tangent));
    return r;
  };
  // The gap g_c + s x + t z over the plate (x, z from its centre): u_y l = g_c - gap,
  // theta_z = s, theta_x = -t.
  const double low = 0.01 * gap, high = 1.5 * gap, centre = 0.5 * (low + high);
  const double s = (high - low) / side;
  // Along one side alone: F = side C / (3 s) [g^-3] and the moment about the centre
  // side / s^2 [-C / (2 g^2) + g_c C / (3 g^3)], both from high to low.
  const auto force_along = [&](double g) { return side * c / (3.0 * s * g * g * g); };
  const auto moment_along = [&](double g) {
    return side / (s * s) * (-c / (2.0 * g * g) + centre * c / (3.0 * g * g * g));
  };
  const double force = force_along(low) - force_along(high);
  const double moment = moment_along(high) - moment_along(low);
  for (const bool along_x : {true, false}) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
    d[uy] = (centre - gap) / l;
    d[along_x ? tz : tx] = along_x ? s : -s;
    const Eigen::VectorXd r = evaluate(casimir, d);
    // The moment of the pressure about z is r[tz] (phi = x), about x -r[tx] (phi = -z).
    const double turning = along_x ? r[tz] * f * l : -r[tx] * f * l;
    std::printf("plate tilted along %s: force %.3e N, error %.1e; moment error %.1e\n",
                along_x ? "x" : "z", force, std::abs(r[uy] * f / force - 1.0),
                std::abs(turning / moment - 1.0));
    EXPECT_NEAR(r[uy] * f, force, 1e-7 * force);
    EXPECT_NEAR(turning, moment, 1e-7 * std::abs(moment));
    EXPECT_NEAR(r[along_x ? tx : tz], 0.0, 1e-12 * std::abs(turning / (f * l)));
    EXPECT_GT(std::abs(evaluate(coarse, d)[uy] / r[uy] - 1.0), 1e-2);
    // The capacitance along the same level lines: eps0 side / s ln(high / low) (~3e-11: 1e-9
    // asserted).
    const FrameGapForce<ElectrostaticPressure> electrode(model, ElectrostaticPressure{1.0},
                                                         FrameGapOptions{gap, {device.plate}});
    const double capacitance = kVacuumPermittivity * side / s * std::log(high / low);
    std::printf("plate tilted along %s: capacitance error %.1e\n", along_x ? "x" : "z",
                std::abs(electrode.Capacitance(d) / capacitance - 1.0));
    EXPECT_NEAR(electrode.Capacitance(d), capacitance, 1e-9 * capacitance);
  }

  // Along the diagonal: the gap's range split between x and z, F = sum over the corners of
  // +-C / (6 s t g^2) (the mixed antiderivative of C / g^4).
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  d[uy] = (centre - gap) / l;
  const double half = 0.5 * (high - low) / side;
  d[tz] = half;
  d[tx] = -half;
  const auto corner = [&](double x, double z) {
    const double g = centre + half * (x + z);
    return c / (6.0 * half * half * g * g);
  };
  const double h = 0.5 * side;
  const double diagonal = corner(h, h) - corner(-h, h) - corner(h, -h) + corner(-h, -h);
  Eigen::VectorXd r = evaluate(casimir, d);
  std::printf("plate tilted along the diagonal: force error %.1e\n",
              std::abs(r[uy] * f / diagonal - 1.0));
  EXPECT_NEAR(r[uy] * f, diagonal, 1e-7 * diagonal);
  EXPECT_NEAR(r[tz], -r[tx], 1e-9 * std::abs(r[tz]));
  EXPECT_GT(std::abs(evaluate(coarse, d)[uy] / r[uy] - 1.0), 1e-2);

  // Along x through the contact plane: where g_c + s x is below the separation, the pressure is
  // the separation's. F = side (x_s + side/2) p(separation) + side C / (3 s) [g^-3] from high to
  // the separation, x_s where the gap reaches the separation.
  FrameGapOptions held_options{gap, {device.plate}};
  held_options.separation = 0.2 * gap;
  FrameGapForce<CasimirPressure> held(model, CasimirPressure{}, held_options);
  d.setZero();
  d[uy] = (centre - gap) / l;
  d[tz] = s;
  const double x_s = (held_options.separation - centre) / s;
  const double held_force = side * (x_s + h) * CasimirPressure{}.Value(held_options.separation) +
                            force_along(held_options.separation) - force_along(high);
  r = evaluate(held, d);
  std::printf("plate tilted through the contact plane: force error %.1e\n",
              std::abs(r[uy] * f / held_force - 1.0));
  EXPECT_NEAR(r[uy] * f, held_force, 1e-7 * held_force);
}

// The same plate tilted along the diagonal, 1 % of its gap left at one corner: its Casimir force
// and tangent against central differences of the energy -C / (3 g^3) over the rectangle, in
// closed form (-C / (6 s t) times the corners' +-1/g); the differences leave ~1e-7: 1e-5 asserted.
TEST(FrameGapIntegralTest, ATiltedPlatesForceAndTangentAreTheDerivativesOfItsEnergy) {
  const test::PlateOnFourBeams device;
  const FrameModel model(device.structure);
  const double l = model.units().length, gap = 2e-6, h = 0.5 * device.side;
  const int plate = model.mesh().body_carrier[0];
  const int uy = model.CarrierDof(plate, 1), tx = model.CarrierDof(plate, 3),
            tz = model.CarrierDof(plate, 5);
  const auto energy = [&](const Eigen::VectorXd& state) {
    const double centre = gap + state[uy] * l, s = state[tz], t = -state[tx];
    const auto corner = [&](double x, double z) { return 1.0 / (centre + s * x + t * z); };
    const double sum = corner(h, h) - corner(-h, h) - corner(h, -h) + corner(-h, -h);
    return -CasimirPressure::Coefficient() * sum / (6.0 * s * t) / (model.units().force * l);
  };
  const double low = 0.01 * gap, high = 1.5 * gap, half = 0.5 * (high - low) / device.side;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  d[uy] = (0.5 * (low + high) - gap) / l;
  d[tz] = half;
  d[tx] = -0.8 * half;  // unequal slopes: the chords turn different corners at each end
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{},
                                         FrameGapOptions{gap, {device.plate}});
  test::ExpectForceAndTangentMatchDifferences(casimir, d, model.Stiffness().bandwidth(), energy,
                                              1e-6 * gap / l, 1e-5);
}

// A state whose gap closes somewhere, or is not finite, is outside the pressure's domain: the
// force says so (the step is cut), on a member as on a plate, whichever degree of freedom
// carries the NaN or the infinity; the capacitance of such a state is NaN.
TEST(FrameGapIntegralTest, AClosedOrNonFiniteGapIsAStatus) {
  const test::PlateOnFourBeams device;
  const FrameModel model(device.structure);
  const double l = model.units().length, gap = 2e-6;
  const ElectrostaticPressure pressure{10.0};
  // Over the plate alone (no strip shares its degrees of freedom), and under everything.
  FrameGapForce<ElectrostaticPressure> plate_only(model, pressure, {gap, {device.plate}});
  FrameGapForce<ElectrostaticPressure> everything(model, pressure, FrameGapOptions{gap});
  const int plate = model.mesh().body_carrier[0];
  const int beam = model.mesh().nodes[model.mesh().elements[1].to].carrier;  // inside a beam
  struct Case {
    FrameGapForce<ElectrostaticPressure>* force;
    int dof;
  };
  const std::vector<Case> cases = {{&plate_only, model.CarrierDof(plate, 1)},
                                   {&plate_only, model.CarrierDof(plate, 3)},
                                   {&plate_only, model.CarrierDof(plate, 5)},
                                   {&everything, model.CarrierDof(beam, 1)},
                                   {&everything, model.CarrierDof(beam, 5)}};
  ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
  for (const Case& c : cases) {
    ASSERT_GE(c.dof, 0);
    for (const double bad : {std::nan(""), std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity()}) {
      Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
      d[c.dof] = bad;
      Eigen::VectorXd r = Eigen::VectorXd::Zero(model.FreeDofCount());
      EXPECT_FALSE(c.force->Evaluate(d, r, tangent)) << "dof " << c.dof << " at " << bad;
      EXPECT_TRUE(std::isnan(c.force->Capacitance(d))) << "dof " << c.dof << " at " << bad;
    }
  }
  for (const Case& c : {cases[0], cases[3]}) {  // through the substrate, then open everywhere
    Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
    d[c.dof] = -1.01 * gap / l;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(model.FreeDofCount());
    EXPECT_FALSE(c.force->Evaluate(d, r, tangent)) << "dof " << c.dof;
    d[c.dof] = -0.5 * gap / l;
    EXPECT_TRUE(c.force->Evaluate(d, r, tangent)) << "dof " << c.dof;
    EXPECT_TRUE(r.allFinite());
  }
}

// A velocity is for the strips' points (the gas film's law): the plates' film is a law of their
// own, and an integral over the plates refuses one rather than drop it.
TEST(FrameGapIntegralTest, AVelocityReachesTheStripsAlone) {
  const test::PlateOnFourBeams device;
  const FrameModel model(device.structure);
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  const auto law = [](const FrameGapIntegral::Face&, double, double area, double vy) {
    return std::pair{vy * area, 0.0};
  };
  ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
  Eigen::VectorXd r = Eigen::VectorXd::Zero(model.FreeDofCount());
  const FrameGapIntegral everything(model, FrameGapOptions{2e-6});
  EXPECT_THROW(everything.Integrate(d, &d, law, r, tangent), std::invalid_argument);
  FrameGapOptions strips{2e-6};
  strips.plates = false;
  EXPECT_TRUE(FrameGapIntegral(model, strips).Integrate(d, &d, law, r, tangent));
}

// With Casimir beside it the electrode pulls the plate in sooner: the fold of
// V^2(x) = 2 (g - x)^2 (k x - p_C(g - x) A) / (eps0 A), maximised here by golden sections.
// The fold search leaves the voltage within ~1e-7 (frame_pullin_test.cpp); 1e-6 asserted.
TEST(FrameSurfaceForceTest, CasimirLowersThePullInVoltageToTheFoldOfTheBalance) {
  const test::PlateOnFourBeams device = ThickPlate();
  const FrameModel model(device.structure);
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{}, FrameGapOptions{kCasimirGap});
  FramePullInOptions options;
  options.electrodes.gap = kCasimirGap;
  options.electrodes.electrodes = {device.plate};
  const FramePullInResult result = SolveFramePullIn(model, options, {&casimir});
  ASSERT_EQ(result.fold.status, Status::kOk);
  const auto squared = [&](double x) {
    const double g = kCasimirGap - x;
    return 2.0 * g * g * (device.k * x - CasimirPressure{}.Value(g) * device.area) /
           (kVacuumPermittivity * device.area);
  };
  double lo = 0.0, hi = kCasimirGap / 2.0;
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200; ++i) {
    const double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
    (squared(x1) < squared(x2) ? lo : hi) = squared(x1) < squared(x2) ? x1 : x2;
  }
  const double voltage = std::sqrt(squared(0.5 * (lo + hi)));
  const double without = std::sqrt(8.0 * device.k * std::pow(kCasimirGap, 3) /
                                   (27.0 * kVacuumPermittivity * device.area));
  std::printf("pull-in with Casimir %.9g V against %.9g V (without it %.9g V)\n",
              result.fold.voltage_v, voltage, without);
  EXPECT_LT(voltage, 0.95 * without);
  EXPECT_NEAR(result.fold.voltage_v, voltage, 1e-6 * voltage);
}

constexpr double kFilmGap = 6e-6;

// The plate, released 0.2 of the gap down, rings down on its film: m x'' + c(h) x' + k x = 0,
// c(h) = mu translation / h^3 at the gap h = g + x, integrated here by fourth-order Runge-Kutta
// at a thousandth of the step. The suspension weighs 1e-3 of polysilicon (its inertia 3e-5 of the
// plate's) and its strips take ~1e-4 of the film's damping; the trapezoidal rule's phase error,
// (w h)^2 / 12 per radian at 400 steps a period, adds ~3e-4 of the swing over the run: 2e-3 of
// the release asserted.
TEST(FrameSqueezeFilmTest, APlateRingsDownOnItsFilmAsTheOscillator) {
  const test::PlateOnFourBeams device(100e-6, 2e-6, 1e-3);
  const FrameModel model(device.structure);
  const SqueezeFilmOptions air{};
  FrameSqueezeFilm film(model, air, kFilmGap);
  const double m = device.Mass(), k = device.k;
  const double c0 = air.viscosity * PlateSqueezeFactors::Of(device.side, device.side).translation;
  const double omega = std::sqrt(k / m);
  const double zeta = c0 / std::pow(kFilmGap, 3) / (2.0 * m * omega);
  ASSERT_GT(zeta, 0.05);  // a swing that decays visibly over the run
  ASSERT_LT(zeta, 0.2);
  const double period = 2.0 * kPi / omega, x0 = -0.2 * kFilmGap;
  TransientOptions options;
  options.duration = 3.0 * period;
  options.time_step = period / 400.0;
  options.start_static = true;
  FrameLoadCase release;
  release.points.push_back({-1, 0, Eigen::Vector3d(0.0, k * x0, 0.0), Eigen::Vector3d::Zero()});
  const FrameTransientResult run = RunFrameTransient(model, release, options, {{-1, 0}}, &film);
  ASSERT_EQ(run.run.status, Status::kOk);
  // The oscillator, from the same release.
  const auto rate = [&](const Eigen::Vector2d& s) {
    const double h = kFilmGap + s[0];
    return Eigen::Vector2d(s[1], -(k * s[0] + c0 / (h * h * h) * s[1]) / m);
  };
  Eigen::Vector2d s(x0, 0.0);
  double t = 0.0, worst = 0.0;
  const double dt = options.time_step / 1000.0;
  for (Eigen::Index row = 0; row < run.history.rows(); ++row) {
    for (; t < run.run.time_s[row] - 0.5 * dt; t += dt) {
      const Eigen::Vector2d k1 = rate(s), k2 = rate(s + 0.5 * dt * k1),
                            k3 = rate(s + 0.5 * dt * k2), k4 = rate(s + dt * k3);
      s += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    worst = std::max(worst, std::abs(run.history(row, 1) - s[0]));
  }
  std::printf("plate on its film: zeta %.3f, largest difference %.2e of the release\n", zeta,
              worst / std::abs(x0));
  EXPECT_LT(worst, 2e-3 * std::abs(x0));
  EXPECT_LT(std::abs(run.history(run.history.rows() - 1, 1)), 0.3 * std::abs(x0));
}

// The film's force against differences in d and in v, the plate tilted and moving, the beams
// bent and moving with it. The plate's moments depend on u_y through c(h) times their rates
// (c' R omega), which the symmetric tangent leaves out: here the plate's tilts do not turn, so
// that term vanishes, while dr/dv, independent of the rates, checks the tilts' damping. The
// power the film takes is positive.
TEST(FrameSqueezeFilmTest, TangentsMatchDifferencesOfTheForce) {
  const test::PlateOnFourBeams device;
  const FrameModel model(device.structure);
  const int n = model.FreeDofCount();
  FrameSqueezeFilm film(model, SqueezeFilmOptions{1.81e-5, 68e-9}, kFilmGap);
  const int plate = model.mesh().body_carrier[0];
  const int uy = model.CarrierDof(plate, 1);
  const int tilts[2] = {model.CarrierDof(plate, 3), model.CarrierDof(plate, 5)};
  Eigen::VectorXd d(n), v(n);
  for (int i = 0; i < n; ++i) {
    d[i] = 1e-3 * std::sin(0.3 * i + 0.1);
    v[i] = 1e-2 * std::sin(0.7 * i + 0.2);
  }
  d[uy] = -0.3 * kFilmGap / model.units().length;
  for (const int tilt : tilts) v[tilt] = 0.0;
  // h = 1e-7 of the state's scale keeps truncation and cancellation near 1e-9.
  test::ExpectViscousTangentsMatchDifferences(film, d, v, model.Stiffness().bandwidth(), 1e-7, 1e-7,
                                              1e-6);
}

}  // namespace
}  // namespace cosmems
