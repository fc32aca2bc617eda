#include "cosmems/scene/scene_conversion.hpp"

#include <cmath>

namespace cosmems {
namespace {

// Where a transient analysis records uy and a pull-in imposes its travel: the free end of a
// cantilever, the middle of a bridge, where a load on either moves the beam most.
double TransientOutputX(const SceneStructure& structure) {
  return structure.kind == StructureKind::kCantilever ? structure.length : 0.5 * structure.length;
}

}  // namespace

Material EffectiveMaterial(const SceneMaterial& material) {
  Material out;
  out.young_modulus = material.young_modulus;
  out.density = material.density;
  out.poisson_ratio = material.poisson_ratio;
  if (material.plate_modulus) {
    out.young_modulus /= 1.0 - material.poisson_ratio * material.poisson_ratio;
  }
  return out;
}

BeamDescription MakeBeamDescription(const Scene& scene) {
  RectangularSection section;
  section.width = scene.structure.width;
  section.thickness = scene.structure.thickness;
  BeamDescription beam =
      MakeStructure(scene.structure.kind, scene.structure.length, EffectiveMaterial(scene.material),
                    section, scene.model.elements, scene.model.series_order);
  beam.axial_load = scene.structure.axial_load;
  return beam;
}

LoadCase MakeLoadCase(const Scene& scene) {
  const SceneLoads& loads = scene.loads;
  const double length = scene.structure.length;
  LoadCase out;
  if (!loads.tip_force.isZero(0.0) || !loads.tip_moment.isZero(0.0)) {
    out.points.push_back(PointLoad{length, loads.tip_force, loads.tip_moment});
  }
  if (!loads.midspan_force.isZero(0.0)) {
    out.points.push_back(PointLoad{0.5 * length, loads.midspan_force, Eigen::Vector3d::Zero()});
  }
  out.distributed = loads.distributed;
  return out;
}

DampingModel MakeDampingModel(const Scene& scene) {
  const std::optional<DampingEffect>& damping = scene.effects.damping;
  if (!IsOn(damping)) return {};
  if (damping->quality_factor) return DampingModel::QualityFactor(*damping->quality_factor);
  return DampingModel::Rayleigh((*damping->rayleigh)[0], (*damping->rayleigh)[1]);
}

LoadTimeFunction MakeLoadTimeFunction(const Scene& scene) {
  LoadTimeFunction out;
  if (!scene.loads.time_function) return out;
  const SceneTimeFunction& f = *scene.loads.time_function;
  switch (f.kind) {
    case TimeFunctionKind::kStep:
      out.kind = LoadTimeFunction::Kind::kStep;
      break;
    case TimeFunctionKind::kRamp:
      out.kind = LoadTimeFunction::Kind::kRamp;
      out.ramp_time = f.ramp_time;
      break;
    case TimeFunctionKind::kSine:
      out.kind = LoadTimeFunction::Kind::kSine;
      out.frequency = f.frequency;
      break;
  }
  return out;
}

GeneralizedAlphaParameters MakeIntegratorParameters(const SceneAnalysis& analysis) {
  switch (analysis.integrator) {
    case Integrator::kNewmark:
      return GeneralizedAlphaParameters::Newmark(analysis.beta, analysis.gamma);
    case Integrator::kHht:
      return GeneralizedAlphaParameters::Hht(analysis.alpha);
    case Integrator::kGeneralizedAlpha:
      return GeneralizedAlphaParameters::FromSpectralRadius(analysis.rho_inf);
    case Integrator::kCentralDifference:
      return GeneralizedAlphaParameters::CentralDifference();
    case Integrator::kModal:
      break;
  }
  return {};
}

TransientOptions MakeTransientOptions(const Scene& scene) {
  const SceneAnalysis& analysis = scene.analysis;
  TransientOptions out;
  out.duration = analysis.duration;
  out.time_step = analysis.time_step;
  if (analysis.integrator == Integrator::kModal) {
    out.path = TimePath::kModal;
    out.modes = scene.model.modes;
  } else {
    out.path = TimePath::kNewmarkFamily;
    out.parameters = MakeIntegratorParameters(analysis);
  }
  out.start_static = analysis.initial == InitialState::kStatic;
  out.time_function = MakeLoadTimeFunction(scene);
  out.damping = MakeDampingModel(scene);
  out.output_x = TransientOutputX(scene.structure);
  return out;
}

SqueezeFilmOptions MakeSqueezeFilmOptions(const Scene& scene) {
  SqueezeFilmOptions out;
  const SqueezeFilmEffect& film = *scene.effects.squeeze_film;
  out.viscosity = film.viscosity.value_or(out.viscosity);
  out.mean_free_path = film.mean_free_path.value_or(out.mean_free_path);
  return out;
}

ContactOptions MakeContactOptions(const Scene& scene) {
  const SceneEffects& e = scene.effects;
  ContactOptions out;
  out.gap = *scene.structure.gap;
  out.separation = e.HasSurfacePressure() ? 1e-2 * out.gap : 0.0;
  if (IsOn(e.contact)) {
    out.separation = e.contact->separation.value_or(out.separation);
    out.tolerance = e.contact->tolerance.value_or(0.0);
    out.proximity = e.contact->proximity.value_or(0.0);
  }
  if (IsOn(e.stiction)) {
    out.stiction = true;
    out.adhesion_energy = *e.stiction->adhesion_energy;
  }
  return out;
}

PullInOptions MakePullInOptions(const Scene& scene) {
  PullInOptions out;
  const SceneStructure& structure = scene.structure;
  const ElectrostaticEffect& electrode = *scene.effects.electrostatic;
  out.electrode.gap = *structure.gap;
  out.electrode.start = electrode.electrode_start.value_or(0.0);
  out.electrode.end = electrode.electrode_end.value_or(structure.length);
  out.fringing = electrode.fringing;
  out.control_x = TransientOutputX(structure);
  if (scene.analysis.voltage_max) out.fold.max_load = std::pow(*scene.analysis.voltage_max, 2);
  return out;
}

}  // namespace cosmems
