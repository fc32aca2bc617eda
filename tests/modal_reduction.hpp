#pragma once

// The lowest modes of a model as the modal path's reduction.

#include <gtest/gtest.h>

#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/time/modal_model.hpp"

namespace cosmems::test {

template <int Dim>
ModalModel ModalReduction(const BeamModel<Dim>& model, int count, const DampingModel& damping) {
  ModalOptions options;
  options.count = count;
  const ModalResult modes = SolveModal(model, options);
  EXPECT_EQ(modes.status, Status::kOk);
  return MakeModalModel(model, modes, damping);
}

}  // namespace cosmems::test
