#pragma once

// Stick-release cycles of the hard-case suite, shared by its unit test (10^3 cycles) and
// bench/hard_cases_bench.cpp (10^5). Each cycle lays the reference cantilever flat on the
// substrate, lets go (it peels back to the S shape the adhesion holds), lifts it off with an
// upward load and lets it come to rest: one stuck event and one release a cycle, and the same
// states every cycle if nothing drifts.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "test_beams.hpp"

namespace cosmems::test {

/// The cycle's beam and surface: the reference cantilever 2 um above the substrate, adhesion
/// 0.02 J/m^2 (an S shape of free span (3 E t^3 g^2 / (2 Gamma))^(1/4) = 142 um).
inline constexpr double kCycleGap = 2e-6;
inline constexpr double kCycleAdhesion = 0.02;
/// The uniform loads of a cycle in units of 8 EI g / L^4, the load that bends the free tip by
/// the gap: 200 lays the beam flat (as in the contact tests), 10 peels it off again.
inline constexpr double kPressLoad = 200.0;
inline constexpr double kLiftLoad = 10.0;

/// The script of one cycle, in steps of 100 us (seven periods of the first mode each): the
/// press ramped in over two steps and held for two, three steps without load (the beam peels
/// back to its S shape), the lift ramped in over three steps, five steps at rest.
struct CyclePhases {
  static constexpr int kPress = 4;
  static constexpr int kLetGo = 3;
  static constexpr int kLift = 3;
  static constexpr int kRest = 5;
  static constexpr int kSteps = kPress + kLetGo + kLift + kRest;
};

struct StickReleaseRun {
  Status status = Status::kOk;  ///< of the first step that failed (the run stops there)
  long cycles = 0;              ///< cycles completed
  long steps = 0;
  long iterations = 0;  ///< Newton iterations over all steps
  long cuts = 0;        ///< step halvings over all steps
  ContactEvents events;
  double first_span_m = 0.0;  ///< free span of the S shape, first cycle
  double span_drift_m = 0.0;  ///< its largest change over the later cycles
  /// The largest |u_y| difference of any node between the end of a cycle and the end of the
  /// first one [m].
  double end_drift_m = 0.0;
  double first_max_energy_j = 0.0;      ///< largest (1/2) v^T M v + (1/2) d^T K d, first cycle
  double max_energy_j = 0.0;            ///< the same over all cycles
  double min_cycle_max_energy_j = 0.0;  ///< the smallest of the cycles' largest energies
  /// q^2 L^5 / (40 EI): the free cantilever's static energy under the lift load q.
  double lift_energy_j = 0.0;
  bool finite = true;  ///< every state of every step
};

/// Runs `cycles` stick-release cycles of the reference cantilever of `elements` planar
/// elements, by the nonlinear Newmark path with generalised-alpha at rho_inf = 0 (the haptic
/// path's member: it annihilates what 100 us steps do not resolve).
inline StickReleaseRun RunStickReleaseCycles(int elements, long cycles) {
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, kReferenceLength, Silicon(),
                                         ReferenceSection(), elements, 0));
  ContactOptions options;
  options.gap = kCycleGap;
  options.stiction = true;
  options.adhesion_energy = kCycleAdhesion;
  SubstrateContact<2> contact(model, options);
  const UnitSystem& u = model.units();
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, contact,
                                        GeneralizedAlphaParameters::FromSpectralRadius(0.0),
                                        1e-4 / u.time);
  const int n = model.FreeDofCount();
  const double ei = Silicon().young_modulus * ReferenceSection().SecondMomentZ();
  const double closing = 8.0 * ei * kCycleGap / std::pow(kReferenceLength, 4);  // N/m
  LoadCase press, lift;
  press.distributed = Eigen::Vector3d(0.0, -kPressLoad * closing, 0.0);
  lift.distributed = Eigen::Vector3d(0.0, kLiftLoad * closing, 0.0);
  const Eigen::VectorXd f_press = AssembleLoads(model, press);
  const Eigen::VectorXd f_lift = AssembleLoads(model, lift);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::VectorXd> script;
  for (int i = 1; i <= CyclePhases::kPress; ++i) {
    script.push_back(f_press * std::min(1.0, i / 2.0));
  }
  for (int i = 0; i < CyclePhases::kLetGo; ++i) script.push_back(zero);
  for (int i = 1; i <= CyclePhases::kLift; ++i) {
    script.push_back(f_lift * (static_cast<double>(i) / CyclePhases::kLift));
  }
  for (int i = 0; i < CyclePhases::kRest; ++i) script.push_back(zero);

  std::vector<int> uy;  // reduced u_y of every free node
  for (int node = 0; node < model.NodeCount(); ++node) {
    const int dof = model.dofs().Reduced(node, NodalDof::kUy);
    if (dof >= 0) uy.push_back(dof);
  }
  StickReleaseRun run;
  const double q = kLiftLoad * closing;
  run.lift_energy_j = q * q * std::pow(kReferenceLength, 5) / (40.0 * ei);
  run.status = integrator.Initialize(zero, zero, zero);
  Eigen::VectorXd mv(n), kd(n), first_end;
  const double energy_unit = u.force * u.length;
  for (long cycle = 0; cycle < cycles && run.status == Status::kOk; ++cycle) {
    double cycle_max = 0.0;
    for (std::size_t s = 0; s < script.size(); ++s) {
      run.status = integrator.Step(script[s]);
      ++run.steps;
      run.iterations += integrator.last_stats().evaluations;
      run.cuts += integrator.last_stats().cuts;
      if (run.status != Status::kOk) break;
      const Eigen::VectorXd& d = integrator.displacement();
      const Eigen::VectorXd& v = integrator.velocity();
      run.finite = run.finite && d.allFinite() && v.allFinite();
      model.Mass(0).Multiply(v, mv);
      model.Stiffness().Multiply(d, kd);
      cycle_max = std::max(cycle_max, 0.5 * (v.dot(mv) + d.dot(kd)) * energy_unit);
      if (s + 1 == CyclePhases::kPress + CyclePhases::kLetGo) {  // let go: the S shape
        const double span = contact.Summary().detached_length_m;
        if (cycle == 0) run.first_span_m = span;
        run.span_drift_m = std::max(run.span_drift_m, std::abs(span - run.first_span_m));
      }
    }
    if (run.status != Status::kOk) break;
    const Eigen::VectorXd& d = integrator.displacement();
    if (cycle == 0) {
      first_end = d;
      run.first_max_energy_j = cycle_max;
      run.min_cycle_max_energy_j = cycle_max;
    }
    for (const int dof : uy) {
      run.end_drift_m = std::max(run.end_drift_m, std::abs(d[dof] - first_end[dof]) * u.length);
    }
    run.max_energy_j = std::max(run.max_energy_j, cycle_max);
    run.min_cycle_max_energy_j = std::min(run.min_cycle_max_energy_j, cycle_max);
    ++run.cycles;
  }
  run.events = contact.events();
  return run;
}

}  // namespace cosmems::test
