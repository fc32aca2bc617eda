#pragma once

// Free vibration of the reference cantilever by the linear Newmark path, with its energy tracked
// at every step: shared by the hard-case unit test (short runs) and bench/hard_cases_bench.cpp
// (long runs of 1000 elements at 1 ns, and every member at the extreme steps).

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "test_beams.hpp"

namespace cosmems::test {

struct ReleaseRun {
  Status status = Status::kOk;  ///< of the initialisation or of the first failed step
  long steps = 0;               ///< steps taken
  /// (1/2) v^T M v + (1/2) d^T K d relative to its initial value (all strain): the largest over
  /// the run and the last.
  double max_energy_ratio = 1.0;
  double final_energy_ratio = 1.0;
  double max_tip_ratio = 1.0;  ///< the largest |u_y| at the tip over its initial value
  bool finite = true;          ///< every state of every step
};

/// The reference cantilever of `elements` planar elements (series order 1) released at rest from
/// its static deflection under a tip force of 0.1 uN, advanced `steps` steps of `time_step` [s]
/// with `parameters`. With no load after the release the energy can only stay (average
/// acceleration) or fall (the dissipative members), and since the static tip-load shape holds
/// the least strain energy for its tip deflection, |u_tip| cannot pass its initial value
/// either.
inline ReleaseRun RunReleasedCantilever(int elements, const GeneralizedAlphaParameters& parameters,
                                        double time_step, long steps) {
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, kReferenceLength, Silicon(),
                                         ReferenceSection(), elements, 1));
  LoadCase tip;
  tip.points.push_back(
      {kReferenceLength, Eigen::Vector3d(0.0, -1e-7, 0.0), Eigen::Vector3d::Zero()});
  const BandCholesky stiffness(model.Stiffness());
  const Eigen::VectorXd d0 = stiffness.Solve(AssembleLoads(model, tip));
  const int n = model.FreeDofCount();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, parameters,
                                     time_step / model.units().time);
  ReleaseRun run;
  run.status = integrator.Initialize(d0, zero, zero);
  if (run.status != Status::kOk) return run;
  const OutputPoint output = OutputPoint::DeflectionAt(model, kReferenceLength);
  const double tip0 = std::abs(output.Evaluate(d0));
  Eigen::VectorXd mv(n), kd(n);
  auto energy = [&] {
    model.Mass(0).Multiply(integrator.velocity(), mv);
    model.Stiffness().Multiply(integrator.displacement(), kd);
    return 0.5 * (integrator.velocity().dot(mv) + integrator.displacement().dot(kd));
  };
  const double e0 = energy();
  for (long i = 0; i < steps; ++i) {
    run.status = integrator.Step(zero);
    if (run.status != Status::kOk) break;
    ++run.steps;
    run.finite =
        run.finite && integrator.displacement().allFinite() && integrator.velocity().allFinite();
    run.final_energy_ratio = energy() / e0;
    run.max_energy_ratio = std::max(run.max_energy_ratio, run.final_energy_ratio);
    run.max_tip_ratio =
        std::max(run.max_tip_ratio, std::abs(output.Evaluate(integrator.displacement())) / tip0);
  }
  return run;
}

}  // namespace cosmems::test
