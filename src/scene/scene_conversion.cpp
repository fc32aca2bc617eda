#include "cosmems/scene/scene_conversion.hpp"

namespace cosmems {

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
  return MakeStructure(scene.structure.kind, scene.structure.length,
                       EffectiveMaterial(scene.material), section, scene.model.elements,
                       scene.model.series_order);
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

}  // namespace cosmems
