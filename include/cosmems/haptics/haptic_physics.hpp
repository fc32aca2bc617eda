#pragma once

#include <Eigen/Core>

#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/haptics/haptic_frame.hpp"
#include "cosmems/haptics/local_model.hpp"
#include "cosmems/time/damping_model.hpp"
#include "cosmems/time/stepper_options.hpp"

namespace cosmems {

/// How the physics advances between two servo ticks.
struct HapticPhysicsOptions {
  double tick_s = 1e-3;  ///< simulated time per Advance() (the servo period)
  /// Implicit steps per tick; 0, the default, takes the path's (Substeps()). The reference
  /// cantilever's first mode (68.8 kHz) is far above the servo rate, so the steps do not resolve
  /// it whatever their number: the hand feels the quasi-static beam. Fewer are faster
  /// (bench/surface_tick_bench.cpp; the figures are in doc/surface.md and doc/speed.md).
  int substeps = 0;
  /// Generalised-alpha's spectral radius: 0 annihilates the unresolved vibrations (the hand
  /// feels the quasi-static structure, as it would the real one) and adds no energy at impacts.
  double rho_inf = 0.0;
  /// The time path (analysis.integrator = "modal" with model.modes): the Newmark family on the
  /// full model, or `modes` modes with the forces held over each step and the truncated modes
  /// answering statically.
  TimePath path = TimePath::kNewmarkFamily;
  int modes = 0;
  /// The modal path's damping, as ratios of the modes (the real device's quality factor): exact
  /// propagation keeps every mode it does not damp ringing under the hand. The full path leaves
  /// it out (rho_inf removes what the ticks do not resolve).
  DampingModel damping;
  /// Newton's residual tolerance in each step (NewtonOptions::residual_tolerance). The hand feels
  /// the force, not the residual: at 1e-6 of the terms the residual balances, the probe's force
  /// on the resonator pressed onto the substrate with contact, stiction and the Casimir force
  /// stayed within 2.2e-5 of its largest value of the 1e-10 solve's, tick by tick, with the same
  /// events (tests/haptics/haptic_structure_test.cpp), far below what a device renders, and a
  /// pressed step takes one Newton correction where 1e-10 takes two (doc/speed.md).
  double residual_tolerance = 1e-6;
  /// The contraction Newton's kept factor must have shown to serve again on the full model's
  /// path (NewtonOptions::reuse_contraction; 1e-3 elsewhere, the modal path's too, where the
  /// driver never undoes a correction: NonlinearModalIntegrator). A haptic step starts from the
  /// last one's solution and its tangent barely moves between ticks, so a factor that cut the
  /// residual tenfold serves on: the resonator pressed onto the substrate with contact, stiction
  /// and the Casimir force factored in 9 of 1000 ticks where 1e-3 factored in 16 (doc/speed.md). A
  /// kept factor's correction that leaves a force's domain or throws the residual up a thousandfold
  /// is undone (NewtonDriver), so the looser rule cannot carry a landing through the substrate.
  double reuse_contraction = 0.1;
  /// On the full model's path, a kept factor's correction below this share of the iterate, which
  /// that factor's last contraction (doubled at each such end since it was measured) predicts to
  /// leave the residual within a tenth of residual_tolerance, ends the tick's iterations without a
  /// last evaluation (NewtonOptions::predicted_increment_tolerance; 0 elsewhere, the modal path's
  /// too). Most ticks then take one evaluation instead of two: the pressed resonator with
  /// contact, stiction and the Casimir force took 1163 evaluations in 1000 ticks where 1634
  /// confirmed every tick, its forces the same to the last bit (tests/haptics/
  /// haptic_structure_test.cpp; doc/speed.md). 0: every tick ends on an evaluation.
  double predicted_increment_tolerance = 1e-6;

  void Validate() const {
    RequirePositive("tick_s", tick_s);
    RequireWithin("substeps", substeps, 0, 10000);
    RequireWithin("rho_inf", rho_inf, 0.0, 1.0);
    RequireWithin("residual_tolerance", residual_tolerance, 1e-14, 1e-3);
    RequireWithin("reuse_contraction", reuse_contraction, 0.0, 0.5);
    RequireWithin("predicted_increment_tolerance", predicted_increment_tolerance, 0.0, 1e-3);
    if (path == TimePath::kModal) RequireWithin("modes", modes, 1, 10000);
  }

  /// The steps a tick takes: `substeps`, or where it is 0 the path's. One on the full model: the
  /// resonator pressed onto the substrate with contact, stiction and Casimir feels within 4.2e-6
  /// of its largest force at 8 steps and a tolerance of 1e-10, outside the tick it lands in (2
  /// steps: 1.5e-7), and its landing tick differs by 1.3e-2 at 1, 2 and 4 steps alike. Two on
  /// the modal path, whose forces are held over a step: at one, a shuttle landing on the
  /// substrate chattered (three contacts where two steps make one).
  int Substeps() const {
    if (substeps > 0) return substeps;
    return path == TimePath::kModal ? 2 : 1;
  }
};

/// What the hand touches, as the HapticLoop ticks it (HapticStructure; a test's stand-in).
/// Advance() places the probe and advances the physics by tick_s; after it the physics holds the
/// LocalModel the servo loop renders. Advance() and Fill() allocate nothing and report a failure as
/// a status; a failed tick leaves the structure where it was and the local model invalid (the
/// safety layer then brings the force to zero).
class HapticPhysics {
 public:
  virtual ~HapticPhysics() = default;

  /// One tick: the probe moves to `probe_m` [m, the structure's axes] (where the hand put it at
  /// device time `source_time_s`) and the structure advances by tick_s.
  virtual Status Advance(const Eigen::Vector3d& probe_m, double source_time_s) = 0;
  /// The paper's "Reset Failure": the undeformed structure at rest, nothing stuck (events are
  /// kept). May allocate: call it outside the servo thread when threads are split (HapticLoop
  /// does).
  virtual Status Reset() = 0;

  virtual const LocalModel& local_model() const = 0;
  /// Simulated time one Advance() covers [s].
  virtual double tick_s() const = 0;
  /// The structure's free degrees of freedom.
  virtual int DofCount() const = 0;

  /// A frame sized for this structure (allocates: call once).
  virtual HapticFrame MakeFrame() const = 0;
  /// Copies the current state into a frame from MakeFrame(); allocates nothing.
  virtual void Fill(HapticFrame& frame) const = 0;
};

}  // namespace cosmems
