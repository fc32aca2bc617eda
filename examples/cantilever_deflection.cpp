// The paper's reference cantilever (Si, 200 x 20 x 2 um) under a growing tip force: deflection,
// root stress and how close the tip comes to a substrate 2 um below.
#include <cosmems/analysis/beam_field.hpp>
#include <cosmems/analysis/static_analysis.hpp>
#include <cosmems/beam/beam_model.hpp>
#include <cstdio>

int main() {
  const cosmems::Material silicon{169e9, 2330.0, 0.22};
  const cosmems::RectangularSection section{20e-6, 2e-6};
  const double length = 200e-6;
  const double gap = 2e-6;
  const cosmems::BeamModel<2> model(
      cosmems::MakeStructure(cosmems::StructureKind::kCantilever, length, silicon, section, 20, 1));
  std::printf("%12s %14s %14s %10s\n", "force [uN]", "tip uy [um]", "stress [MPa]", "gap left");
  for (double micronewtons : {0.1, 0.5, 1.0, 1.5}) {
    cosmems::LoadCase loads;
    loads.points.push_back(
        {length, Eigen::Vector3d(0, -micronewtons * 1e-6, 0), Eigen::Vector3d::Zero()});
    const cosmems::StaticSolution solution = cosmems::SolveStatic(model, loads);
    const cosmems::BeamField<2> field(model, solution.displacement);
    const double tip = field.At(length)[1];
    std::printf("%12.2f %14.4f %14.3f %9.0f%%\n", micronewtons, tip * 1e6, field.MaxStress() * 1e-6,
                100.0 * (gap + tip) / gap);
  }
  return 0;
}
