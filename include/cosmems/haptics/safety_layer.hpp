#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosmems/haptics/device_types.hpp"

namespace cosmems {

/// Limits every force any backend sends (haptics-notes: clamp, slew, ramp-in, zero on faults,
/// time-domain passivity). Rates are per second; the layer works on the device's nominal period.
struct SafetyOptions {
  double force_limit_n = 0.0;         ///< 0: the device's continuous force (motors stay cool)
  double slew_limit_n_per_s = 100.0;  ///< largest change of force: 0.1 N a tick at 1 kHz
  double ramp_in_s = 0.5;             ///< force scale 0 -> 1 after start and after every fault
  double max_model_age_s = 0.01;      ///< an older force (stale physics) is replaced by zero
  bool passivity_control = true;      ///< Hannaford & Ryu's observer and variable damper

  /// Throws std::invalid_argument naming the field and its value.
  void Validate() const {
    auto require = [](bool ok, const char* field, double value) {
      if (!ok) {
        throw std::invalid_argument(std::string("safety.") + field + " = " + std::to_string(value) +
                                    " is out of range");
      }
    };
    require(std::isfinite(force_limit_n) && force_limit_n >= 0.0, "force_limit_n", force_limit_n);
    require(std::isfinite(slew_limit_n_per_s) && slew_limit_n_per_s > 0.0, "slew_limit_n_per_s",
            slew_limit_n_per_s);
    require(std::isfinite(ramp_in_s) && ramp_in_s >= 0.0, "ramp_in_s", ramp_in_s);
    require(max_model_age_s > 0.0, "max_model_age_s", max_model_age_s);
  }
};

/// How often the safety layer stepped in, and the largest force it let through.
struct SafetyCounters {
  long clamped = 0;                ///< force above the limit, scaled down to it
  long slew_limited = 0;           ///< change above the slew limit, cut to it
  long ramp_ticks = 0;             ///< ticks with the ramp-in scale below 1
  long non_finite_states = 0;      ///< NaN or infinite position or velocity from the device
  long non_finite_forces = 0;      ///< NaN or infinite force from the client
  long stale_forces = 0;           ///< invalid or too old force from the client
  long device_faults = 0;          ///< force errors the device reported
  long passivity_activations = 0;  ///< ticks the passivity controller added damping
  double max_force_n = 0.0;        ///< largest force commanded
};

/// The filter between a servo client and the device. Every output is finite, no larger than
/// force_limit(), and differs from the previous output by at most slew_per_tick(): a fault
/// drives the force to zero along the slew limit rather than dropping it, so a test can hold the
/// layer to these three bounds under any input. Allocation-free; one instance per servo loop.
class SafetyLayer {
 public:
  SafetyLayer(const SafetyOptions& options, const DeviceSpecs& specs)
      : options_(options), period_s_(1.0 / specs.nominal_rate_hz) {
    options.Validate();
    const double device_limit = std::min(specs.max_force_n, specs.max_continuous_force_n);
    limit_n_ = options.force_limit_n > 0.0 ? std::min(options.force_limit_n, specs.max_force_n)
                                           : device_limit;
    max_damping_ = specs.max_damping_ns_per_m;
    if (!(limit_n_ > 0.0) || !(period_s_ > 0.0)) {
      throw std::invalid_argument(
          "device specs: max_force_n = " + std::to_string(specs.max_force_n) +
          ", nominal_rate_hz = " + std::to_string(specs.nominal_rate_hz) + " give no usable limit");
    }
  }

  double force_limit() const { return limit_n_; }
  double slew_per_tick() const { return options_.slew_limit_n_per_s * period_s_; }
  double period() const { return period_s_; }
  const SafetyCounters& counters() const { return counters_; }
  const Eigen::Vector3d& last_output() const { return output_; }

  /// Starts over from zero force: ramp-in and the passivity observer restart (the counters stay).
  void Restart() {
    output_.setZero();
    ramp_ = 0.0;
    energy_j_ = 0.0;
  }

  /// The force to send at this tick, given the device state and the client's command.
  Eigen::Vector3d Filter(const DeviceState& state, const ForceCommand& command) noexcept {
    const bool state_ok = state.position_m.allFinite() && state.velocity_m_s.allFinite();
    bool fault = false;
    if (!state_ok) {
      fault = Count(counters_.non_finite_states);
    } else if (!command.valid || !(command.age_s <= options_.max_model_age_s)) {
      fault = Count(counters_.stale_forces);
    } else if (!command.force_n.allFinite()) {
      fault = Count(counters_.non_finite_forces);
    }
    if (state.fault) fault = Count(counters_.device_faults);
    Eigen::Vector3d target = Eigen::Vector3d::Zero();
    if (fault) {
      ramp_ = 0.0;
      energy_j_ = 0.0;
    } else {
      target = command.force_n;
      if (options_.passivity_control) Dissipate(state.velocity_m_s, target);
      const double norm = target.stableNorm();  // 1e300 N is clamped, not overflowed to zero
      if (norm > limit_n_) {
        target *= limit_n_ / norm;
        ++counters_.clamped;
      }
      if (ramp_ < 1.0) {
        ramp_ =
            options_.ramp_in_s > 0.0 ? std::min(1.0, ramp_ + period_s_ / options_.ramp_in_s) : 1.0;
        ++counters_.ramp_ticks;
        target *= ramp_;
      }
    }
    // Both ends of the step lie in the ball of radius limit_n_, so the slewed force does too.
    const Eigen::Vector3d change = target - output_;
    const double step = change.norm();
    const double max_step = slew_per_tick();
    if (step > max_step) {
      output_ += change * (max_step / step);
      ++counters_.slew_limited;
    } else {
      output_ = target;
    }
    counters_.max_force_n = std::max(counters_.max_force_n, output_.norm());
    return output_;
  }

 private:
  static bool Count(long& counter) {
    ++counter;
    return true;
  }

  // Time-domain passivity (Hannaford & Ryu 2002): the observer sums the energy the hand has put
  // into the virtual world, -f.v dt; when it turns negative the world has produced energy, and a
  // one-tick damper -alpha v takes it back (alpha bounded by the device's damping).
  void Dissipate(const Eigen::Vector3d& v, Eigen::Vector3d& force) {
    energy_j_ -= force.dot(v) * period_s_;
    const double v2 = v.squaredNorm();
    if (energy_j_ >= 0.0 || v2 == 0.0) return;
    const double alpha = std::min(-energy_j_ / (period_s_ * v2), max_damping_);
    force -= alpha * v;
    energy_j_ += alpha * v2 * period_s_;
    ++counters_.passivity_activations;
  }

  SafetyOptions options_;
  double period_s_;
  double limit_n_ = 0.0;
  double max_damping_ = 0.0;
  Eigen::Vector3d output_ = Eigen::Vector3d::Zero();
  double ramp_ = 0.0;
  double energy_j_ = 0.0;
  SafetyCounters counters_;
};

}  // namespace cosmems
