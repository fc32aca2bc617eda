#pragma once

#include <gtest/gtest.h>

#include <string>

#include "cosmems/scene/scene.hpp"

namespace cosmems::testing {

// Field-by-field equality of two scenes, Scene::source aside (it names where a scene came from,
// not what it is). Exact comparisons: both sides are parsed from the same decimal text.
inline void ExpectSameScene(const Scene& a, const Scene& b) {
  EXPECT_EQ(a.structure.kind, b.structure.kind);
  EXPECT_EQ(a.structure.length, b.structure.length);
  EXPECT_EQ(a.structure.width, b.structure.width);
  EXPECT_EQ(a.structure.thickness, b.structure.thickness);
  EXPECT_EQ(a.structure.gap, b.structure.gap);
  EXPECT_EQ(a.structure.axial_load, b.structure.axial_load);
  EXPECT_EQ(a.material.young_modulus, b.material.young_modulus);
  EXPECT_EQ(a.material.density, b.material.density);
  EXPECT_EQ(a.material.poisson_ratio, b.material.poisson_ratio);
  EXPECT_EQ(a.material.plate_modulus, b.material.plate_modulus);
  EXPECT_EQ(a.model.theory, b.model.theory);
  EXPECT_EQ(a.model.dimension, b.model.dimension);
  EXPECT_EQ(a.model.elements, b.model.elements);
  EXPECT_EQ(a.model.series_order, b.model.series_order);
  EXPECT_EQ(a.model.modes, b.model.modes);
  EXPECT_EQ(a.loads.tip_force, b.loads.tip_force);
  EXPECT_EQ(a.loads.midspan_force, b.loads.midspan_force);
  EXPECT_EQ(a.loads.distributed, b.loads.distributed);
  EXPECT_EQ(a.loads.tip_moment, b.loads.tip_moment);
  ASSERT_EQ(a.loads.time_function.has_value(), b.loads.time_function.has_value());
  if (a.loads.time_function) {
    EXPECT_EQ(a.loads.time_function->kind, b.loads.time_function->kind);
    EXPECT_EQ(a.loads.time_function->ramp_time, b.loads.time_function->ramp_time);
    EXPECT_EQ(a.loads.time_function->frequency, b.loads.time_function->frequency);
  }
  ASSERT_EQ(a.effects.contact.has_value(), b.effects.contact.has_value());
  if (a.effects.contact) {
    EXPECT_EQ(a.effects.contact->enabled, b.effects.contact->enabled);
    EXPECT_EQ(a.effects.contact->separation, b.effects.contact->separation);
    EXPECT_EQ(a.effects.contact->tolerance, b.effects.contact->tolerance);
    EXPECT_EQ(a.effects.contact->proximity, b.effects.contact->proximity);
  }
  ASSERT_EQ(a.effects.stiction.has_value(), b.effects.stiction.has_value());
  if (a.effects.stiction) {
    EXPECT_EQ(a.effects.stiction->enabled, b.effects.stiction->enabled);
    EXPECT_EQ(a.effects.stiction->adhesion_energy, b.effects.stiction->adhesion_energy);
  }
  ASSERT_EQ(a.effects.electrostatic.has_value(), b.effects.electrostatic.has_value());
  if (a.effects.electrostatic) {
    const ElectrostaticEffect &ea = *a.effects.electrostatic, &eb = *b.effects.electrostatic;
    EXPECT_EQ(ea.enabled, eb.enabled);
    EXPECT_EQ(ea.voltage, eb.voltage);
    EXPECT_EQ(ea.fringing, eb.fringing);
    EXPECT_EQ(ea.electrode_start, eb.electrode_start);
    EXPECT_EQ(ea.electrode_end, eb.electrode_end);
    ASSERT_EQ(ea.electrodes.size(), eb.electrodes.size());
    for (std::size_t i = 0; i < ea.electrodes.size(); ++i) {
      EXPECT_EQ(ea.electrodes[i].x, eb.electrodes[i].x);
      EXPECT_EQ(ea.electrodes[i].z, eb.electrodes[i].z);
    }
  }
  EXPECT_EQ(a.effects.casimir.has_value(), b.effects.casimir.has_value());
  EXPECT_EQ(a.effects.van_der_waals.has_value(), b.effects.van_der_waals.has_value());
  ASSERT_EQ(a.effects.damping.has_value(), b.effects.damping.has_value());
  if (a.effects.damping) {
    EXPECT_EQ(a.effects.damping->enabled, b.effects.damping->enabled);
    EXPECT_EQ(a.effects.damping->quality_factor, b.effects.damping->quality_factor);
    EXPECT_EQ(a.effects.damping->rayleigh, b.effects.damping->rayleigh);
  }
  ASSERT_EQ(a.effects.squeeze_film.has_value(), b.effects.squeeze_film.has_value());
  if (a.effects.squeeze_film) {
    EXPECT_EQ(a.effects.squeeze_film->enabled, b.effects.squeeze_film->enabled);
    EXPECT_EQ(a.effects.squeeze_film->viscosity, b.effects.squeeze_film->viscosity);
    EXPECT_EQ(a.effects.squeeze_film->mean_free_path, b.effects.squeeze_film->mean_free_path);
  }
  EXPECT_EQ(a.analysis.type, b.analysis.type);
  EXPECT_EQ(a.analysis.count, b.analysis.count);
  EXPECT_EQ(a.analysis.duration, b.analysis.duration);
  EXPECT_EQ(a.analysis.time_step, b.analysis.time_step);
  EXPECT_EQ(a.analysis.integrator, b.analysis.integrator);
  EXPECT_EQ(a.analysis.beta, b.analysis.beta);
  EXPECT_EQ(a.analysis.gamma, b.analysis.gamma);
  EXPECT_EQ(a.analysis.alpha, b.analysis.alpha);
  EXPECT_EQ(a.analysis.rho_inf, b.analysis.rho_inf);
  EXPECT_EQ(a.analysis.initial, b.analysis.initial);
  EXPECT_EQ(a.device.has_value(), b.device.has_value());
}

}  // namespace cosmems::testing
