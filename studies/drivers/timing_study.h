#pragma once
// Study S5, run time against error (SPEC §3; issue 5), for each solver and mesh level:
//   - the bar (Table 3 row 1, limit mode, Q1 n × n with n contact nodes): the fast solver
//     (condensation + active set, and its solve phase alone), the paper's relaxation at a
//     sweep of tolerances, and two peers on the identical condensed problem, Siconos' fc2d
//     NSGS and Lemke solvers;
//   - the dovetail (case d): limit mode at three element sizes along S, layer mode at ε = 1e-2
//     and 1e-4;
// each against a tightly converged reference and as a ratio to one linear solve
// (factorisation + solve) of the same mesh; then how time grows with the number of unknowns
// (the exponent of a log–log fit) and the targets, met or not. Times are medians.
// "Skip what a scene doesn't need" is its own study (studies/drivers/skip_study.h).
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

struct TimingStudyOptions {
  std::vector<int> fast_levels = {32, 64, 128, 256, 512};  // contact nodes = elements along AD
  std::vector<int> relaxation_levels = {32, 64};
  std::vector<double> relaxation_tolerances = {1e-4, 1e-6, 1e-8, 1e-10};
  int relaxation_cap = 50000;                                // sweeps
  std::vector<int> peer_levels = {32, 64, 128, 256};
  std::vector<double> peer_tolerances = {1e-10};
  // NSGS sweeps / Lemke pivots. NSGS does not converge on the bar from 64 contact nodes on
  // (f = 1; tests/test_siconos_peers.cpp): a cap of 1e4 keeps its 256-node run near 10 s.
  int peer_cap = 10000;
  std::vector<double> dovetail_h = {0.05, 0.025, 0.0125};    // element size along S (L = 1)
  std::vector<double> layer_eps = {1e-2, 1e-4};              // dovetail layer mode, case d, h = 0.025
  int repeats = 3;                                           // medians of this many runs
  // The reference: the fast solver, whose last step is an exact linear solve of the settled
  // statuses, at a residual ten times below any compared solve's. (1e-12 is below the
  // residual's round-off floor on the finest bar: 1.8e-12 measured at 512 contact nodes.)
  double reference_tolerance = 1e-11;

  // The reduced set `verify` runs (about a minute).
  static TimingStudyOptions quick();
};

std::vector<Check> run_timing_study(const TimingStudyOptions& options, H5Writer* out);

}  // namespace thinlayer
