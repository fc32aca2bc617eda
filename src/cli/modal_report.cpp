#include "modal_report.hpp"

#include <chrono>
#include <iomanip>

#include "cosmems/analysis/beam_field.hpp"
#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "csv_file.hpp"
#include "nodal_shape.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

template <int Dim>
std::unique_ptr<ModalReport> RunModal(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  ModalOptions options;
  options.count = scene.analysis.count;
  const auto start = std::chrono::steady_clock::now();
  const BeamModel<Dim> model(MakeBeamDescription(scene));
  ModalResult result;
  if (scene.model.theory == Theory::kStretching) {
    // About the equilibrium under the scene's loads, where stretching has stiffened the beam.
    StretchingForce<Dim> force(model);
    const NonlinearStaticSolution deflected =
        SolveNonlinearStatic(model, force, MakeLoadCase(scene));
    result.status = deflected.status;
    if (deflected.status == Status::kOk) {
      result = SolveModal(model, ModalPencil::About(model, force, deflected.displacement), options);
    }
  } else {
    result = SolveModal(model, options);
  }
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.status;
  header.dofs = model.FreeDofCount();

  std::vector<ModeResult> modes;
  if (result.status == Status::kOk) {
    for (const Mode& mode : result.modes) {
      modes.push_back({mode.frequency_hz, mode.kind,
                       NodalShape(model, mode.shape, mode.kind == ModeKind::kTorsion)});
    }
    if (static_cast<int>(modes.size()) < scene.analysis.count) {
      header.warnings.push_back("analysis.count = " + std::to_string(scene.analysis.count) +
                                " modes asked for, but the model has only " +
                                std::to_string(modes.size()));
    }
  }
  return std::make_unique<ModalReport>(std::move(header), std::move(modes));
}

}  // namespace

std::unique_ptr<ModalReport> ModalReport::Run(const Scene& scene) {
  return scene.model.dimension == 2 ? RunModal<2>(scene) : RunModal<3>(scene);
}

void ModalReport::AddResults(nlohmann::ordered_json& json) const {
  nlohmann::ordered_json frequencies = nlohmann::ordered_json::array();
  nlohmann::ordered_json modes = nlohmann::ordered_json::array();
  for (const ModeResult& mode : modes_) {
    frequencies.push_back(mode.frequency_hz);
    modes.push_back({{"frequency_hz", mode.frequency_hz}, {"kind", ToString(mode.kind)}});
  }
  json["frequencies_hz"] = frequencies;
  json["modes"] = modes;
}

void ModalReport::PrintResults(std::ostream& out) const {
  out << "mode   frequency        kind\n";
  for (std::size_t i = 0; i < modes_.size(); ++i) {
    out << std::setw(4) << i + 1 << "   " << std::setw(10)
        << Significant(modes_[i].frequency_hz / 1e3, 6) << " kHz   " << ToString(modes_[i].kind)
        << "\n";
  }
}

void ModalReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile summary(directory / "modes.csv", "mode,frequency_hz,kind");
  CsvFile shapes(directory / "mode_shapes.csv", "mode,x_m,ux,uy,uz,rx,ry,rz");
  for (std::size_t i = 0; i < modes_.size(); ++i) {
    const std::string number = std::to_string(i + 1);
    summary.Row({number, CsvFile::Number(modes_[i].frequency_hz), ToString(modes_[i].kind)});
    shapes.Rows(modes_[i].shape, number);
  }
  summary.Close();
  shapes.Close();
}

}  // namespace cosmems::internal
