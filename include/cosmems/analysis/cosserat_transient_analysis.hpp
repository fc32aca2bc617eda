#pragma once

#include <stdexcept>

#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/analysis/transient_options.hpp"
#include "cosmems/analysis/transient_recorder.hpp"
#include "cosmems/analysis/transient_result.hpp"
#include "cosmems/rod/cosserat_rod.hpp"
#include "cosmems/rod/rod_loads.hpp"
#include "cosmems/time/cosserat_newmark_integrator.hpp"

namespace cosmems {

/// A transient run of a Cosserat rod under `loads` (SI; one pattern times the time function),
/// by CosseratNewmarkIntegrator with options.parameters, recording uy at options.output_x. A
/// static start solves the rod's large-deflection statics under the loads and releases it from
/// there at rest. The rod has no damping model and no modes to propagate: options asking for
/// either are refused (std::invalid_argument naming the field).
inline TransientResult RunCosseratTransient(const CosseratRod& rod, const RodLoads& loads,
                                            const TransientOptions& options) {
  options.Validate();
  if (options.path == TimePath::kModal) {
    throw std::invalid_argument(
        "analysis.integrator = \"modal\": a Cosserat rod has no modes to propagate; it needs a "
        "Newmark-family integrator");
  }
  if (options.damping.kind != DampingModel::Kind::kNone) {
    throw std::invalid_argument("effects.damping: not available for a Cosserat rod");
  }
  TransientRecorder recorder(options, rod.description().Length());
  TransientResult result;
  RodState start = rod.UndeformedState();
  if (options.start_static) {
    CosseratStaticSolver statics(rod);
    result.status = statics.Solve(loads);
    if (result.status != Status::kOk) return result;
    start = statics.state();
  }
  CosseratNewmarkIntegrator integrator(rod, options.parameters, options.time_step);
  const RodLoads none = RodLoads::None(rod.NodeCount());
  RodLoads now = none;
  RodLoads::Interpolate(none, loads, options.Amplitude(0), now);
  result.status = integrator.Initialize(start, now);
  if (result.status != Status::kOk) return result;
  recorder.Run(
      result,
      [&](long i) {
        RodLoads::Interpolate(none, loads, options.Amplitude(i), now);
        return integrator.Step(now);
      },
      [&] { return rod.DisplacementAt(integrator.state(), options.output_x).y(); });
  recorder.Finish(result);
  return result;
}

}  // namespace cosmems
