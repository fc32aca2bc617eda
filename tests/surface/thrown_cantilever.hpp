#pragma once

// The impact tests' run: the 20-element reference cantilever thrown at the substrate at 1 m/s
// (every free node's u_y), contact without adhesion, the integrator under test made and started
// by the caller and stepped for two periods and several impacts.

#include <gtest/gtest.h>

#include <algorithm>

#include "cosmems/surface/substrate_contact.hpp"
#include "test_beams.hpp"

namespace cosmems::test {

struct ImpactRecord {
  double initial_energy = 0.0;  ///< 1/2 v^T M_0 v + 1/2 d^T K d at the start
  double largest_energy = 0.0;  ///< the same, the largest after any step
  double deepest = 0.0;         ///< m: the largest penetration after any step
  double tolerance = 0.0;       ///< m: the penetration the contact accepts
  long touching = 0;            ///< steps that ended in contact
  int contacts = 0;             ///< contact events
};

/// `make(model, contact, v0)` returns the integrator started from rest with velocity v0,
/// `step(integrator)` advances it one step.
template <typename Make, typename Step>
ImpactRecord ThrowAtTheSubstrate(int steps, Make&& make, Step&& step) {
  const BeamModel<2> model = PlanarCantilever(kReferenceLength, 20);
  ContactOptions options;
  options.gap = kReferenceGap;
  SubstrateContact<2> contact(model, options);
  const UnitSystem& u = model.units();
  Eigen::VectorXd v0 = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (int node = 1; node <= 20; ++node) {
    v0[model.dofs().Reduced(node, NodalDof::kUy)] = -1.0 / (u.length / u.time);
  }
  auto integrator = make(model, contact, v0);
  auto energy = [&] {
    const Eigen::VectorXd& d = integrator.displacement();
    const Eigen::VectorXd& v = integrator.velocity();
    return 0.5 * (v.dot(model.Mass(0) * v) + d.dot(model.Stiffness() * d));
  };
  ImpactRecord out;
  out.initial_energy = energy();
  out.tolerance = contact.tolerance();
  for (int i = 0; i < steps; ++i) {
    if (step(integrator) != Status::kOk) {
      ADD_FAILURE() << "step " << i << " failed";
      break;
    }
    out.deepest = std::max(out.deepest, contact.Penetration(integrator.displacement()));
    out.largest_energy = std::max(out.largest_energy, energy());
    out.touching += contact.Summary().InContact();
  }
  out.contacts = contact.events().contacts;
  return out;
}

/// What every impact test asks: contact made more than once (it bounced and came back), the
/// penetration within the tolerance, and no energy gained.
inline void ExpectInelasticImpacts(const ImpactRecord& r) {
  EXPECT_GT(r.touching, 0);
  EXPECT_GT(r.contacts, 1);
  EXPECT_LE(r.deepest, r.tolerance);
  EXPECT_LE(r.largest_energy, r.initial_energy * (1.0 + 1e-9));
}

}  // namespace cosmems::test
