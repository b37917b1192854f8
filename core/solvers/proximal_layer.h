#pragma once
// The floating-layer solver of earlier stops, kept as the fallback of floating_layer.h: proximal
// point steps on the layer's face DOFs (S + αP, P = diag(S), pulling w towards its previous
// value), each solved by the active-set method on the mixed (r, w) problem, α shrinking while
// the statuses settle, and each settled set of statuses tried exactly on the true problem.
// Slow (hundreds of steps), but it converges on some scenes the dual path does not (the
// closing notes of issue 13 list which).
#include "core/solvers/floating_layer.h"

namespace thinlayer {

FloatingLayerRun solve_layer_proximal(const Condensed& c, const ContactProblem& problem,
                                      const CondensedInterface& condensed, const SolverOptions& options,
                                      Eigen::VectorXd r, Eigen::VectorXd w, int max_steps);

}  // namespace thinlayer
