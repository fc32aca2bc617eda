#include "cosmems/analysis/frame_modal_analysis.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace cosmems {

FrameRigidMotions::FrameRigidMotions(const FrameModel& model) {
  const FrameMesh& mesh = model.mesh();
  const double length = model.units().length;
  double mass = 0.0;
  for (int e = 0; e < model.ElementCount(); ++e) {
    const ElementProperties& p = model.elements()[e].properties();
    const FrameMesh::Element& element = mesh.elements[e];
    const Eigen::Vector3d middle =
        0.5 * (mesh.nodes[element.from].position + mesh.nodes[element.to].position) / length;
    mass += p.density * p.area * p.length;
    center += p.density * p.area * p.length * middle;
  }
  for (std::size_t b = 0; b < mesh.body_carrier.size(); ++b) {
    const double m = model.BodyMass(static_cast<int>(b))(0, 0);
    mass += m;
    center += m * mesh.carriers[mesh.body_carrier[b]].position / length;
  }
  center /= mass;

  // Every element and body in full, anchors ignored: the totals are the whole structure's.
  for (int e = 0; e < model.ElementCount(); ++e) {
    const FrameMesh::Element& element = mesh.elements[e];
    const FrameModel::Element::Matrix m0 = model.elements()[e].Mass(model.bases(), 0);
    for (int k = 0; k < 6; ++k) {
      FrameModel::ElementVector r;
      r << element.axes * At(mesh.nodes[element.from].position / length, k).head<3>(),
          element.axes * At(mesh.nodes[element.from].position / length, k).tail<3>(),
          element.axes * At(mesh.nodes[element.to].position / length, k).head<3>(),
          element.axes * At(mesh.nodes[element.to].position / length, k).tail<3>();
      total[k] += r.dot(m0 * r);
    }
  }
  reduced = Eigen::MatrixXd::Zero(model.FreeDofCount(), 6);
  for (int c = 0; c < static_cast<int>(mesh.carriers.size()); ++c) {
    const Eigen::Vector3d p = mesh.carriers[c].position / length;
    for (int k = 0; k < 6; ++k) {
      const FrameModel::Motion r = At(p, k);
      for (int d = 0; d < 6; ++d) {
        if (model.CarrierDof(c, d) >= 0) reduced(model.CarrierDof(c, d), k) = r[d];
      }
      if (mesh.carriers[c].body >= 0) total[k] += r.dot(model.BodyMass(mesh.carriers[c].body) * r);
    }
  }
}

FrameModel::Motion FrameRigidMotions::At(const Eigen::Vector3d& p, int k) const {
  FrameModel::Motion r = FrameModel::Motion::Zero();
  if (k < 3) {
    r[k] = 1.0;
  } else {
    const Eigen::Vector3d axis = Eigen::Vector3d::Unit(k - 3);
    r.head<3>() = axis.cross(p - center);
    r.tail<3>() = axis;
  }
  return r;
}

ModeKind ClassifyFrameMode(const FrameModel& model, const Eigen::VectorXd& shape) {
  std::array<double, kFieldCount> energy{};
  for (int e = 0; e < model.ElementCount(); ++e) {
    const FrameModel::ElementVector u = model.LocalDisplacement(shape, e);
    const FrameModel::ElementVector ku = model.LocalStiffness(e) * u;
    for (int a = 0; a < 12; ++a) {
      energy[static_cast<int>(FieldOf(static_cast<NodalDof>(a % 6)))] += u[a] * ku[a];
    }
  }
  return static_cast<ModeKind>(std::max_element(energy.begin(), energy.end()) - energy.begin());
}

ModalResult SolveModal(const FrameModel& model, const SymmetricBandMatrix& stiffness,
                       const ModalOptions& options) {
  ModalPencil pencil{stiffness, 0.0, Eigen::VectorXd::Zero(model.FreeDofCount()), {}};
  for (int j = 0; j <= model.SeriesOrder(); ++j) pencil.mass.push_back(model.Mass(j));
  ModalResult out = SolvePencilModes(pencil, model.units().time, options);
  for (Mode& mode : out.modes) mode.kind = ClassifyFrameMode(model, mode.shape);
  return out;
}

ModalResult SolveModal(const FrameModel& model, const ModalOptions& options) {
  return SolveModal(model, model.Stiffness(), options);
}

FrameModalResult WithParticipations(const FrameModel& model, ModalResult modes) {
  FrameModalResult out{std::move(modes), {}};
  const FrameRigidMotions rigid(model);
  Eigen::MatrixXd mr(model.FreeDofCount(), 6);
  for (int k = 0; k < 6; ++k) {
    Eigen::VectorXd column(model.FreeDofCount());
    model.Mass(0).Multiply(rigid.reduced.col(k), column);
    mr.col(k) = column;
  }
  for (const Mode& mode : out.modal.modes) {
    std::array<double, 6> share{};
    for (int k = 0; k < 6; ++k) {
      const double gamma = mode.shape.dot(mr.col(k));
      share[k] = rigid.total[k] > 0.0 ? gamma * gamma / rigid.total[k] : 0.0;
    }
    out.participation.push_back(share);
  }
  return out;
}

FrameModalResult SolveFrameModal(const FrameModel& model, const ModalOptions& options) {
  return WithParticipations(model, SolveModal(model, options));
}

FrameModalResult SolveFrameModalAbout(const FrameModel& model, NonlinearForce& force,
                                      const Eigen::VectorXd& d, const ModalOptions& options) {
  ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
  Eigen::VectorXd r = Eigen::VectorXd::Zero(model.FreeDofCount());
  tangent.Clear();
  FrameModalResult out;
  if (!force.Evaluate(d, r, tangent)) {
    out.modal.status = Status::kNonFinite;
    return out;
  }
  if (tangent.rank_one_scale() != 0.0) {
    throw std::invalid_argument("SolveFrameModalAbout: the force's tangent must fit the band");
  }
  tangent.band().mutable_data() += model.Stiffness().data();
  return WithParticipations(model, SolveModal(model, tangent.band(), options));
}

}  // namespace cosmems
