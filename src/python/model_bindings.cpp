#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "cosmems/analysis/mode_kind.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "model_stepper.hpp"
#include "scene_model.hpp"

namespace py = pybind11;

namespace cosmems::python {
namespace {

void Require(Status status, const std::string& what) {
  if (status != Status::kOk) throw NumericalFailure(what + ": " + ToString(status));
}

// K d = f in SI.
Eigen::VectorXd SolveStaticSi(const SceneModel& model, const Eigen::VectorXd& f_si) {
  if (f_si.size() != model.size()) {
    throw std::invalid_argument("f has " + std::to_string(f_si.size()) +
                                " entries; the model has " + std::to_string(model.size()) +
                                " degrees of freedom");
  }
  const UnitSystem& u = model.units();
  SpdSolver solver;
  Require(solver.Compute(model.Stiffness()), "the static solve");
  Eigen::VectorXd d = f_si.cwiseProduct(model.dof_scale()) / (u.force * u.length);
  solver.SolveInPlace(d);
  if (!d.allFinite()) Require(Status::kNonFinite, "the static solve");
  return d.cwiseProduct(model.dof_scale());
}

// The modes in SI: frequencies [Hz], shapes as columns (m, rad) with phi^T M_0 phi = 1 kg m^2
// for translations, and each mode's kind.
py::tuple ModalSi(const SceneModel& model, int count) {
  if (count < 1) throw std::invalid_argument("count = " + std::to_string(count) + ": must be >= 1");
  ModalResult result;
  {
    py::gil_scoped_release release;
    result = model.Modal(count);
  }
  Require(result.status, "the modal solve");
  const UnitSystem& u = model.units();
  const double normalise = 1.0 / std::sqrt(u.force * u.length * u.time * u.time);
  Eigen::VectorXd frequencies(result.modes.size());
  Eigen::MatrixXd shapes(model.size(), static_cast<Eigen::Index>(result.modes.size()));
  std::vector<std::string> kinds;
  for (std::size_t i = 0; i < result.modes.size(); ++i) {
    const Eigen::Index column = static_cast<Eigen::Index>(i);
    frequencies[column] = result.modes[i].frequency_hz;
    shapes.col(column) = result.modes[i].shape.cwiseProduct(model.dof_scale()) * normalise;
    kinds.emplace_back(ToString(result.modes[i].kind));
  }
  return py::make_tuple(frequencies, shapes, kinds);
}

}  // namespace

void BindModels(py::module_& m) {
  py::class_<SceneModel, std::shared_ptr<SceneModel>>(
      m, "Model",
      "The linear model of a scene's structure (a beam or a device): its free degrees of "
      "freedom, K and the mass terms M_2j of D(w) = K - sum_j w^(2j+2) M_2j in SI, static and "
      "modal solves, and Newmark steppers.")
      .def(py::init([](const std::string& scene, const std::vector<std::string>& sets) {
             return std::make_shared<SceneModel>(LoadWith(scene, sets));
           }),
           py::arg("scene"), py::arg("sets") = std::vector<std::string>{})
      .def_property_readonly("size", &SceneModel::size, "Free degrees of freedom.")
      .def_property_readonly("series_order", &SceneModel::SeriesOrder)
      .def_property_readonly(
          "units",
          [](const SceneModel& model) {
            const UnitSystem& u = model.units();
            py::dict units;
            units["length_m"] = u.length;
            units["force_n"] = u.force;
            units["time_s"] = u.time;
            return units;
          },
          "The internal units the core works in, which a Stepper's state is in.")
      .def_property_readonly(
          "dof_labels",
          [](const SceneModel& model) {
            std::vector<std::string> labels;
            for (const SceneModel::Dof& dof : model.dofs()) labels.push_back(dof.label);
            return labels;
          },
          "\"NAME.uy\": the node or body (\"nodeK\" when unnamed) and the component.")
      .def_property_readonly(
          "dof_positions",
          [](const SceneModel& model) {
            Eigen::MatrixXd positions(model.size(), 3);
            for (int i = 0; i < model.size(); ++i) {
              positions.row(i) = model.dofs()[i].position.transpose();
            }
            return positions;
          },
          "Where each degree of freedom sits (m): its node, or its body's centre.")
      .def_property_readonly(
          "dof_scale", [](const SceneModel& model) { return Eigen::VectorXd(model.dof_scale()); },
          "SI per internal unit of each displacement: the unit length (m) for a translation, 1 "
          "for a rotation.")
      .def(
          "stiffness", [](const SceneModel& model) { return model.MatrixSi(-1); },
          "K in SI (N/m, N, N m) as a scipy.sparse matrix.")
      .def(
          "mass",
          [](const SceneModel& model, int j) {
            if (j < 0 || j > model.SeriesOrder()) {
              throw std::invalid_argument("j = " + std::to_string(j) +
                                          ": the series has terms 0.." +
                                          std::to_string(model.SeriesOrder()));
            }
            return model.MatrixSi(j);
          },
          py::arg("j") = 0,
          "M_2j in SI (kg s^(2j) for translations) as a scipy.sparse matrix; M_0 is the mass.")
      .def(
          "loads", [](const SceneModel& model) { return Eigen::VectorXd(model.loads_si()); },
          "The scene's [loads] as one load vector f (N, N m), the pattern its time function "
          "scales.")
      .def(
          "static",
          [](const SceneModel& model, const Eigen::VectorXd& f) {
            py::gil_scoped_release release;
            return SolveStaticSi(model, f);
          },
          py::arg("f"), "d (m, rad) solving K d = f for the load f (N, N m).")
      .def("modal", &ModalSi, py::arg("count") = 4,
           "(frequencies_hz, shapes, kinds) of the `count` lowest modes of D(w): shapes as "
           "columns in m and rad, mass-normalised in SI.")
      .def(
          "newmark",
          [](std::shared_ptr<SceneModel> model, double time_step, double beta, double gamma,
             std::optional<double> rho_inf, double mass_damping, double stiffness_damping) {
            const GeneralizedAlphaParameters parameters =
                rho_inf ? GeneralizedAlphaParameters::FromSpectralRadius(*rho_inf)
                        : GeneralizedAlphaParameters::Newmark(beta, gamma);
            return std::make_unique<ModelStepper>(std::move(model), time_step, parameters,
                                                  RayleighDamping{mass_damping, stiffness_damping});
          },
          py::arg("time_step"), py::kw_only(), py::arg("beta") = 0.25, py::arg("gamma") = 0.5,
          py::arg("rho_inf") = py::none(), py::arg("mass_damping") = 0.0,
          py::arg("stiffness_damping") = 0.0,
          "A linear stepper of M a + C v + K d = f, C = mass_damping M + stiffness_damping K "
          "(1/s, s): Newmark(beta, gamma), or generalised-alpha of spectral radius rho_inf.");

  py::class_<ModelStepper>(
      m, "Stepper",
      "A time loop on a Model. d, v and a are views, without a copy and writable, of the "
      "stepper's state in the model's internal units (times Model.dof_scale: m and rad; v and a "
      "also over units['time_s'] and its square). Their buffers stay in place for the stepper's "
      "life and every step updates them, so an array kept across steps shows the current "
      "state; a write through it is where the next step starts.")
      .def(
          "initialize",
          [](ModelStepper& stepper, const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
             const Eigen::VectorXd& f0) { Require(stepper.Initialize(d0, v0, f0), "initialize"); },
          py::arg("d0"), py::arg("v0"), py::arg("f0"),
          "The state at t = 0 (SI); the acceleration solves M a0 = f0 - C v0 - K d0.")
      // The step keeps the GIL: on a small model, releasing and taking it back would be a
      // visible part of a step that takes about a microsecond.
      .def(
          "step",
          [](ModelStepper& stepper, const Eigen::Ref<const Eigen::VectorXd>& f) {
            Require(stepper.Step(f), "the step");
          },
          py::arg("f"),
          "One step to the load f (N, N m) at t + dt. A float64 array is read without a copy.")
      .def_property_readonly(
          "d", [](ModelStepper& stepper) -> Eigen::VectorXd& { return stepper.displacement(); },
          py::return_value_policy::reference_internal,
          "The displacement, internal units (times dof_scale: m, rad): a writable view that "
          "stays current across steps.")
      .def_property_readonly(
          "v", [](ModelStepper& stepper) -> Eigen::VectorXd& { return stepper.velocity(); },
          py::return_value_policy::reference_internal,
          "The velocity, internal units (times dof_scale / time_s: m/s, rad/s): a writable view "
          "that stays current across steps.")
      .def_property_readonly(
          "a", [](ModelStepper& stepper) -> Eigen::VectorXd& { return stepper.acceleration(); },
          py::return_value_policy::reference_internal,
          "The acceleration, internal units (times dof_scale / time_s^2: m/s^2, rad/s^2): a "
          "writable view that stays current across steps.")
      .def_property_readonly("time", &ModelStepper::time_s, "s")
      .def_property_readonly("time_step", &ModelStepper::time_step_s, "s");
}

}  // namespace cosmems::python
