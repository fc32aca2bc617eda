// The haptic scene's steps allocate nothing: contact, stiction, the Casimir force and the gas
// film composed at compile time, through a press that makes the tip touch and stick and a pull
// that peels it off (the multiplier updates, the compliance factorisation of the peel test and
// the adaptive quadrature all run within the counted steps).
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/beam/force_tuple.hpp"
#include "cosmems/structure/serpentine.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/frame_squeeze_film.hpp"
#include "cosmems/surface/gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/surface/squeeze_film.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "cosmems/time/modal_model.hpp"
#include "cosmems/time/nonlinear_modal_integrator.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "cosmems/time/voltage_drive.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

constexpr double kGap = 2e-6;

// Contact with stiction on a plane 20 nm above the substrate (asperities).
ContactOptions StickyContact() {
  ContactOptions contact;
  contact.gap = kGap;
  contact.separation = 2e-8;
  contact.stiction = true;
  contact.adhesion_energy = 0.02;
  return contact;
}

GapForce<2, CasimirPressure> Casimir(const BeamModel<2>& model, const ContactOptions& contact) {
  return GapForce<2, CasimirPressure>(
      model, CasimirPressure{},
      GapSpan{kGap, 0.0, test::kReferenceLength}.WithSeparation(contact.separation));
}

// The hand's tip force at step i, in closing forces (3 EI / L^3 times the gap): 40 steps down to
// three, 40 up to five the other way. The tip, stuck alone, lets go near three, where its energy
// release rate p^2 theta / b reaches Gamma (SubstrateContact).
double PressAndPull(int step) {
  return step < 40 ? -3.0 * step / 40.0 : -3.0 + 8.0 * (step - 40) / 40.0;
}

TEST(SurfaceNoAllocationTest, PressStickAndPeelStepsAllocateNothing) {
  const BeamModel<2> model = test::PlanarCantilever(test::kReferenceLength, 20);
  const ContactOptions contact = StickyContact();
  ForceTuple<SubstrateContact<2>, GapForce<2, CasimirPressure>, SqueezeFilm<2>> forces(
      SubstrateContact<2>(model, contact), Casimir(model, contact),
      SqueezeFilm<2>(model, SqueezeFilmOptions{}, kGap, contact.separation));
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, forces,
                                        GeneralizedAlphaParameters::FromSpectralRadius(0.0),
                                        1e-4 / model.units().time);
  const int n = model.FreeDofCount();
  const int tip = model.dofs().Reduced(20, NodalDof::kUy);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  ASSERT_EQ(integrator.Initialize(f, f, f), Status::kOk);
  const double closing = 0.845 * kGap / model.units().force;  // 3 EI / L^3 times the gap
  int step = 0;
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(80,
                                    [&] {
                                      f[tip] = closing * PressAndPull(step);
                                      ++step;
                                      if (status == Status::kOk) status = integrator.Step(f);
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
  const ContactEvents& events = forces.get<0>().events();
  EXPECT_GE(events.stuck, 1);
  EXPECT_GE(events.releases, 1);
}

// The modal path through the same press, stick and peel (contact, stiction and the Casimir
// force; the gas film is the Newmark family's): Newton's dense factorisations, the multiplier
// updates, the peel test and the velocity's projection and fit all run within the counted steps.
TEST(SurfaceNoAllocationTest, ModalPressStickAndPeelStepsAllocateNothing) {
  const BeamModel<2> model = test::PlanarCantilever(test::kReferenceLength, 20);
  const ContactOptions contact = StickyContact();
  ForceTuple<SubstrateContact<2>, GapForce<2, CasimirPressure>> forces(
      SubstrateContact<2>(model, contact), Casimir(model, contact));
  ModalOptions four;
  four.count = 4;
  const ModalModel modal = MakeModalModel(model, SolveModal(model, four), DampingModel{});
  const int n = model.FreeDofCount();
  const int tip = model.dofs().Reduced(20, NodalDof::kUy);
  Eigen::VectorXd pattern = Eigen::VectorXd::Zero(n);
  pattern[tip] = 0.845 * kGap / model.units().force;  // the closing force, 3 EI / L^3 times the gap
  NonlinearModalIntegrator integrator(model, modal, pattern, forces, 1e-4 / model.units().time);
  Eigen::VectorXd s = Eigen::VectorXd::Zero(1);
  ASSERT_EQ(integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), s),
            Status::kOk);
  int step = 0;
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(80,
                                    [&] {
                                      s[0] = PressAndPull(step);
                                      ++step;
                                      if (status == Status::kOk) status = integrator.Step(s);
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
  const ContactEvents& events = forces.get<0>().events();
  EXPECT_GE(events.stuck, 1);
  EXPECT_GE(events.releases, 1);
}

// The modal path on 140 elements, over 400 rows: past the size at which a blocked dense
// factorisation would take its workspace from the heap (Eigen's LLT did: 345 allocations in
// these 80 steps). The tip pressed to 0.8 of the closing force and back under the Casimir pressure,
// Newton refactoring at every iteration (reuse_contraction 0) so that every step factors: a beam
// this fine does not take the touchdown on the modal path (doc/hard_cases.md).
TEST(SurfaceNoAllocationTest, ModalStepsOfALargeModelAllocateNothing) {
  const int elements = 140;
  const BeamModel<2> model = test::PlanarCantilever(test::kReferenceLength, elements);
  const int n = model.FreeDofCount();
  ASSERT_GT(n, 400);
  GapForce<2, CasimirPressure> casimir = Casimir(model, StickyContact());
  ModalOptions four;
  four.count = 4;
  const ModalModel modal = MakeModalModel(model, SolveModal(model, four), DampingModel{});
  Eigen::VectorXd pattern = Eigen::VectorXd::Zero(n);
  pattern[model.dofs().Reduced(elements, NodalDof::kUy)] = 0.845 * kGap / model.units().force;
  NewtonOptions plain;
  plain.reuse_contraction = 0.0;
  NonlinearModalIntegrator integrator(model, modal, pattern, casimir, 1e-4 / model.units().time,
                                      plain);
  Eigen::VectorXd s = Eigen::VectorXd::Zero(1);
  ASSERT_EQ(integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), s),
            Status::kOk);
  int step = 0;
  Status status = Status::kOk;
  long factorizations = 0;
  EXPECT_EQ(test::AllocationsDuring(80,
                                    [&] {
                                      s[0] = -0.8 * (step < 40 ? step : 80 - step) / 40.0;
                                      ++step;
                                      if (status == Status::kOk) status = integrator.Step(s);
                                      factorizations += integrator.last_stats().factorizations;
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
  EXPECT_GE(factorizations, 80);
}

// The serpentine plate of one turn and one element per segment (54 free dofs), and an
// electrode under its plate.
StructureDescription SmallSerpentine() {
  SerpentineDesign design;
  design.turns = 1;
  design.elements = 1;
  return Serpentine(design);
}
FrameGapOptions UnderThePlate() {
  FrameGapOptions electrodes;
  electrodes.gap = kGap;
  electrodes.electrodes = {Electrode{{-50e-6, 50e-6}, {-50e-6, 50e-6}}};
  return electrodes;
}

// Fifty steps of 0.1 us from rest (n free dofs), the electrodes' pressure rescaled to V(t)^2 before
// each, allocate nothing and all succeed.
void ExpectDrivenStepsAllocateNothing(BeamStepper& stepper, int n,
                                      FrameGapForce<ElectrostaticPressure>& pressure,
                                      const VoltageDrive& drive) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd s = Eigen::VectorXd::Zero(1);
  pressure.SetScale(drive.SquaredAt(0.0));
  ASSERT_EQ(stepper.Initialize(zero, zero, s), Status::kOk);
  int step = 0;
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(50,
                                    [&] {
                                      ++step;
                                      pressure.SetScale(drive.SquaredAt(step * 1e-7));
                                      if (status == Status::kOk) status = stepper.Step(s);
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
}

// A device's steps under an alternating electrode voltage allocate nothing: the serpentine plate
// over its electrode, its pressure rescaled to V(t)^2 before every step (FrameGapForce), Newton
// on the frame's band within the counted steps, on both time paths.
TEST(SurfaceNoAllocationTest, ADeviceDrivenByAnAlternatingVoltageStepsWithoutAllocating) {
  const FrameModel model(SmallSerpentine());
  const FrameGapOptions electrodes = UnderThePlate();
  const VoltageDrive drive{8.0, 2.0, 1e5};
  for (const TimePath path : {TimePath::kNewmarkFamily, TimePath::kModal}) {
    SCOPED_TRACE(path == TimePath::kModal ? "modal" : "newmark");
    FrameGapForce<ElectrostaticPressure> pressure(model, ElectrostaticPressure{1.0, 0.0, false},
                                                  electrodes);
    StepperOptions options;
    options.path = path;
    options.time_step = 1e-7;
    options.modes = 4;
    const int n = model.FreeDofCount();
    const BeamStepperSetup setup =
        MakeBeamStepper(model, options, Eigen::MatrixXd::Zero(n, 1), &pressure);
    ASSERT_EQ(setup.status, Status::kOk);
    ExpectDrivenStepsAllocateNothing(*setup.stepper, n, pressure, drive);
  }
}

// The surface forces under a device allocate nothing either: the serpentine plate over its
// electrode at an alternating voltage, with the Casimir pressure under all of it and the gas film
// under its members (strips) and its plate (Reynolds' plate), stepped by Newton in the Newmark
// family (the film's path).
TEST(SurfaceNoAllocationTest, ADeviceOnItsGasFilmStepsWithoutAllocating) {
  const FrameModel model(SmallSerpentine());
  const FrameGapOptions electrodes = UnderThePlate();
  FrameGapForce<ElectrostaticPressure> pressure(model, ElectrostaticPressure{1.0, 0.0, false},
                                                electrodes);
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{}, FrameGapOptions{kGap});
  FrameSqueezeFilm film(model, SqueezeFilmOptions{1.81e-5, 68e-9}, kGap);
  ForceSum forces;
  for (NonlinearForce* f : std::initializer_list<NonlinearForce*>{&pressure, &casimir, &film}) {
    forces.Add(*f);
  }
  const VoltageDrive drive{8.0, 2.0, 1e5};
  StepperOptions options;
  options.time_step = 1e-7;
  const int n = model.FreeDofCount();
  const BeamStepperSetup setup =
      MakeBeamStepper(model, options, Eigen::MatrixXd::Zero(n, 1), &forces);
  ASSERT_EQ(setup.status, Status::kOk);
  ExpectDrivenStepsAllocateNothing(*setup.stepper, n, pressure, drive);
}

}  // namespace
}  // namespace cosmems
