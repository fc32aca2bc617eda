#include "scene_model.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "cosmems/analysis/frame_modal_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems::python {
namespace {

constexpr std::array<const char*, 6> kComponents = {"ux", "uy", "uz", "rx", "ry", "rz"};

// A beam's degrees of freedom: its nodes along x.
template <int Dim>
std::vector<SceneModel::Dof> DofsOf(const BeamModel<Dim>& model) {
  std::vector<SceneModel::Dof> dofs(model.FreeDofCount());
  const double length = model.units().length;
  for (int node = 0; node < model.NodeCount(); ++node) {
    for (int local = 0; local < FrameLayout<Dim>::kNodeDofs; ++local) {
      const int index = model.dofs().Reduced(node, local);
      if (index < 0) continue;
      const int component = static_cast<int>(FrameLayout<Dim>::kDof[local]);
      dofs[index] = {"node" + std::to_string(node) + "." + kComponents[component], component < 3,
                     Eigen::Vector3d(model.NodeX()[node] * length, 0.0, 0.0)};
    }
  }
  return dofs;
}

// A device's degrees of freedom: its carriers, named after their body or their first named node.
std::vector<SceneModel::Dof> DofsOf(const FrameModel& model) {
  const StructureDescription& description = model.description();
  const FrameMesh& mesh = model.mesh();
  std::vector<std::string> names(mesh.carriers.size());
  for (std::size_t c = 0; c < mesh.carriers.size(); ++c) {
    if (mesh.carriers[c].body >= 0) names[c] = description.bodies[mesh.carriers[c].body].name;
  }
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    std::string& name = names[mesh.nodes[n].carrier];
    if (!name.empty()) continue;
    name = n < description.nodes.size() ? description.nodes[n].name : "node" + std::to_string(n);
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

// The scene's [loads] on a beam, and on a device (internal units).
template <int Dim>
Eigen::VectorXd LoadsOf(const BeamModel<Dim>& model, const Scene& scene) {
  return AssembleLoads(model, MakeLoadCase(scene));
}

Eigen::VectorXd LoadsOf(const FrameModel& model, const Scene& scene) {
  return AssembleFrameLoads(model, MakeFrameLoadCase(scene, model.description()));
}

// The SceneModel of a BeamModel<Dim> or a FrameModel, built in place.
template <class Model>
class TypedSceneModel final : public SceneModel {
 public:
  template <class Description>
  TypedSceneModel(const Scene& scene, const Description& description) : model_(description) {
    SetDofs(DofsOf(model_));
    SetLoads(LoadsOf(model_, scene));
  }

  const SymmetricBandMatrix& Stiffness() const override { return model_.Stiffness(); }
  const SymmetricBandMatrix& Mass(int j) const override { return model_.Mass(j); }
  int SeriesOrder() const override { return model_.SeriesOrder(); }
  const UnitSystem& units() const override { return model_.units(); }
  ModalResult Modal(int count) const override {
    ModalOptions options;
    options.count = count;
    return SolveModal(model_, options);
  }

 private:
  Model model_;
};

}  // namespace

std::unique_ptr<SceneModel> SceneModel::Make(const Scene& scene) {
  if (IsDevice(scene.structure.kind)) {
    return std::make_unique<TypedSceneModel<FrameModel>>(scene, MakeStructureDescription(scene));
  }
  if (scene.model.dimension == 2) {
    return std::make_unique<TypedSceneModel<BeamModel<2>>>(scene, MakeBeamDescription(scene));
  }
  return std::make_unique<TypedSceneModel<BeamModel<3>>>(scene, MakeBeamDescription(scene));
}

void SceneModel::SetDofs(std::vector<Dof> dofs) {
  dofs_ = std::move(dofs);
  scale_.resize(size());
  for (int i = 0; i < size(); ++i) scale_[i] = dofs_[i].translation ? units().length : 1.0;
}

void SceneModel::SetLoads(Eigen::VectorXd loads) {
  const UnitSystem& u = units();
  loads_si_ = loads.cwiseQuotient(scale_) * (u.force * u.length);
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
