#include "scene_model.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "cosmems/analysis/frame_modal_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems::python {
namespace {

constexpr std::array<const char*, 6> kComponents = {"ux", "uy", "uz", "rx", "ry", "rz"};

// The degrees of freedom of a structure's carriers: a device's named after their body or their
// first named node, a beam's (`beam`: one member along x) after their node's place along it.
std::vector<SceneModel::Dof> DofsOf(const FrameModel& model, bool beam) {
  const StructureDescription& description = model.description();
  const FrameMesh& mesh = model.mesh();
  std::vector<std::string> names(mesh.carriers.size());
  for (std::size_t c = 0; c < mesh.carriers.size(); ++c) {
    if (mesh.carriers[c].body >= 0) names[c] = description.bodies[mesh.carriers[c].body].name;
  }
  const double pitch = beam ? mesh.elements.front().length : 0.0;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    std::string& name = names[mesh.nodes[n].carrier];
    if (!name.empty()) continue;
    if (beam) {
      name = "node" + std::to_string(std::lround(mesh.nodes[n].position.x() / pitch));
    } else {
      name = n < description.nodes.size() ? description.nodes[n].name : "node" + std::to_string(n);
    }
  }
  std::vector<SceneModel::Dof> dofs(model.FreeDofCount());
  for (std::size_t c = 0; c < mesh.carriers.size(); ++c) {
    for (int d = 0; d < 6; ++d) {
      const int index = model.CarrierDof(static_cast<int>(c), d);
      if (index < 0) continue;
      dofs[index] = {names[c] + "." + kComponents[d], d < 3, mesh.carriers[c].position};
    }
  }
  return dofs;
}

}  // namespace

SceneModel::SceneModel(const Scene& scene)
    : model_(MakeStructureDescription(scene)), dofs_(DofsOf(model_, IsStraightBeam(scene))) {
  scale_.resize(size());
  for (int i = 0; i < size(); ++i) scale_[i] = dofs_[i].translation ? units().length : 1.0;
  const UnitSystem& u = units();
  const Eigen::VectorXd loads =
      AssembleFrameLoads(model_, MakeFrameLoadCase(scene, model_.description()));
  loads_si_ = loads.cwiseQuotient(scale_) * (u.force * u.length);
}

ModalResult SceneModel::Modal(int count) const {
  ModalOptions options;
  options.count = count;
  return SolveModal(model_, options);
}

Eigen::SparseMatrix<double> SceneModel::MatrixSi(int j) const {
  const UnitSystem& u = units();
  // The energy unit F L over the two displacements' scales, times T^(2j+2) for M_2j.
  const double factor = u.force * u.length * (j < 0 ? 1.0 : std::pow(u.time, 2.0 * j + 2.0));
  Eigen::SparseMatrix<double> a = (j < 0 ? Stiffness() : Mass(j)).ToSparse();
  const Eigen::VectorXd inverse = scale_.cwiseInverse();
  a = factor * inverse.asDiagonal() * a * inverse.asDiagonal();
  return a;
}

}  // namespace cosmems::python
