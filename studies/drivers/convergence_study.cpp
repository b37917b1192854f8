#include "studies/drivers/convergence_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "core/io/reference_tables.h"
#include "studies/tools/format.h"

namespace thinlayer {

DovetailSceneDef limit_scene(char law_case, double tolerance) {
  return {"limit", std::string(1, law_case), 0.0, tolerance};
}

DovetailSceneDef layer_scene(char law_case, double eps, double tolerance) {
  return {"layer", std::string(1, law_case), eps, tolerance};
}

DovetailNodes dovetail_nodes(DovetailLimitBulk& bulk) {
  DovetailNodes n;
  n.base_nodes = bulk.meshes().base.num_nodes();
  n.tenon_nodes = bulk.meshes().tenon.num_nodes();
  n.base_x = bulk.meshes().base.nodes;
  n.tenon_x = bulk.meshes().tenon.nodes;
  n.S = dovetail::make_limit_interface(bulk.model(), InterfaceLaw{}).nodes;
  return n;
}

double predicted_rate(char c) {
  for (const PredictedRate& r : load_predicted_rates())
    if (r.law_case == c) return r.p;
  throw std::runtime_error(std::string("reference/predicted_rates.csv has no case ") + c);
}

namespace {

void print_case(const CaseConvergence& c, const std::vector<DovetailScene const*>& layers) {
  std::printf("\ncase %c (gamma %g, delta %g): predicted p = %g\n", c.law_case, c.gamma, c.delta, c.p_predicted);
  std::printf("  %-7s", "eps");
  for (const std::string& q : distance_quantities()) std::printf(" %12s", q.c_str());
  std::printf(" %5s %5s %9s %8s\n", "diff", "it", "residual", "time[s]");
  for (size_t i = 0; i < c.eps.size(); ++i) {
    std::printf("  %-7g", c.eps[i]);
    for (const std::string& q : distance_quantities()) std::printf(" %12s", sci(c.distance[i].e.at(q), 2).c_str());
    const SolveReport& r = layers[i]->report;
    std::printf(" %5d %5d %9s %8.2f%s\n", c.distance[i].status_diff, r.iterations, sci(r.residual.value(), 1).c_str(),
                r.wall_time_s, r.converged ? "" : "  NOT converged");
  }
  print_fit_rows(distance_quantities(), c.fit, c.floor_fit, 7, 12);
}

void write_case(H5Writer& out, const CaseConvergence& c) {
  const std::string g = std::string("/studies/convergence/") + c.law_case;
  out.dataset(g + "/eps", c.eps);
  for (const std::string& q : distance_quantities()) {
    std::vector<double> e;
    for (const ModeDistance& d : c.distance) e.push_back(d.e.at(q));
    out.dataset(g + "/e_" + q, e);
    const auto& f = c.fit.at(q);
    out.attr(g, "p_" + q, f ? f->p : 0.0);
    out.attr(g, "p_" + q + "_stderr", f ? f->p_stderr : 0.0);
    out.attr(g, "fitted_" + q, f ? 1 : 0);
    const auto& ff = c.floor_fit.at(q);
    out.attr(g, "p_floor_" + q, ff ? ff->p : 0.0);
    out.attr(g, "p_floor_" + q + "_stderr", ff ? ff->p_stderr : 0.0);
    out.attr(g, "floor_" + q, ff ? ff->floor : 0.0);
    out.attr(g, "C_floor_" + q, ff ? ff->C : 0.0);
    out.attr(g, "fitted_floor_" + q, ff ? 1 : 0);
  }
  std::vector<int> diff, converged;
  for (size_t i = 0; i < c.distance.size(); ++i) {
    diff.push_back(c.distance[i].status_diff);
    converged.push_back(c.converged[i]);
  }
  out.dataset(g + "/status_diff", diff);
  out.dataset(g + "/converged", converged);
  out.dataset(g + "/layer_scene", c.layer_ids);
  out.attr(g, "limit_scene", c.limit_id);
  out.attr(g, "gamma", c.gamma);
  out.attr(g, "delta", c.delta);
  out.attr(g, "p_predicted", c.p_predicted);
}

}  // namespace

ConvergenceResult run_convergence_study(const ConvergenceStudyOptions& options, DovetailSceneCache& cache,
                                        H5Writer* out) {
  if (options.eps.size() < 3) throw std::invalid_argument("the convergence study needs at least 3 thicknesses");
  cache.set_progress_tag("convergence");
  std::vector<DovetailSceneDef> defs;
  for (char c : options.cases) {
    defs.push_back(limit_scene(c, options.tolerance));
    for (double eps : options.eps) defs.push_back(layer_scene(c, eps, options.tolerance));
  }
  cache.solve(defs);
  const DovetailNodes nodes = dovetail_nodes(cache.bulk());

  std::printf("\nConvergence (S2): relative L2 distances between the layer and limit modes of the dovetail;\n"
              "*_away: farther than %g from the slot corners; diff: S nodes whose combined status differs;\n"
              "scenes solved to residual %g; rate p of e(eps) ~ C eps^p by least squares (± standard error)\n",
              options.corner_radius, options.tolerance);
  ConvergenceResult result;
  for (char c : options.cases) {
    CaseConvergence cc;
    cc.law_case = c;
    const dovetail::Exponents e = dovetail::exponents_of(c);
    cc.gamma = e.gamma;
    cc.delta = e.delta;
    cc.p_predicted = predicted_rate(c);
    const DovetailScene& limit = cache.get(limit_scene(c, options.tolerance));
    cc.limit_id = limit.record.id;
    cc.limit_converged = limit.report.converged;
    std::vector<const DovetailScene*> layers;
    for (double eps : options.eps) {
      const DovetailScene& s = cache.get(layer_scene(c, eps, options.tolerance));
      layers.push_back(&s);
      cc.eps.push_back(eps);
      cc.distance.push_back(mode_distance(s.record, limit.record, nodes, options.corner_radius));
      cc.converged.push_back(s.report.converged);
      cc.layer_ids.push_back(s.record.id);
    }
    for (const std::string& q : distance_quantities()) {
      std::vector<double> e_q;
      for (const ModeDistance& d : cc.distance) e_q.push_back(d.e.at(q));
      cc.fit[q] = fit_power_law(cc.eps, e_q);
      cc.floor_fit[q] = fit_power_law_with_floor(cc.eps, e_q);
    }
    const auto& primary = cc.floor_fit.at(options.primary);
    cc.pass = primary && std::abs(primary->p - cc.p_predicted) <= options.rate_tolerance;
    print_case(cc, layers);

    // The rate itself is checked on the Cauchy differences (cauchy_rates.h), where the mesh
    // floor cancels; the fits above are shown for comparison only.
    const std::string id = std::string("convergence.") + c;
    const int converged = static_cast<int>(std::count(cc.converged.begin(), cc.converged.end(), true)) + cc.limit_converged;
    result.checks.push_back({id + ".scenes_converged", converged == static_cast<int>(cc.eps.size()) + 1,
                             std::to_string(cc.eps.size() + 1) + " scenes at residual <= " + sci(options.tolerance, 0),
                             std::to_string(converged), sci(options.tolerance, 0)});
    result.cases.push_back(std::move(cc));
  }

  std::printf("\nRates of %s fitted to the modes' distance (for comparison: the check uses the Cauchy differences):\n"
              "floored fit e = e_inf + C eps^p and plain fit e = C eps^p\n",
              options.primary.c_str());
  std::printf("%-4s %-6s %-6s | %-9s | %-11s %-9s %-5s | %-11s\n", "case", "gamma", "delta", "predicted", "p (floor)",
              "e_inf", "", "p (plain)");
  for (const CaseConvergence& c : result.cases) {
    const auto& ff = c.floor_fit.at(options.primary);
    std::printf("%-4c %-6g %-6g | %-9g | %-11s %-9s %-5s | %-11s\n", c.law_case, c.gamma, c.delta, c.p_predicted,
                rate_text(ff).c_str(), ff ? sci(ff->floor, 1).c_str() : "n/a", c.pass ? "near" : "off",
                rate_text(c.fit.at(options.primary)).c_str());
  }

  // The solver's share: case (d) (the smallest distances, so the most sensitive; else the first
  // case) at the largest and smallest ε re-solved to the SPEC tolerance 1e-10, its distances
  // against the study's.
  double solver_effect = 0, solver_effect_all = 0;  // on the primary quantity, on every quantity
  if (options.solver_check && options.tolerance != 1e-10 && !result.cases.empty()) {
    const auto d_case = std::find_if(result.cases.begin(), result.cases.end(),
                                     [](const CaseConvergence& c) { return c.law_case == 'd'; });
    const CaseConvergence& c = d_case != result.cases.end() ? *d_case : result.cases.front();
    const auto [smallest, largest] = std::minmax_element(c.eps.begin(), c.eps.end());
    cache.solve({limit_scene(c.law_case, 1e-10), layer_scene(c.law_case, *smallest, 1e-10),
                 layer_scene(c.law_case, *largest, 1e-10)});
    const DovetailScene& tight_limit = cache.get(limit_scene(c.law_case, 1e-10));
    bool converged = tight_limit.report.converged;
    std::string worst;
    for (const auto eps : {smallest, largest}) {
      const size_t i = static_cast<size_t>(eps - c.eps.begin());
      const DovetailScene& tight = cache.get(layer_scene(c.law_case, *eps, 1e-10));
      converged = converged && tight.report.converged;
      const ModeDistance d = mode_distance(tight.record, tight_limit.record, nodes, options.corner_radius);
      for (const std::string& q : distance_quantities()) {
        const double effect = std::abs(c.distance[i].e.at(q) - d.e.at(q)) / d.e.at(q);
        if (effect > solver_effect_all) worst = q + " at eps " + sci(*eps, 0);
        solver_effect_all = std::max(solver_effect_all, effect);
        if (q == options.primary) solver_effect = std::max(solver_effect, effect);
      }
    }
    std::printf("\nsolver tolerance: case %c at eps %g and %g re-solved to 1e-10 (%s): the distance %s moves by %s\n"
                "(relative), the other distances by at most %s (%s); read those with that margin\n",
                c.law_case, *smallest, *largest, converged ? "converged" : "NOT converged", options.primary.c_str(),
                sci(solver_effect, 1).c_str(), sci(solver_effect_all, 1).c_str(), worst.c_str());
    result.checks.push_back({"convergence.solver_tolerance", converged && solver_effect <= 0.01,
                             "distance " + options.primary + " at residual " + sci(options.tolerance, 0) +
                                 " within 1% of that at 1e-10",
                             sci(solver_effect, 1), "0.01"});
  }

  if (out) {
    const std::string g = "/studies/convergence";
    out->attr(g, "tolerance", options.tolerance);
    out->attr(g, "corner_radius", options.corner_radius);
    out->attr(g, "primary_quantity", options.primary);
    out->attr(g, "rate_tolerance", options.rate_tolerance);
    out->attr(g, "solver_tolerance_effect", solver_effect);
    out->attr(g, "solver_tolerance_effect_all_quantities", solver_effect_all);
    for (const CaseConvergence& c : result.cases) {
      write_case(*out, c);
      const auto& f = c.floor_fit.at(options.primary);
      const std::string cg = std::string(g) + "/" + c.law_case;
      out->attr(cg, "p_fit", f ? f->p : 0.0);
      out->attr(cg, "p_stderr", f ? f->p_stderr : 0.0);
      out->attr(cg, "C_fit", f ? f->C : 0.0);
      out->attr(cg, "floor_fit", f ? f->floor : 0.0);
      out->attr(cg, "fit_model", std::string("e = floor + C eps^p"));
      out->attr(cg, "pass", c.pass ? 1 : 0);
    }
  }
  return result;
}

}  // namespace thinlayer
