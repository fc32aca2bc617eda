#pragma once

// The reference cantilever (silicon, 200 x 20 x 2 um, 20 elements) the haptic tests touch, as
// the one-member netlist the command line touches, with its tip stiffness 3EI/L^3 and the
// paper's surface under it.
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/haptics/device_types.hpp"
#include "cosmems/haptics/hand_scaling.hpp"
#include "cosmems/haptics/haptic_physics.hpp"
#include "cosmems/structure/straight_beam.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "test_beams.hpp"

namespace cosmems::test {

inline double ReferenceTipStiffness() {
  const double inertia = 20e-6 * 8e-18 / 12.0;  // b t^3 / 12
  return 3.0 * 169e9 * inertia / (kReferenceLength * kReferenceLength * kReferenceLength);
}

/// The paper's substrate: 2 um below the beam.
constexpr double kHapticGap = 2e-6;
/// The stylus's probe (radius as the beam is thick) and its coupling spring, N/m.
constexpr double kProbeRadius = 2e-6, kProbeCoupling = 5.0;

/// The command line's hand scaling for the reference cantilever on `specs`: 5000 hand m per
/// micro m, the `coupling` (N/m) felt at half the device's renderable stiffness, and the
/// device's centre putting the probe 5 um above the tip (one gap above its upper face).
inline HandScaling ReferenceHandScaling(const DeviceSpecs& specs, double coupling) {
  HandScaling scaling;
  scaling.position_scale = 5000.0;
  scaling.force_scale = 0.5 * specs.max_stiffness_n_per_m * scaling.position_scale / coupling;
  scaling.device_origin_m = -scaling.position_scale * Eigen::Vector3d(kReferenceLength, 5e-6, 0.0);
  return scaling;
}

/// `options` with Newton meeting 1e-10 of the terms it balances instead of the haptic 1e-6: for
/// the tests that hold a press to closed-form statics to 1e-9 (the haptic tolerance leaves the
/// static state up to 5.4e-7 off, measured;
/// HapticStructureTest.TheHapticToleranceFeelsAsTheTightOne bounds what the hand feels of it).
inline HapticPhysicsOptions TightPhysics(HapticPhysicsOptions options = {}) {
  options.residual_tolerance = 1e-10;
  return options;
}

/// The probe's centre over the tip with its lowest point `depth` below the undeformed upper face.
inline Eigen::Vector3d OverTip(double depth) {
  return Eigen::Vector3d(kReferenceLength, 0.5 * kReferenceThickness - depth + kProbeRadius, 0.0);
}

/// The paper's contact and stiction: the substrate 2 um below, 0.02 J/m^2, asperities 20 nm high.
inline ContactOptions HapticContact() {
  ContactOptions contact;
  contact.gap = kHapticGap;
  contact.separation = 2e-8;
  contact.stiction = true;
  contact.adhesion_energy = 0.02;
  return contact;
}

/// The reference cantilever as the command line touches it: its one-member netlist (StraightBeam,
/// Hermite elements), planar (u_x, u_y, r_z: model.dimension = 2) or spatial.
inline StructureDescription HapticCantileverNetlist(bool planar = true) {
  StraightBeamDesign d;
  d.length = kReferenceLength;
  d.material = Silicon();
  d.section = ReferenceSection();
  d.elements = 20;
  d.series_order = 0;
  d.planar = planar;
  return StraightBeam(d);
}

/// The paper's surface under a netlist, as a scene builds it: the contact and stiction, and the
/// Casimir force held at the asperities' height. Not movable: `all` holds the two.
struct HapticNetlistSurface {
  explicit HapticNetlistSurface(const FrameModel& model)
      : contact(model, HapticContact()), casimir(model, CasimirPressure{}, Under()) {
    all.Add(contact);
    all.Add(casimir);
  }
  HapticNetlistSurface(const HapticNetlistSurface&) = delete;
  HapticNetlistSurface& operator=(const HapticNetlistSurface&) = delete;

  static FrameGapOptions Under() {
    FrameGapOptions under{kHapticGap};
    under.separation = HapticContact().separation;
    return under;
  }

  FrameSubstrateContact contact;
  FrameGapForce<CasimirPressure> casimir;
  ForceSum all;
};

/// The tip's u_y [m] in a frame of the netlist's HapticStructure (node "tip" is node 1).
inline double NetlistTipDeflection(const FrameModel& model, const HapticFrame& frame) {
  return frame.carrier_motion_m(1, model.mesh().nodes[1].carrier);
}

}  // namespace cosmems::test
