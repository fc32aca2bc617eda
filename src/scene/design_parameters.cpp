#include "cosmems/scene/design_parameters.hpp"

#include "scene_keys.hpp"

namespace cosmems {
namespace {

using internal::ChosenDesign;
using internal::DesignFields;
using internal::IntegerRange;
using internal::NumberRule;

// Visits the design keys (scene_keys.hpp) and keeps those the scene's kind reads.
class DesignLister {
 public:
  explicit DesignLister(std::vector<DesignParameter>& out) : out_(out) {}

  void Design(const char* name, StructureKind kind, DesignFields<double> fields, const NumberRule&,
              const char* meaning) {
    if (const double* value = ChosenDesign(kind, fields))
      out_.push_back({name, *value, false, meaning});
  }
  void Design(const char* name, StructureKind kind, DesignFields<int> fields, const IntegerRange&,
              const char* meaning) {
    if (const int* value = ChosenDesign(kind, fields))
      out_.push_back({name, static_cast<double>(*value), true, meaning});
  }

 private:
  std::vector<DesignParameter>& out_;
};

}  // namespace

std::vector<DesignParameter> DesignParameters(const Scene& scene) {
  std::vector<DesignParameter> out;
  DesignLister lister(out);
  SceneStructure structure = scene.structure;  // the visitor takes the fields to write
  internal::VisitDesigns(lister, structure);
  return out;
}

}  // namespace cosmems
