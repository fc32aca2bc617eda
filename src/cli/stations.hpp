#pragma once

#include <Eigen/Core>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "cosmems/structure/frame_model.hpp"
#include "csv_file.hpp"

namespace cosmems::internal {

/// The points at which a report lists a structure's motions: along a straight beam's axis, at
/// each node of its one member's mesh (rows labelled by x in m: a cantilever's or a bridge's CSV
/// files), or at every named node, then every body's centre (rows labelled by name).
class Stations {
 public:
  Stations() = default;
  /// `along_axis`: a straight beam's stations (its first member's mesh nodes, x from its first
  /// node).
  Stations(const FrameModel& model, bool along_axis) : along_axis_(along_axis) {
    if (along_axis) {
      const StructureDescription& s = model.description();
      const StructureMember& member = s.members.at(0);
      for (int k = 0; k <= member.elements; ++k) {
        at_.push_back(static_cast<double>(k) / member.elements);
      }
      const double length = (s.nodes[member.to].position - s.nodes[member.from].position).norm();
      for (double at : at_) labels_.push_back(CsvFile::Number(at * length));
      return;
    }
    for (const StructureNode& node : model.description().nodes) labels_.push_back(node.name);
    for (const StructureBody& body : model.description().bodies) labels_.push_back(body.name);
  }

  /// Stations at x (internal units of `length_unit` m) along the axis of a beam that is not a
  /// frame (the Cosserat rod): labels for the rows of values computed elsewhere; Motions() and
  /// Shape() need a frame's stations.
  static Stations AlongAxis(const std::vector<double>& x, double length_unit) {
    Stations out;
    out.along_axis_ = true;
    for (double xi : x) out.labels_.push_back(CsvFile::Number(xi * length_unit));
    return out;
  }

  /// The CSV column that labels the rows: "x_m" or "name".
  std::string Key() const { return along_axis_ ? "x_m" : "name"; }

  /// The motions (SI: ux, uy, uz in m, rx, ry, rz in rad) of the reduced state d (internal units)
  /// at every station, one row each.
  Eigen::MatrixXd Motions(const FrameModel& model, const Eigen::VectorXd& d) const {
    Eigen::MatrixXd values(static_cast<Eigen::Index>(labels_.size()), 6);
    if (along_axis_) {
      for (std::size_t k = 0; k < at_.size(); ++k) {
        values.row(k) = model.MemberMotion(d, 0, at_[k]).transpose();
      }
    } else {
      const int nodes = static_cast<int>(model.description().nodes.size());
      for (int n = 0; n < nodes; ++n) values.row(n) = model.NodeMotion(d, n).transpose();
      for (std::size_t b = 0; b < model.mesh().body_carrier.size(); ++b) {
        values.row(nodes + b) = model.CarrierMotion(d, model.mesh().body_carrier[b]).transpose();
      }
    }
    values.leftCols<3>() *= model.units().length;
    return values;
  }

  /// A mode or buckling shape (reduced, internal units) at every station, scaled so that its
  /// largest translation is +1, or its largest rotation for a shape that barely translates (a
  /// twist): a solver's normalisation and sign mean nothing on a plot. Of components equal in
  /// size to 1e-9 (a symmetric structure's mirrored stations) the first, station by station, is
  /// the positive one, so the sign does not hang on the solver's numbering or its round-off.
  Eigen::MatrixXd Shape(const FrameModel& model, const Eigen::VectorXd& shape) const {
    const Eigen::MatrixXd values = Motions(model, shape);
    int columns = 0;  // the translations'
    double largest = values.leftCols<3>().cwiseAbs().maxCoeff();
    const double twist = values.rightCols<3>().cwiseAbs().maxCoeff();
    if (!(largest > 1e-6 * twist * model.units().length)) {
      columns = 3;
      largest = twist;
    }
    if (!(largest > 0.0)) return values;
    for (Eigen::Index r = 0; r < values.rows(); ++r) {
      for (int c = columns; c < columns + 3; ++c) {
        if (std::abs(values(r, c)) >= (1.0 - 1e-9) * largest) return values / values(r, c);
      }
    }
    return values / largest;
  }

  /// The motions `values` (one row per station, SI) in `directory`: in `along_axis_file` with
  /// x_m rows along a beam, in nodes.csv with name rows at every node and body.
  void WriteMotions(const std::filesystem::path& directory, const std::string& along_axis_file,
                    const Eigen::MatrixXd& values) const {
    CsvFile csv(directory / (along_axis_ ? along_axis_file : "nodes.csv"),
                Key() + ",ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
    WriteRows(csv, values);
    csv.Close();
  }

  /// Rows of `values` (one per station), each after `first_cell` when given and the station's
  /// label.
  void WriteRows(CsvFile& csv, const Eigen::MatrixXd& values,
                 const std::string& first_cell = "") const {
    for (std::size_t k = 0; k < labels_.size(); ++k) {
      std::vector<std::string> cells;
      if (!first_cell.empty()) cells.push_back(first_cell);
      cells.push_back(labels_[k]);
      for (Eigen::Index c = 0; c < values.cols(); ++c) {
        cells.push_back(CsvFile::Number(values(static_cast<Eigen::Index>(k), c)));
      }
      csv.Row(cells);
    }
  }

 private:
  bool along_axis_ = false;
  std::vector<double> at_;  ///< along the axis: each station's fraction of the member
  std::vector<std::string> labels_;
};

}  // namespace cosmems::internal
