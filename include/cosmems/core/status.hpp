#pragma once

namespace cosmems {

/// Outcome of a numerical operation. Set-up errors throw; numerical trouble is a Status.
enum class Status {
  kOk,
  kNotPositiveDefinite,  ///< a factorisation met a non-positive pivot (insufficient supports)
  kNotConverged,         ///< an iteration hit its limit before its tolerance
  kNonFinite,            ///< a NaN or infinity appeared in the result
  kDiverged,             ///< a run grew without bound (e.g. an explicit step above its limit)
};

/// The JSON/CLI spelling of a status: "ok" or a short reason.
constexpr const char* ToString(Status status) {
  switch (status) {
    case Status::kOk:
      return "ok";
    case Status::kNotPositiveDefinite:
      return "not positive definite (is the structure supported?)";
    case Status::kNotConverged:
      return "not converged";
    case Status::kNonFinite:
      return "non-finite result";
    case Status::kDiverged:
      return "diverged (unstable time step?)";
  }
  return "unknown";
}

}  // namespace cosmems
