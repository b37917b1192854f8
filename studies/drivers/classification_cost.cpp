#include "studies/drivers/classification_cost.h"

#include <cmath>
#include <sstream>

#include "cases/scene/load_path.h"
#include "core/solvers/stop_verdict.h"
#include "studies/tools/bondline_fields.h"
#include "studies/tools/error_norms.h"
#include "studies/tools/scene_distance.h"

namespace thinlayer {

namespace {

bool same_law(const InterfaceLaw& a, const InterfaceLaw& b) {
  return a.lambda_bar == b.lambda_bar && a.mu_bar == b.mu_bar && a.bilateral == b.bilateral;
}

std::string percent(double x) {
  std::ostringstream s;
  s.precision(3);
  s << 100 * x << " %";
  return s.str();
}

}  // namespace

ClassificationCost classification_cost(SceneFileBulk& bulk, const SceneFileScene& scene, double eps,
                                       const SolverOptions& options) {
  ClassificationCost cost;
  for (const SceneBondline& b : scene.bondlines) cost.differs = cost.differs || !same_law(b.law, b.classified);
  if (!cost.differs) return cost;
  try {
    // What statics proves first (cases/scene/load_path.h): a rule's law with no stiffness where the
    // load needs one leaves it no path, and its solve would only meet a singular system.
    const LoadPath path = check_load_path(bulk.model(), bulk.limit_interfaces(eps, true, true), bulk.spec().units.force);
    if (!path.no_path.empty() || !path.friction_overload.empty()) {
      cost.not_computed = "under that law, " + (path.no_path.empty() ? path.friction_overload : path.no_path);
      return cost;
    }
    const SceneFileScene rule = solve_scene_file_limit(bulk, SolverKind::Fast, options, eps, default_status_tolerance,
                                                       /*classified=*/true);
    if (!usable(rule.report)) {  // one rule (core/solvers/stop_verdict.h): no cost from an unusable answer
      cost.not_computed = "its solve did not converge (" + rule.report.message + ")";
      return cost;
    }
    const Eigen::VectorXd u = adherent_displacements(bulk, scene.record), v = adherent_displacements(bulk, rule.record);
    const double U = std::max(u.cwiseAbs().maxCoeff(), 1e-300);
    cost.u = relative_distance(v, u, Eigen::VectorXd::Ones(u.size()), U);
    cost.reactions = reaction_distance(rule.record, scene.record);
    cost.computed = true;
  } catch (const std::exception& e) {
    cost.not_computed = std::string("its solve failed (") + e.what() + ")";
  }
  return cost;
}

std::string classification_cost_line(const SceneFileBulk& bulk, const SceneFileScene& scene,
                                     const ClassificationCost& cost) {
  if (!cost.differs) return "";
  std::ostringstream s;
  s << "the paper's 3 % / 30x rule (section 3.3) would choose";
  for (std::size_t i = 0; i < scene.bondlines.size(); ++i) {
    const InterfaceLaw& c = scene.bondlines[i].classified;
    s << (i ? "; " : " ") << (bulk.spec().interface_list ? bulk.spec().interfaces[i].group + " " : "") << "class ("
      << c.table1_case() << ") lambda_bar " << c.lambda_bar << ", mu_bar " << c.mu_bar;
  }
  if (cost.computed)
    s << ": solved with it, the reactions are " << percent(cost.reactions) << " and the adherents' displacements "
      << percent(cost.u) << " from this answer (not used: an engineer's glue keeps its finite law, SPEC 1.3)";
  else
    s << ": its distance to this answer is not computed: " << cost.not_computed;
  return s.str();
}

}  // namespace thinlayer
