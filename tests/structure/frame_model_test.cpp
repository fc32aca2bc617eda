// Frames against an oracle written in the tests (frame_oracle.hpp: textbook 12 x 12 Euler-
// Bernoulli elements, dense, constraints by a null space) and against closed forms.
//
// Tolerances: static point loads at nodes are exact for Hermite elements, so the frame and the
// oracle agree to the round-off of the solves, 1e-9 of the largest displacement (the reduced
// stiffness's condition number is about 1e6 here). At series order 0 the frame's mass is the
// oracle's, so their frequencies agree to the eigensolvers' round-off (measured 4e-14; 1e-12
// allowed); at order 1 they agree to the oracle's discretisation error at a fine mesh.
#include <gtest/gtest.h>

#include <cmath>

#include "test_beams.hpp"
#include "test_frames.hpp"

namespace cosmems {
namespace {

using test::AddBeam;
using test::AddBody;
using test::AddNode;
using test::Poly;
using test::SquareSection;

constexpr double kL = 100e-6;

ModalOptions Count(int count) {
  ModalOptions options;
  options.count = count;
  return options;
}

// Every node's motion of the frame model against the oracle's, relative to the largest.
void ExpectStaticMatchesOracle(const StructureDescription& s, const FrameLoadCase& loads,
                               double tolerance = 1e-9) {
  const FrameModel model(s);
  const FrameStaticSolution solution = SolveFrameStatic(model, loads);
  ASSERT_EQ(solution.status, Status::kOk);
  const int nodes = static_cast<int>(s.nodes.size());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(6 * (nodes + static_cast<int>(s.bodies.size())));
  for (const FramePointLoad& load : loads.points) {
    const int at = load.node >= 0 ? load.node : nodes + load.body;
    f.segment<3>(6 * at) += load.force;
    f.segment<3>(6 * at + 3) += load.moment;
  }
  const Eigen::VectorXd expected = test::oracle::SolveStatic(test::ToOracle(s), f);
  Eigen::VectorXd got(expected.size());
  for (int n = 0; n < nodes; ++n) got.segment<6>(6 * n) = solution.nodes[n];
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    got.segment<6>(6 * (nodes + b)) = solution.bodies[b];
  }
  // Displacements against the largest, rotations against the largest or the largest
  // displacement over the structure's size (when no rotation is more than round-off).
  double scale[2] = {0.0, 0.0};
  for (int i = 0; i < expected.size(); ++i) {
    scale[i % 6 / 3] = std::max(scale[i % 6 / 3], std::abs(expected[i]));
  }
  double size = 0.0;
  for (const StructureNode& a : s.nodes) {
    for (const StructureNode& b : s.nodes) size = std::max(size, (a.position - b.position).norm());
  }
  scale[1] = std::max(scale[1], scale[0] / size);
  for (int i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(got[i], expected[i], tolerance * scale[i % 6 / 3]) << "entry " << i;
  }
}

// Reactions and loads balance: forces, and moments about the origin.
void ExpectBalanced(const StructureDescription& s, const FrameLoadCase& loads,
                    const FrameStaticSolution& solution) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double scale_f = 0.0, scale_m = 0.0;
  auto add = [&](const Eigen::Vector3d& at, const Eigen::Vector3d& f, const Eigen::Vector3d& c) {
    force += f;
    moment += c + at.cross(f);
    scale_f = std::max(scale_f, f.norm());
    scale_m = std::max(scale_m, (c + at.cross(f)).norm());
  };
  for (const FramePointLoad& load : loads.points) {
    add(load.node >= 0 ? s.nodes[load.node].position : s.bodies[load.body].center, load.force,
        load.moment);
  }
  for (const FrameReaction& r : solution.reactions)
    add(s.nodes[r.node].position, r.force, r.moment);
  EXPECT_LT(force.norm(), 1e-9 * scale_f);
  EXPECT_LT(moment.norm(), 1e-9 * scale_m);
}

FrameLoadCase NodeLoad(int node, Eigen::Vector3d force, Eigen::Vector3d moment = {0, 0, 0}) {
  FrameLoadCase loads;
  loads.points.push_back({node, -1, force, moment});
  return loads;
}

StructureDescription LFrame() {
  StructureDescription s;
  const int a = AddNode(s, "anchor", {0, 0, 0}, Support::kClamped);
  const int corner = AddNode(s, "corner", {kL, 0, 0});
  const int tip = AddNode(s, "tip", {kL, 0, 0.6 * kL});
  AddBeam(s, a, corner, 3);
  AddBeam(s, corner, tip, 2, RectangularSection{3e-6, 2e-6});
  return s;
}

TEST(FrameStaticTest, LFrameMatchesTheOracleInAndOutOfPlane) {
  const StructureDescription s = LFrame();
  ExpectStaticMatchesOracle(s, NodeLoad(2, {1e-7, -2e-6, 3e-7}, {1e-12, 2e-12, -3e-12}));
  ExpectStaticMatchesOracle(s, NodeLoad(1, {0, 0, 1e-6}));
}

TEST(FrameStaticTest, TAndPortalFramesMatchTheOracle) {
  StructureDescription t;
  const int foot = AddNode(t, "foot", {0, 0, 0}, Support::kClamped);
  const int joint = AddNode(t, "joint", {0.8 * kL, 0, 0});
  const int left = AddNode(t, "left", {0.8 * kL, 0, -0.5 * kL}, Support::kPinned);
  const int right = AddNode(t, "right", {0.8 * kL, 0, 0.4 * kL});
  AddBeam(t, foot, joint, 4);
  AddBeam(t, joint, left, 2);
  AddBeam(t, right, joint, 3, RectangularSection{4e-6, 2e-6});
  FrameLoadCase loads = NodeLoad(right, {2e-7, -1e-6, 5e-7});
  loads.points.push_back({joint, -1, {0, 3e-7, 0}, {0, 0, 1e-12}});
  ExpectStaticMatchesOracle(t, loads);

  // A portal standing out of the substrate plane: legs along y name their thickness direction.
  StructureDescription p;
  const int a = AddNode(p, "a", {0, 0, 0}, Support::kClamped);
  const int b = AddNode(p, "b", {0, 0.5 * kL, 0});
  const int c = AddNode(p, "c", {kL, 0.5 * kL, 0});
  const int d = AddNode(p, "d", {kL, 0, 0}, Support::kClamped);
  AddBeam(p, a, b, 3, SquareSection(), Eigen::Vector3d::UnitX());
  AddBeam(p, b, c, 4);
  AddBeam(p, d, c, 3, RectangularSection{3e-6, 2e-6}, -Eigen::Vector3d::UnitZ());
  FrameLoadCase sway = NodeLoad(b, {1e-6, 0, 2e-7});
  sway.points.push_back({c, -1, {0, -1e-6, 0}, {1e-12, 0, 0}});
  ExpectStaticMatchesOracle(p, sway);
}

TEST(FrameStaticTest, ReactionsBalanceTheLoadsAndMatchTheCantilever) {
  const StructureDescription s = LFrame();
  FrameLoadCase loads = NodeLoad(2, {1e-7, -2e-6, 3e-7}, {1e-12, 2e-12, -3e-12});
  loads.distributed = {0, -0.01, 0.002};
  const FrameStaticSolution solution = SolveFrameStatic(FrameModel(s), loads);
  ASSERT_EQ(solution.status, Status::kOk);
  ASSERT_EQ(solution.reactions.size(), 1u);
  // A distributed load balances through its resultant: add it as point loads at member centres.
  FrameLoadCase all = loads;
  all.distributed.setZero();
  StructureDescription with_centres = s;
  for (const StructureMember& m : s.members) {
    const Eigen::Vector3d a = s.nodes[m.from].position, b = s.nodes[m.to].position;
    const int centre = AddNode(with_centres, "centre" + std::to_string(m.from), 0.5 * (a + b));
    all.points.push_back({centre, -1, loads.distributed * (b - a).norm(), {0, 0, 0}});
  }
  ExpectBalanced(with_centres, all, solution);

  // One cantilever: the clamp holds the tip force and its moment F L.
  StructureDescription c;
  AddNode(c, "root", {0, 0, 0}, Support::kClamped);
  AddNode(c, "tip", {kL, 0, 0});
  AddBeam(c, 0, 1, 5);
  const FrameStaticSolution tip = SolveFrameStatic(FrameModel(c), NodeLoad(1, {0, -1e-6, 0}));
  EXPECT_NEAR(tip.reactions[0].force.y(), 1e-6, 1e-6 * 1e-12);
  EXPECT_NEAR(tip.reactions[0].moment.z(), 1e-6 * kL, 1e-6 * kL * 1e-12);
  const double eiz = Poly().young_modulus * SquareSection().SecondMomentZ();
  EXPECT_NEAR(tip.nodes[1][1], -1e-6 * kL * kL * kL / (3 * eiz), 1e-12 * 1e-6 * kL * kL * kL / eiz);
  EXPECT_NEAR(tip.max_deflection, 1e-6 * kL * kL * kL / (3 * eiz),
              1e-12 * 1e-6 * kL * kL * kL / eiz);
  // A torque T: von Mises of Saint-Venant's shear T c / J, sqrt(3) T c / J.
  const FrameStaticSolution twisted =
      SolveFrameStatic(FrameModel(c), NodeLoad(1, {0, 0, 0}, {1e-12, 0, 0}));
  const double tau = 1e-12 * 2e-6 / SquareSection().TorsionConstant();
  EXPECT_NEAR(twisted.max_stress_pa, std::sqrt(3.0) * tau, 1e-9 * tau);
  // sigma = M c / I at the root.
  EXPECT_NEAR(tip.max_stress_pa, 1e-6 * kL * 1e-6 / SquareSection().SecondMomentZ(),
              1e-9 * 1e-6 * kL * 1e-6 / SquareSection().SecondMomentZ());
}

TEST(FrameStaticTest, RigidBodiesGiveTheClosedFormsOfGuidedBeams) {
  const double eiz = Poly().young_modulus * SquareSection().SecondMomentZ();
  const double eiy = Poly().young_modulus * SquareSection().SecondMomentY();

  // A plate on four beams clamped at their anchors: out of plane, each beam is clamped-guided.
  StructureDescription plate;
  std::vector<int> corners;
  for (int sx = -1; sx <= 1; sx += 2) {
    for (int sz = -1; sz <= 1; sz += 2) {
      const int anchor = AddNode(plate, "a", {sx * (30e-6 + kL), 0, sz * 20e-6}, Support::kClamped);
      const int corner = AddNode(plate, "c", {sx * 30e-6, 0, sz * 20e-6});
      AddBeam(plate, anchor, corner, 4);
      corners.push_back(corner);
    }
  }
  for (std::size_t i = 0; i < plate.nodes.size(); ++i) plate.nodes[i].name += std::to_string(i);
  AddBody(plate, "plate", {0, 0, 0}, {60e-6, 2e-6, 40e-6}, corners);
  FrameLoadCase press;
  press.points.push_back({-1, 0, {0, -1e-6, 0}, {0, 0, 0}});
  const FrameStaticSolution pressed = SolveFrameStatic(FrameModel(plate), press);
  ASSERT_EQ(pressed.status, Status::kOk);
  EXPECT_NEAR(pressed.bodies[0][1], -1e-6 / (4 * 12 * eiz / (kL * kL * kL)),
              1e-10 * pressed.max_deflection);
  ExpectStaticMatchesOracle(plate, press);

  // The folded flexure along x: 24 E I_y / L^3 with rigid trusses and shuttle.
  const StructureDescription flexure = test::FoldedFlexure(kL, 5);
  const int shuttle = static_cast<int>(flexure.bodies.size()) - 1;
  FrameLoadCase pull;
  pull.points.push_back({-1, shuttle, {1e-6, 0, 0}, {0, 0, 0}});
  const FrameStaticSolution pulled = SolveFrameStatic(FrameModel(flexure), pull);
  ASSERT_EQ(pulled.status, Status::kOk);
  EXPECT_NEAR(pulled.bodies[shuttle][0], 1e-6 / (24 * eiy / (kL * kL * kL)),
              1e-10 * pulled.bodies[shuttle][0]);
  ExpectStaticMatchesOracle(flexure, pull);
}

TEST(FrameStaticTest, TheFoldedFlexureGeneratorBuildsItsDesignsStiffness) {
  FoldedFlexureDesign design;
  design.material = Poly();
  design.beam_length = 150e-6;
  design.beam_width = 3e-6;
  design.elements = 3;
  const StructureDescription s = FoldedFlexure(design);
  EXPECT_EQ(s.members.size(), 8u);
  EXPECT_EQ(s.bodies.back().name, "shuttle");
  FrameLoadCase pull;
  pull.points.push_back({-1, 2, {1e-6, 0, 0}, {0, 0, 0}});
  const FrameStaticSolution pulled = SolveFrameStatic(FrameModel(s), pull);
  ASSERT_EQ(pulled.status, Status::kOk);
  // 24 E I / L^3: each beam clamped-guided (the trusses turn by nothing under a pull along x).
  EXPECT_NEAR(1e-6 / pulled.bodies[2][0], design.Stiffness(), 1e-10 * design.Stiffness());
  design.shuttle_width = 10e-6;
  try {
    FoldedFlexure(design);
    ADD_FAILURE() << "a shuttle narrower than its beams was built";
  } catch (const FieldError& error) {
    EXPECT_EQ(error.field(), "structure.shuttle_width");
  }
}

TEST(FrameStaticTest, AMechanismIsAStatusAndBadNetlistsNameTheirEntry) {
  StructureDescription floating = LFrame();
  floating.nodes[0].anchor = AnchorMask{};
  const FrameStaticSolution s = SolveFrameStatic(FrameModel(floating), NodeLoad(2, {0, 1e-6, 0}));
  EXPECT_EQ(s.status, Status::kNotPositiveDefinite);
  EXPECT_TRUE(s.displacement.allFinite());

  auto message = [](const StructureDescription& d) {
    try {
      d.Validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  StructureDescription zero = LFrame();
  zero.nodes[2].position = zero.nodes[1].position;
  EXPECT_NE(message(zero).find("structure.beams[1].nodes"), std::string::npos) << message(zero);
  EXPECT_NE(message(zero).find("zero length"), std::string::npos);
  StructureDescription upright = LFrame();
  upright.nodes[2].position = upright.nodes[1].position + Eigen::Vector3d(0, kL, 0);
  EXPECT_NE(message(upright).find("structure.beams[1].thickness_direction"), std::string::npos);
  StructureDescription empty = LFrame();
  AddBody(empty, "lonely", {0, 0, 0}, {1e-6, 1e-6, 1e-6}, {});
  EXPECT_NE(message(empty).find("structure.bodies[0].nodes: empty"), std::string::npos);
  StructureDescription twice = LFrame();
  twice.nodes[1].name = "anchor";
  EXPECT_NE(message(twice).find("structure.nodes[1].name: already the name of structure.nodes[0]"),
            std::string::npos);
}

TEST(FrameModelTest, ReverseCuthillMcKeeNumbersAShuffledChainAlongIt) {
  StructureDescription chain;
  const int order[6] = {3, 0, 5, 1, 4, 2};  // node k sits at x = order[k] L / 5
  for (int k = 0; k < 6; ++k) {
    AddNode(chain, "n" + std::to_string(k), {order[k] * kL / 5, 0, 0},
            order[k] == 0 ? Support::kClamped : Support::kFree);
  }
  for (int x = 0; x < 5; ++x) {
    const int from = static_cast<int>(std::find(order, order + 6, x) - order);
    const int to = static_cast<int>(std::find(order, order + 6, x + 1) - order);
    AddBeam(chain, from, to, 2);
  }
  const FrameModel model(chain);
  // Along x the four fields decouple and are numbered each on its own: the widest, a bending,
  // spans two neighbouring nodes' two dofs.
  EXPECT_EQ(model.Stiffness().bandwidth(), 3);
  EXPECT_EQ(model.FreeDofCount(), 6 * 10);
  // Turned in the x-y plane, the chain couples ux, uy, rz and, apart, uz, rx, ry: two nodes'
  // three dofs. Turned out of every plane, all six couple.
  const Eigen::Matrix3d in_plane =
      Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d skew =
      Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for (const auto& [turn, band] : {std::pair{in_plane, 5}, std::pair{skew, 11}}) {
    StructureDescription turned = chain;
    for (StructureNode& node : turned.nodes) node.position = turn * node.position;
    for (StructureMember& member : turned.members) member.thickness_direction = turn.col(1);
    const FrameModel tilted(turned);
    EXPECT_EQ(tilted.Stiffness().bandwidth(), band);
    // The same structure in other axes: the same frequencies.
    ModalOptions three;
    three.count = 3;
    const ModalResult a = SolveModal(model, three), b = SolveModal(tilted, three);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(b.modes[i].frequency_hz, a.modes[i].frequency_hz,
                  1e-10 * a.modes[i].frequency_hz);
    }
  }
}

// The frame's modes against the oracle: identical discretisation at series order 0.
TEST(FrameModalTest, FrequenciesMatchTheOracleAtOrderZeroAndConvergeAtOrderOne) {
  StructureDescription s = test::FoldedFlexure(kL, 4);
  s.series_order = 0;
  const FrameModalResult modes = SolveFrameModal(FrameModel(s), Count(8));
  ASSERT_EQ(modes.modal.status, Status::kOk);
  const Eigen::VectorXd oracle = test::oracle::Frequencies(test::ToOracle(s), 8);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(modes.modal.modes[i].frequency_hz, oracle[i], 1e-12 * oracle[i]) << "mode " << i;
  }
  // Order 1 at 4 elements per member against the oracle's Hermite elements at 16: measured
  // within 6e-9 ... 1.3e-7 for the six lowest modes, about the oracle's own h^4 error there.
  StructureDescription fine = s;
  for (StructureMember& m : fine.members) m.elements = 16;
  const Eigen::VectorXd converged = test::oracle::Frequencies(test::ToOracle(fine), 6);
  s.series_order = 1;
  const FrameModalResult series = SolveFrameModal(FrameModel(s), Count(6));
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(series.modal.modes[i].frequency_hz, converged[i], 5e-7 * converged[i])
        << "mode " << i;
  }
}

TEST(FrameModalTest, TheShuttleModeIsInPlaneBendingCarryingTheShuttlesMass) {
  const StructureDescription s = test::FoldedFlexure(kL, 6);
  const FrameModel model(s);
  const FrameModalResult modes = SolveFrameModal(model, Count(4));
  ASSERT_EQ(modes.modal.status, Status::kOk);
  // The shuttle's mode: the one moving most mass along x.
  std::size_t i = 0;
  for (std::size_t k = 1; k < modes.participation.size(); ++k) {
    if (modes.participation[k][0] > modes.participation[i][0]) i = k;
  }
  EXPECT_EQ(modes.modal.modes[i].kind, ModeKind::kBendingZ);  // the beams bend in the plane
  // Rayleigh (Tang 1989): the shuttle, a quarter of the trusses and 12/35 of the beams on
  // k = 24 E I / L^3.
  const double k = 24 * Poly().young_modulus * SquareSection().SecondMomentY() / (kL * kL * kL);
  const double beam = Poly().density * SquareSection().Area() * kL;
  const double shuttle = s.bodies[2].Mass(), trusses = s.bodies[0].Mass() + s.bodies[1].Mass();
  const double rayleigh =
      std::sqrt(k / (shuttle + trusses / 4 + 12.0 / 35.0 * 8 * beam)) / (2 * kPi);
  // The static shapes bound the frequency from above; here the beams weigh as much as the
  // shuttle, and the estimate stays within 1 %.
  EXPECT_LT(modes.modal.modes[i].frequency_hz, rayleigh);
  EXPECT_NEAR(modes.modal.modes[i].frequency_hz, rayleigh, 0.01 * rayleigh);
  const double total = shuttle + trusses + 8 * beam;
  EXPECT_GT(modes.participation[i][0], shuttle / total);
  EXPECT_LT(modes.participation[i][0], 1.0);
  EXPECT_LT(modes.participation[i][1], 1e-12);
}

TEST(FrameModalTest, ParticipationsSumToTheFreeMassOverAllModes) {
  StructureDescription s = LFrame();
  s.series_order = 0;
  const FrameModel model(s);
  const FrameModalResult modes = SolveFrameModal(model, Count(model.FreeDofCount()));
  const FrameRigidMotions rigid(model);
  for (int k = 0; k < 6; ++k) {
    double sum = 0.0;
    for (const auto& share : modes.participation) sum += share[k];
    const Eigen::VectorXd r = rigid.reduced.col(k);
    EXPECT_NEAR(sum, r.dot(model.Mass(0) * r) / rigid.total[k], 1e-9) << "direction " << k;
  }
  // The whole structure's mass: members' rho A L.
  const double mass =
      Poly().density * SquareSection().Area() * kL + Poly().density * 6e-12 * 0.6 * kL;
  EXPECT_NEAR(rigid.total[1] * model.units().Mass(), mass, 1e-12 * mass);
}

TEST(FrameModalTest, TheTorsionalMirrorRingsAtGJOverLAndThePlatesInertia) {
  StructureDescription s;
  const int a = AddNode(s, "left_anchor", {-kL - 50e-6, 0, 0}, Support::kClamped);
  const int l = AddNode(s, "left", {-50e-6, 0, 0});
  const int r = AddNode(s, "right", {50e-6, 0, 0});
  const int b = AddNode(s, "right_anchor", {kL + 50e-6, 0, 0}, Support::kClamped);
  AddBeam(s, a, l, 8);
  AddBeam(s, b, r, 8);
  AddBody(s, "mirror", {0, 0, 0}, {100e-6, 2e-6, 100e-6}, {l, r});
  const FrameModel model(s);
  const FrameModalResult modes = SolveFrameModal(model, Count(4));
  ASSERT_EQ(modes.modal.status, Status::kOk);
  const RectangularSection section = SquareSection();
  const double gj = Poly().ShearModulus() * section.TorsionConstant();
  const double plate = s.bodies[0].Mass() * (100e-6 * 100e-6 + 2e-6 * 2e-6) / 12;
  // The beams' own rotary inertia joins at a third (the linear twist's Rayleigh quotient).
  const double beams = 2 * Poly().density * section.PolarMoment() * kL / 3;
  const double expected = std::sqrt(2 * gj / kL / (plate + beams)) / (2 * kPi);
  const auto torsion = std::find_if(modes.modal.modes.begin(), modes.modal.modes.end(),
                                    [](const Mode& m) { return m.kind == ModeKind::kTorsion; });
  ASSERT_NE(torsion, modes.modal.modes.end());
  EXPECT_NEAR(torsion->frequency_hz, expected, 1e-6 * expected);
  const std::size_t i = torsion - modes.modal.modes.begin();
  EXPECT_GT(modes.participation[i][3], 0.9);  // a rotation about x
}

// A column standing along y under a compressive load at its top buckles at the load the
// BeamModel of the same cantilever finds (the same elements: round-off) and near Euler's.
TEST(FrameBucklingTest, ANetlistColumnBucklesAtTheBeamsLoad) {
  StructureDescription s;
  AddNode(s, "foot", {0, 0, 0}, Support::kClamped);
  AddNode(s, "top", {0, kL, 0});
  const RectangularSection section{3e-6, 2e-6};
  AddBeam(s, 0, 1, 10, section, Eigen::Vector3d::UnitX());
  const FrameBucklingResult column = SolveFrameBuckling(FrameModel(s), NodeLoad(1, {0, -1e-6, 0}));
  ASSERT_EQ(column.status, Status::kOk);
  const BucklingResult beam = SolveBuckling(
      BeamModel<3>(MakeStructure(StructureKind::kCantilever, kL, Poly(), section, 10, 1)));
  const double expected = beam.modes.at(0).critical_load_n;
  EXPECT_NEAR(column.critical_load_n, expected, 1e-9 * expected);
  EXPECT_NEAR(column.load_factor, expected / 1e-6, 1e-9 * expected / 1e-6);
  EXPECT_NEAR(column.axial_force_n[9], -1e-6, 1e-15);
  const double euler = kPi * kPi * Poly().young_modulus * section.SecondMomentZ() / (4 * kL * kL);
  EXPECT_NEAR(column.critical_load_n, euler, 1e-6 * euler);
}

// A netlist of the reference cantilever and the BeamModel of the same beam give the same
// statics and frequencies to round-off; rotated in the plane, translated or scaled, a frame
// gives the same relative answers.
TEST(FrameInvarianceTest, ANetlistCantileverIsTheBeamAndRigidMotionsChangeNothing) {
  StructureDescription s;
  AddNode(s, "root", {0, 0, 0}, Support::kClamped);
  AddNode(s, "middle", {0.4 * test::kReferenceLength, 0, 0});
  AddNode(s, "tip", {test::kReferenceLength, 0, 0});
  s.members.push_back({0, 1, test::Silicon(), test::ReferenceSection(), 8, {0, 1, 0}});
  s.members.push_back({1, 2, test::Silicon(), test::ReferenceSection(), 12, {0, 1, 0}});
  const FrameModel frame(s);
  const BeamModel<3> beam(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                        test::Silicon(), test::ReferenceSection(), 20, 1));
  // Its four fields decouple along x, and each is numbered on its own as the chain's are: the
  // same band, so the same cost per step.
  EXPECT_EQ(frame.FreeDofCount(), beam.FreeDofCount());
  EXPECT_EQ(frame.Stiffness().bandwidth(), beam.Stiffness().bandwidth());
  const FrameModalResult frame_modes = SolveFrameModal(frame, Count(6));
  const ModalResult beam_modes = SolveModal(beam, Count(6));
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(frame_modes.modal.modes[i].frequency_hz, beam_modes.modes[i].frequency_hz,
                1e-10 * beam_modes.modes[i].frequency_hz);
    EXPECT_EQ(frame_modes.modal.modes[i].kind, beam_modes.modes[i].kind);
  }
  const FrameStaticSolution frame_tip = SolveFrameStatic(frame, NodeLoad(2, {1e-7, -1e-6, 2e-7}));
  LoadCase beam_loads;
  beam_loads.points.push_back({test::kReferenceLength, {1e-7, -1e-6, 2e-7}, {0, 0, 0}});
  const BeamField<3> beam_tip(beam, SolveStatic(beam, beam_loads).displacement);
  const Eigen::Vector3d u = beam_tip.At(test::kReferenceLength).head<3>();
  EXPECT_NEAR((frame_tip.nodes[2].head<3>() - u).norm(), 0.0, 1e-10 * u.norm());

  // Turned 37 degrees about y, moved, and at 1/100 and 100 times the size.
  const StructureDescription l = LFrame();
  const Eigen::VectorXd reference = [&] {
    Eigen::VectorXd f(6);
    const FrameModalResult m = SolveFrameModal(FrameModel(l), Count(6));
    for (int i = 0; i < 6; ++i) f[i] = m.modal.modes[i].frequency_hz;
    return f;
  }();
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.6458, Eigen::Vector3d::UnitY()).toRotationMatrix();
  StructureDescription moved = l;
  for (StructureNode& n : moved.nodes)
    n.position = turn * n.position + Eigen::Vector3d(3e-5, 1e-6, -2e-5);
  const FrameModalResult turned = SolveFrameModal(FrameModel(moved), Count(6));
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(turned.modal.modes[i].frequency_hz, reference[i], 1e-10 * reference[i]);
  }
  const FrameStaticSolution straight =
      SolveFrameStatic(FrameModel(l), NodeLoad(2, {1e-7, -1e-6, 2e-7}));
  const FrameStaticSolution rotated =
      SolveFrameStatic(FrameModel(moved), NodeLoad(2, turn * Eigen::Vector3d(1e-7, -1e-6, 2e-7)));
  EXPECT_NEAR((rotated.nodes[2].head<3>() - turn * straight.nodes[2].head<3>()).norm(), 0.0,
              1e-10 * straight.nodes[2].head<3>().norm());
  for (double scale : {0.01, 100.0}) {
    StructureDescription sized = l;
    for (StructureNode& n : sized.nodes) n.position *= scale;
    for (StructureMember& m : sized.members) {
      m.section.width *= scale;
      m.section.thickness *= scale;
    }
    const FrameModalResult m = SolveFrameModal(FrameModel(sized), Count(6));
    for (int i = 0; i < 6; ++i) {
      EXPECT_NEAR(m.modal.modes[i].frequency_hz * scale, reference[i], 1e-10 * reference[i]);
    }
  }
}

}  // namespace
}  // namespace cosmems
