#pragma once
// Which solver solves a scene, and running it: the one choice every case and study makes the
// same way (it lived in the bar's scene builders before the dovetail and scene files used it).
#include <string>

#include "core/solvers/condensed_interface.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

// Relative tolerance of the gap/slide/stick classification (SPEC §1.2), reported with results.
constexpr double default_status_tolerance = 1e-6;

enum class SolverKind { Fast, Relaxation };
SolverKind parse_solver(const std::string& name);  // "fast" | "relaxation", else throws
const char* to_string(SolverKind s);

// Runs the chosen solver; the fast one reuses `condensed` when given.
SolveReport run_solver(const ContactProblem& problem, const CondensedInterface* condensed, SolverKind solver,
                       const SolverOptions& options);

}  // namespace thinlayer
