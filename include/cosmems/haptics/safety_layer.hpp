#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cosmems/haptics/device_types.hpp"

namespace cosmems {

/// Limits every force any backend sends (haptics-notes: clamp, slew, ramp-in, zero on faults,
/// time-domain passivity). Rates are per second; the layer works on the device's nominal period.
struct SafetyOptions {
  double force_limit_n = 0.0;         ///< 0: the device's continuous force (motors stay cool)
  double slew_limit_n_per_s = 100.0;  ///< largest change of force: 0.1 N a tick at 1 kHz; 1 to 1e6
  double ramp_in_s = 0.5;         ///< force scale 0 -> 1 after start and after every fault; <= 60
  double max_model_age_s = 0.01;  ///< an older force (stale physics) is replaced by zero; <= 1
  bool passivity_control = true;  ///< Hannaford & Ryu's observer and variable damper
  /// Most energy the passivity observer banks [J]; 0: the force limit times the usable
  /// workspace's diagonal, the most a passive world rendered within the limits could return.
  double passivity_energy_limit_j = 0.0;

  /// Throws std::invalid_argument naming the field and its value.
  void Validate() const {
    auto require = [](bool ok, const char* field, double value) {
      if (!ok) {
        throw std::invalid_argument(std::string("safety.") + field + " = " + std::to_string(value) +
                                    " is out of range");
      }
    };
    require(std::isfinite(force_limit_n) && force_limit_n >= 0.0, "force_limit_n", force_limit_n);
    // From 1 N/s (a stop takes a desk device's peak force down in seconds, not hours) to 1e6
    // N/s (any force within a tick: no slew limit at all).
    require(slew_limit_n_per_s >= 1.0 && slew_limit_n_per_s <= 1e6, "slew_limit_n_per_s",
            slew_limit_n_per_s);
    require(ramp_in_s >= 0.0 && ramp_in_s <= 60.0, "ramp_in_s", ramp_in_s);
    // An infinite age limit would render a stalled physics thread's last force for ever; a
    // model a second old is no longer a rendering of the hand's touch.
    require(max_model_age_s > 0.0 && max_model_age_s <= 1.0, "max_model_age_s", max_model_age_s);
    require(std::isfinite(passivity_energy_limit_j) && passivity_energy_limit_j >= 0.0,
            "passivity_energy_limit_j", passivity_energy_limit_j);
  }
};

/// The device states the layer accepts: beyond these a reading is a fault, not a motion. They
/// lie orders of magnitude past any desk device (workspaces of tenths of a metre, hand speeds of
/// a few m/s) and keep every product the layer forms (f.v dt, alpha v) far from overflow.
struct StateBounds {
  static constexpr double kMaxPositionM = 100.0;
  static constexpr double kMaxSpeedMS = 1000.0;
  /// Smaller components are taken as zero: a denormal squared underflows, and a damper divided
  /// by it would be infinite.
  static constexpr double kNegligible = 1e-150;
};

/// How often the safety layer stepped in, and the largest force it let through.
struct SafetyCounters {
  long clamped = 0;                ///< force above the limit, scaled down to it
  long slew_limited = 0;           ///< change above the slew limit, cut to it
  long ramp_ticks = 0;             ///< ticks with the ramp-in scale below 1
  long non_finite_states = 0;      ///< NaN or infinite position or velocity from the device
  long out_of_range_states = 0;    ///< finite position or velocity beyond StateBounds
  long non_finite_forces = 0;      ///< NaN or infinite force from the client
  long stale_forces = 0;           ///< invalid, too old or negative-age force from the client
  long device_faults = 0;          ///< force errors the device reported
  long passivity_activations = 0;  ///< ticks the passivity controller added damping
  long output_guards = 0;          ///< outputs the last guard replaced (none if the layer is right)
  long ramp_down_ticks = 0;        ///< ticks spent bringing the force to zero at a stop
  long uncalibrated_ticks = 0;     ///< ticks the force was held at zero for want of calibration
  double max_force_n = 0.0;        ///< largest force commanded
};

/// The filter between a servo client and the device. Every output is finite, no larger than
/// force_limit(), and differs from the previous output by at most slew_per_tick(), whatever the
/// inputs: they are sanitised before any arithmetic (non-finite or out-of-range states and
/// forces are faults, negligible components zero), and a last guard checks the output itself.
/// A fault drives the force to zero along the slew limit rather than dropping it; so does a stop
/// (RampDown()). The passivity observer books the force actually sent. Allocation-free; one
/// instance per servo loop.
class SafetyLayer {
 public:
  SafetyLayer(const SafetyOptions& options, const DeviceSpecs& specs)
      : options_(options), period_s_(1.0 / specs.nominal_rate_hz) {
    options.Validate();
    const double device_limit = std::min(specs.max_force_n, specs.max_continuous_force_n);
    limit_n_ = options.force_limit_n > 0.0 ? std::min(options.force_limit_n, specs.max_force_n)
                                           : device_limit;
    max_damping_ = specs.max_damping_ns_per_m;
    // A workspace the device does not report leaves a unit of length: a desk device's reach is
    // a few tenths of a metre, so the ceiling is then looser, never absent.
    const double reach_m = (specs.workspace_max_m - specs.workspace_min_m).norm();
    energy_limit_j_ = options.passivity_energy_limit_j > 0.0
                          ? options.passivity_energy_limit_j
                          : limit_n_ * (reach_m > 0.0 && std::isfinite(reach_m) ? reach_m : 1.0);
    // Servo rates from 100 Hz to 10 kHz: the haptic range, and a stop's ramp a countable number
    // of ticks.
    if (!(limit_n_ > 0.0 && std::isfinite(limit_n_)) ||
        !(specs.nominal_rate_hz >= 100.0 && specs.nominal_rate_hz <= 1e4) ||
        !(max_damping_ >= 0.0 && std::isfinite(max_damping_))) {
      throw std::invalid_argument(
          "device specs: max_force_n = " + std::to_string(specs.max_force_n) +
          ", nominal_rate_hz = " + std::to_string(specs.nominal_rate_hz) +
          ", max_damping_ns_per_m = " + std::to_string(specs.max_damping_ns_per_m) +
          " give no usable limit");
    }
  }

  double force_limit() const { return limit_n_; }
  double slew_per_tick() const { return options_.slew_limit_n_per_s * period_s_; }
  double period() const { return period_s_; }
  /// The passivity observer's ceiling [J] (SafetyOptions::passivity_energy_limit_j).
  double passivity_energy_limit() const { return energy_limit_j_; }
  const SafetyCounters& counters() const { return counters_; }
  const Eigen::Vector3d& last_output() const { return output_; }
  /// The most ticks RampDown() needs to bring any output to zero.
  long MaxRampDownTicks() const {
    return static_cast<long>(std::ceil(limit_n_ / slew_per_tick())) + 1;
  }

  /// Whether a device state may be shown to a client: finite and within StateBounds.
  static bool Usable(const DeviceState& state) {
    Eigen::Vector3d unused;
    return Sanitise(state.position_m, StateBounds::kMaxPositionM, unused) == Reading::kOk &&
           Sanitise(state.velocity_m_s, StateBounds::kMaxSpeedMS, unused) == Reading::kOk;
  }

  /// Starts over from zero force: ramp-in and the passivity observer restart (the counters stay).
  void Restart() {
    output_.setZero();
    ramp_ = 0.0;
    energy_j_ = 0.0;
  }

  /// The force to send at this tick, given the device state and the client's command.
  Eigen::Vector3d Filter(const DeviceState& state, const ForceCommand& command) noexcept {
    Eigen::Vector3d position, velocity, force;
    bool fault = false;
    const Reading p = Sanitise(state.position_m, StateBounds::kMaxPositionM, position);
    const Reading v = Sanitise(state.velocity_m_s, StateBounds::kMaxSpeedMS, velocity);
    // The command may be any finite size: only a non-finite one is a fault (a huge force is
    // clamped), so its bound is the largest double.
    const Reading f = Sanitise(command.force_n, std::numeric_limits<double>::max(), force);
    if (p == Reading::kNonFinite || v == Reading::kNonFinite) {
      fault = Count(counters_.non_finite_states);
    } else if (p == Reading::kOutOfRange || v == Reading::kOutOfRange) {
      fault = Count(counters_.out_of_range_states);
    } else if (!command.valid ||
               !(command.age_s >= 0.0 && command.age_s <= options_.max_model_age_s)) {
      fault = Count(counters_.stale_forces);
    } else if (f != Reading::kOk) {
      fault = Count(counters_.non_finite_forces);
    }
    if (state.fault) fault = Count(counters_.device_faults);
    if (!state.calibrated) {
      // Not a fault of the loop: the device cannot yet say where the hand is.
      ++counters_.uncalibrated_ticks;
      fault = true;
    }
    if (fault) {
      ramp_ = 0.0;
      energy_j_ = 0.0;
      return Deliver(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    }
    Eigen::Vector3d target = Clamped(force);
    if (ramp_ < 1.0) {
      ramp_ =
          options_.ramp_in_s > 0.0 ? std::min(1.0, ramp_ + period_s_ / options_.ramp_in_s) : 1.0;
      ++counters_.ramp_ticks;
      target *= ramp_;
    }
    if (options_.passivity_control) Dissipate(velocity, target);
    return Deliver(target, velocity);
  }

  /// One tick of a stop: the force moves toward zero along the slew limit. True once it is zero.
  bool RampDown() noexcept {
    ramp_ = 0.0;
    energy_j_ = 0.0;
    if (!output_.isZero(0.0)) ++counters_.ramp_down_ticks;
    Deliver(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    return output_.isZero(0.0);
  }

 private:
  enum class Reading { kOk, kNonFinite, kOutOfRange };
  // Relative slack of the bounds for rounding: scaling a vector to a length rounds by a few
  // ulps (~1e-16); 1e-12 is far above that and far below any real breach.
  static constexpr double kRounding = 1e-12;

  // Copies `in` to `out` with negligible components zeroed, and says whether every component is
  // finite and within `bound`; nothing else is computed from an unchecked value.
  static Reading Sanitise(const Eigen::Vector3d& in, double bound, Eigen::Vector3d& out) {
    Reading reading = Reading::kOk;
    for (int i = 0; i < 3; ++i) {
      const double x = in[i];
      if (!std::isfinite(x)) {
        out.setZero();  // never read on a fault; defined all the same
        return Reading::kNonFinite;
      }
      if (std::abs(x) > bound) reading = Reading::kOutOfRange;
      out[i] = std::abs(x) < StateBounds::kNegligible ? 0.0 : x;
    }
    return reading;
  }

  static bool Count(long& counter) {
    ++counter;
    return true;
  }

  // Scales `force` into the ball of radius limit_n_. stableNorm: 1e300 N is clamped, not
  // overflowed to infinity or underflowed to zero.
  Eigen::Vector3d Clamped(const Eigen::Vector3d& force) {
    const double norm = force.stableNorm();
    if (norm <= limit_n_) return force;
    ++counters_.clamped;
    return force * (limit_n_ / norm);
  }

  // The step from the last output toward `target` (in the ball), cut to the slew limit; `cut`
  // says whether it was. Both ends lie in the ball, so the step does too. A step that exceeds
  // the limit by rounding alone (a ramp of whole slew steps) is not cut: it would leave a
  // 1e-16 N tail for one more tick.
  Eigen::Vector3d Slewed(const Eigen::Vector3d& target, bool& cut) const {
    const Eigen::Vector3d change = target - output_;
    const double step = change.norm();
    const double max_step = slew_per_tick();
    cut = step > max_step * (1.0 + kRounding);
    return cut ? Eigen::Vector3d(output_ + change * (max_step / step)) : target;
  }

  // Sends `target` through the slew limit and the last guard, and books the energy the hand
  // receives from what is sent.
  Eigen::Vector3d Deliver(const Eigen::Vector3d& target, const Eigen::Vector3d& velocity) {
    bool cut = false;
    Eigen::Vector3d next = Slewed(target, cut);
    if (cut) ++counters_.slew_limited;
    const double norm = next.norm();
    if (!(next.allFinite() && norm <= limit_n_ * (1.0 + kRounding) &&
          (next - output_).norm() <= slew_per_tick() * (1.0 + kRounding))) {
      // Unreachable while the layer is right: the last good output, a slew step nearer zero.
      ++counters_.output_guards;
      const double last = output_.norm();
      next = last > slew_per_tick() ? Eigen::Vector3d(output_ * (1.0 - slew_per_tick() / last))
                                    : Eigen::Vector3d::Zero();
    }
    output_ = next;
    // The ceiling: minutes of dissipative contact would otherwise bank credit that a later
    // active model could return to the hand unopposed.
    energy_j_ = std::min(energy_j_ - output_.dot(velocity) * period_s_, energy_limit_j_);
    counters_.max_force_n = std::max(counters_.max_force_n, output_.norm());
    return output_;
  }

  // Time-domain passivity (Hannaford & Ryu 2002): the observer sums the energy the hand has put
  // into the virtual world, -f.v dt, over the forces sent (up to the ceiling). When the force
  // about to be sent would turn it negative, the world has produced energy, and a damper -alpha v
  // for this tick takes it back (alpha bounded by the device's damping), clamped again.
  void Dissipate(const Eigen::Vector3d& v, Eigen::Vector3d& target) {
    const double v2 = v.squaredNorm();
    if (v2 == 0.0) return;
    bool cut = false;
    const double energy = energy_j_ - Slewed(target, cut).dot(v) * period_s_;
    if (energy >= 0.0) return;
    const double alpha = std::min(-energy / (period_s_ * v2), max_damping_);
    target = Clamped(target - alpha * v);
    ++counters_.passivity_activations;
  }

  SafetyOptions options_;
  double period_s_;
  double limit_n_ = 0.0;
  double max_damping_ = 0.0;
  double energy_limit_j_ = 0.0;
  Eigen::Vector3d output_ = Eigen::Vector3d::Zero();
  double ramp_ = 0.0;
  double energy_j_ = 0.0;
  SafetyCounters counters_;
};

}  // namespace cosmems
