// A program outside the cosmems tree: the reference cantilever's tip deflection through the
// installed headers, with its sparse (CHOLMOD) path so the private link dependency is tested, and
// the OpenHaptics backend opened (the fake HD library's device when built without the SDK).
#include <cmath>
#include <cosmems/cosmems.hpp>
#include <cosmems/openhaptics/openhaptics_device.hpp>
#include <cstdio>

int main() {
  const cosmems::Material silicon{169e9, 2330.0, 0.22};
  const cosmems::RectangularSection section{20e-6, 2e-6};
  const double length = 200e-6;
  const double force = -1e-7;
  const cosmems::BeamModel<3> model(
      cosmems::MakeStructure(cosmems::StructureKind::kCantilever, length, silicon, section, 10, 1));
  cosmems::LoadCase loads;
  loads.points.push_back({length, Eigen::Vector3d(0, force, 0), Eigen::Vector3d::Zero()});
  const auto solution = cosmems::SolveStatic(model, loads, cosmems::LinearSolverKind::kCholmod);
  const double tip = cosmems::BeamField<3>(model, solution.displacement).At(length)[1];
  const double expected =
      force * length * length * length / (3 * silicon.young_modulus * section.SecondMomentZ());
  std::printf("tip deflection %.6e m (closed form %.6e m)\n", tip, expected);
  cosmems::OpenHapticsDevice device;
  const cosmems::DeviceStatus status = device.Open();
  std::printf("OpenHaptics (%s): %s, %s\n",
              cosmems::OpenHapticsDevice::BuiltWithSdk() ? "SDK" : "fake",
              cosmems::ToString(status), device.specs().model.c_str());
  if (!cosmems::OpenHapticsDevice::BuiltWithSdk() && status != cosmems::DeviceStatus::kOk) return 1;
  device.Close();
  return std::abs(tip - expected) <= 1e-10 * std::abs(expected) ? 0 : 1;
}
