#pragma once

#include <ostream>
#include <vector>

#include "sweep_request.hpp"
#include "sweep_row.hpp"

namespace cosmems::internal {

/// `cosmems sweep`: validates the whole sweep before any sample runs (every grid value and
/// every distribution's median must make a valid scene; a bad key or value throws SceneError
/// or CliInputError), runs the samples of its shard that the --out folder does not hold yet on
/// `threads` workers, then prints the summary (doc/sweeps.md) on `out`: one JSON object with
/// --json, a table otherwise. `progress` draws a progress line on `err`. Returns 0; a sample
/// that fails is a row with its status. Built with MPI and started by an MPI launcher with more
/// than one rank, rank 0 runs the sweep and the other ranks its samples (MpiWorld). `rows`, when
/// given, receives the rows the summary covers (the folder's, with --out), sorted by index.
int RunSweep(const SweepRequest& request, std::ostream& out, std::ostream& err, bool progress,
             std::vector<SweepRow>* rows = nullptr);

}  // namespace cosmems::internal
