#pragma once
// Which revision of a solver produced an answer: studies that keep solved scenes between runs
// (`study convergence --refine`, studies/tools/scene_store.h) reuse a stored scene only when it was
// solved by the revision this binary carries, and solve it again otherwise.
//
// Raise a revision with every change that can change an answer, a stop cause or whether a scene
// converges (a new method, a new tolerance rule, a different ladder); a change that keeps every
// answer bit for bit (a rename, a refactoring) leaves it. A stale revision is not unsafe (every
// stored scene keeps its own SPEC residual, which no solver's choice enters) but it makes
// `--resolve stale`, the default, keep answers the new solver would give differently.
#include <string>

#include "core/solvers/solver_choice.h"

namespace thinlayer {

// 1: the fast solver of 2026-11 (condensed active set, sparse Newton, the floating-layer ladder).
constexpr int fast_solver_revision = 1;
// 1: the paper's relaxation (SPEC §1.5).
constexpr int relaxation_solver_revision = 1;

// "fast r1", "relaxation r1": what a stored scene records as its solver.
inline std::string solver_identity(SolverKind solver) {
  return std::string(to_string(solver)) + " r" +
         std::to_string(solver == SolverKind::Fast ? fast_solver_revision : relaxation_solver_revision);
}

}  // namespace thinlayer
