#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/core/units.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/dof_weights.hpp"

namespace cosmems {

/// The stylus tip in the micro world: a sphere of `radius` [m] tied to the hand by the virtual
/// coupling, a spring of `stiffness` [N/m] (Colgate, Stanley & Brown; Adams & Hannaford): the
/// hand feels at most this stiffness, whatever the structure does, so choosing it within the
/// device's renderable stiffness keeps the loop stable.
struct ProbeOptions {
  double radius = 2e-6;    ///< m
  double stiffness = 0.0;  ///< N/m, the coupling spring (required, > 0)
};

/// The faces of the box the probe meets, each pushed along one of the box's axes: the upper face
/// (away from the substrate; a member's thickness direction), the lower face, the sides at +z
/// and -z, and the end faces at the first and the last x.
enum class ProbeFace { kUpper = 0, kLower, kPositiveZ, kNegativeZ, kFirstEnd, kLastEnd };
inline constexpr int kProbeFaceCount = 6;

/// Where the probe meets the structure at a state: the face it presses on (or is nearest to),
/// its outward normal [global axes], the depth along it [m] (negative: the clearance; -inf: out
/// of reach) and the force the structure pushes the probe with along the normal [N] (>= 0).
struct ProbeTouch {
  ProbeFace face = ProbeFace::kUpper;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double depth_m = -std::numeric_limits<double>::infinity();
  double force_n = 0.0;
};

/// The probe pressing on the six faces of a box of the structure, as a NonlinearForce;
/// ProbeContact places the faces of the box under the sphere (MoveTo), this pushes.
///
/// Face f, moved along its axis by u_f(d) = w_f . d at the face's point under the sphere,
/// overlaps the sphere by delta_f(d) = s_f u_f(d) + c_f, s_f = +-1 its side and c_f its
/// overlap at rest. A sphere that meets the box is pushed out through the face it came in by:
/// the face of least overlap when contact begins (the separating-axis push), held from one
/// accepted step to the next until its overlap ends, so a hand pressing deeper than the half
/// thickness never pops through to the other face (Zilles & Salisbury's god object keeps its
/// face the same way). With delta the held face's overlap, the coupling's energy (k/2) delta^2
/// gives r(d) = k delta s_f w_f and dr/dd = k w_f w_f^T, each delta_f being affine in d.
/// Evaluate() allocates nothing.
class ProbeFaces : public NonlinearForce {
 public:
  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    if (!reach_) return true;
    const auto [face, delta] = Pushing(d);
    if (!std::isfinite(delta)) return false;
    if (delta <= 0.0) return true;
    const Face& f = faces_[static_cast<std::size_t>(face)];
    for (int i = 0; i < f.count; ++i) {
      force[f.dof[i]] += stiffness_ * delta * f.sign * f.n[i];
      if (!tangent.band_wanted()) continue;
      for (int j = i; j < f.count; ++j)
        tangent.band().Add(f.dof[i], f.dof[j], stiffness_ * f.n[i] * f.n[j]);
    }
    return true;
  }

  /// Idle: out of reach, or clear of every face (the spring, zero at contact, then stays zero
  /// around d).
  bool Idle(const Eigen::VectorXd& d) const override { return !reach_ || Pushing(d).second < 0.0; }

  /// The step ending at d is accepted: the face pushing there is held while contact lasts.
  void Commit(const Eigen::VectorXd& d) override {
    if (!reach_) {
      held_ = kNoFace;
      return;
    }
    const auto [face, delta] = Pushing(d);
    held_ = delta > 0.0 ? static_cast<int>(face) : kNoFace;
  }

  /// Whether the face held since the last accepted step, pushed at `start` by the sphere where
  /// it is now, is clear of it at `predicted` (NonlinearForce::LetsGo). A sphere the hand moved
  /// off the face pushes nowhere at `start`: that release is the hand's, and the prediction
  /// stays.
  bool LetsGo(const Eigen::VectorXd& start, const Eigen::VectorXd& predicted) const override {
    if (held_ == kNoFace || !reach_) return false;
    const Face& face = faces_[static_cast<std::size_t>(held_)];
    return Overlap(face, start) > 0.0 && !(Overlap(face, predicted) > 0.0);
  }

  /// Whether the sphere, where it is now, pushes at d while it pushed nowhere at the last
  /// accepted step: it has just touched, and the structure's Newton matrix has gained the
  /// spring's k w_f w_f^T.
  bool Touches(const Eigen::VectorXd& d) const {
    return held_ == kNoFace && reach_ && Pushing(d).second > 0.0;
  }

  /// The face the probe presses on (or is nearest to) at d, and how deep.
  ProbeTouch Touch(const Eigen::VectorXd& d) const {
    ProbeTouch touch;
    if (!reach_) return touch;
    const auto [face, delta] = Pushing(d);
    touch.face = face;
    touch.normal = faces_[static_cast<std::size_t>(face)].normal;
    touch.depth_m = delta * units_.length;
    touch.force_n = delta > 0.0 ? stiffness_ * delta * units_.force : 0.0;
    return touch;
  }

  /// w_f^T A w_f of the weights of the face's point under the probe, for A the band of K^-1
  /// (BandCholesky::InverseWithinBand): the structure's compliance there (internal units),
  /// zero for a face that does not move. The weights fit the band, as their stiffness does.
  double Compliance(ProbeFace face, const SymmetricBandMatrix& inverse_band) const {
    return faces_[static_cast<std::size_t>(face)].QuadraticForm(inverse_band);
  }
  double stiffness_n_per_m() const { return stiffness_ * units_.force / units_.length; }

 protected:
  ProbeFaces(const UnitSystem& units, const ProbeOptions& options)
      : units_(units),
        radius_(options.radius / units.length),
        stiffness_(options.stiffness / (units.force / units.length)) {
    RequirePositive("probe.radius", options.radius);
    RequirePositive("probe.stiffness", options.stiffness);
  }

  /// Places a face: its side, its overlap at rest, its outward normal and the weights of its
  /// motion along its axis over the carriers' `dofs` (-1: anchored or absent).
  void Place(ProbeFace face, double sign, double constant, const Eigen::Vector3d& normal,
             const std::array<int, 12>& dofs, const Eigen::Matrix<double, 12, 1>& weights) {
    Face& f = faces_[static_cast<std::size_t>(face)];
    f.Set(dofs, weights);
    f.sign = sign;
    f.constant = constant;
    f.normal = normal;
  }

  UnitSystem units_;
  double radius_, stiffness_;  ///< internal units
  bool reach_ = false;         ///< whether a box lies within the radius (set by MoveTo)

 private:
  struct Face : DofWeights {
    double sign = 1.0, constant = 0.0;
    Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  };

  static double Overlap(const Face& f, const Eigen::VectorXd& d) {
    return f.sign * f.Dot(d) + f.constant;
  }

  // The face pushing the sphere and its overlap (internal units; the sphere is in reach): the
  // held face while contact lasts, else the face of least overlap.
  std::pair<ProbeFace, double> Pushing(const Eigen::VectorXd& d) const {
    if (held_ == kNoFace) return Deepest(d);
    return {static_cast<ProbeFace>(held_), Overlap(faces_[static_cast<std::size_t>(held_)], d)};
  }

  // The face of least overlap and that overlap.
  std::pair<ProbeFace, double> Deepest(const Eigen::VectorXd& d) const {
    ProbeFace face = ProbeFace::kUpper;
    double least = std::numeric_limits<double>::infinity();
    for (int f = 0; f < kProbeFaceCount; ++f) {
      const double overlap = Overlap(faces_[static_cast<std::size_t>(f)], d);
      if (std::isnan(overlap)) return {static_cast<ProbeFace>(f), overlap};  // reported
      if (overlap < least) {
        least = overlap;
        face = static_cast<ProbeFace>(f);
      }
    }
    return {face, least};
  }

  std::array<Face, kProbeFaceCount> faces_{};
  static constexpr int kNoFace = -1;
  int held_ = kNoFace;  ///< the face pushing at the last accepted step
};

}  // namespace cosmems
