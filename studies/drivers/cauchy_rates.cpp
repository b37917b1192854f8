#include "studies/drivers/cauchy_rates.h"

#include <cmath>
#include <cstdio>

#include "studies/drivers/convergence_study.h"
#include "studies/tools/format.h"
#include "studies/tools/mode_distance.h"

namespace thinlayer {

namespace {

// The columns printed per case (all quantities go to the file).
const std::vector<std::string> printed = {"R_top", "u", "u_away", "sigma_N", "sigma_N_away", "sigma_T", "sigma_T_away"};

// One case: its grid scenes, their neighbours' differences, and the rate of each quantity.
CaseCauchy measure_case(char law_case, const CauchyStudyOptions& options, DovetailSceneCache& cache,
                        const DovetailNodes& nodes) {
  CaseCauchy c;
  c.law_case = law_case;
  c.p_predicted = predicted_rate(law_case);
  c.eps = options.eps;
  std::vector<const DovetailScene*> scenes;
  for (double eps : options.eps) {
    scenes.push_back(&cache.get(layer_scene(law_case, eps, options.tolerance)));
    c.converged.push_back(scenes.back()->report.converged);
    c.iterations.push_back(scenes.back()->report.iterations);
    c.residual.push_back(scenes.back()->report.residual.value());
    c.layer_ids.push_back(scenes.back()->record.id);
  }
  std::map<std::string, std::vector<double>> difference;
  for (size_t k = 0; k + 1 < scenes.size(); ++k) {
    const ModeDistance d = mode_distance(scenes[k]->record, scenes[k + 1]->record, nodes, default_corner_radius);
    for (const auto& [q, e] : d.e) difference[q].push_back(e);
    c.status_changes.push_back(d.status_diff);
  }
  for (const auto& [q, d] : difference) c.rate[q] = cauchy_rate(c.eps, d, c.converged, options.tail, c.status_changes);
  for (const std::string& q : options.checked) {
    const auto& fit = c.rate.at(q).fit;
    c.pass[q] = fit && std::abs(fit->p - c.p_predicted) <= options.rate_tolerance;
  }
  return c;
}

void print_case(const CaseCauchy& c) {
  std::printf("\ncase %c: Cauchy differences |q(eps_k) - q(eps_k+1)|, predicted p = %g ('*': in the fitted tail)\n",
              c.law_case, c.p_predicted);
  std::printf("  %-10s %5s %9s", "eps_k", "it", "residual");
  for (const std::string& q : printed) std::printf(" %12s", q.c_str());
  std::printf(" %7s\n", "changes");
  for (size_t k = 0; k < c.eps.size(); ++k) {
    std::printf("  %-10s %5d %9s", sci(c.eps[k], 2).c_str(), c.iterations[k], sci(c.residual[k], 1).c_str());
    if (k + 1 < c.eps.size()) {
      for (const std::string& q : printed) {
        const CauchyRate& r = c.rate.at(q);
        std::printf(" %11s%s", sci(r.difference[k], 2).c_str(), r.in_tail[k] ? "*" : " ");
      }
      std::printf(" %7d", c.status_changes[k]);
    }
    std::printf("%s\n", c.converged[k] ? "" : "  NOT converged");
  }
  std::printf("  %-26s", "p (tail)");
  for (const std::string& q : printed) std::printf(" %12s", rate_text(c.rate.at(q).fit).c_str());
  std::printf("\n");
  bool differs = false;
  for (const std::string& q : printed) differs = differs || c.rate.at(q).fit_any_status.has_value() != c.rate.at(q).fit.has_value() ||
                                                 (c.rate.at(q).fit && c.rate.at(q).fit->points != c.rate.at(q).fit_any_status->points);
  if (!differs) return;
  std::printf("  %-26s", "p (across status changes)");
  for (const std::string& q : printed) std::printf(" %12s", rate_text(c.rate.at(q).fit_any_status).c_str());
  std::printf("\n");
}

void write_case(H5Writer& out, const CaseCauchy& c, const CauchyStudyOptions& options) {
  const std::string g = std::string("/studies/convergence/") + c.law_case + "/cauchy";
  out.dataset(g + "/eps", c.eps);
  std::vector<int> converged(c.converged.begin(), c.converged.end());
  out.dataset(g + "/converged", converged);
  out.dataset(g + "/iterations", c.iterations);
  out.dataset(g + "/residual", c.residual);
  out.dataset(g + "/status_changes", c.status_changes);
  out.dataset(g + "/layer_scene", c.layer_ids);
  for (const auto& [q, r] : c.rate) {
    out.dataset(g + "/d_" + q, r.difference);
    out.dataset(g + "/in_tail_" + q, std::vector<int>(r.in_tail.begin(), r.in_tail.end()));
    out.attr(g, "p_" + q, r.fit ? r.fit->p : 0.0);
    out.attr(g, "p_" + q + "_stderr", r.fit ? r.fit->p_stderr : 0.0);
    out.attr(g, "C_" + q, r.fit ? r.fit->C : 0.0);
    out.attr(g, "points_" + q, r.fit ? r.fit->points : 0);
    out.attr(g, "fitted_" + q, r.fit ? 1 : 0);
    out.attr(g, "p_" + q + "_any_status", r.fit_any_status ? r.fit_any_status->p : 0.0);
    out.attr(g, "p_" + q + "_any_status_stderr", r.fit_any_status ? r.fit_any_status->p_stderr : 0.0);
    out.attr(g, "fitted_" + q + "_any_status", r.fit_any_status ? 1 : 0);
  }
  for (const auto& [q, pass] : c.pass) out.attr(g, "pass_" + q, pass ? 1 : 0);
  out.attr(g, "p_predicted", c.p_predicted);
  out.attr(g, "grid_ratio", c.eps.size() > 1 ? c.eps[1] / c.eps[0] : 0.0);
  std::string checked;
  for (const std::string& q : options.checked) checked += (checked.empty() ? "" : ",") + q;
  out.attr(g, "checked", checked);
}

}  // namespace

std::vector<CaseCauchy> run_cauchy_rates(const CauchyStudyOptions& options, DovetailSceneCache& cache, H5Writer* out,
                                         std::vector<Check>& checks) {
  cache.set_progress_tag("convergence rates");
  std::vector<DovetailSceneDef> defs;
  for (char c : options.cases)
    for (double eps : options.eps) defs.push_back(layer_scene(c, eps, options.tolerance));
  cache.solve(defs);
  const DovetailNodes nodes = dovetail_nodes(cache.bulk());

  std::printf("\nConvergence rates (S2): Cauchy differences of the layer model along eps (grid ratio %s), relative\n"
              "to the distances' scales (mode_distance.h); scenes solved to residual %s; the rate is fitted on the\n"
              "differences with eps_k <= %s whose two scenes converged, below the last status change between converged\n"
              "neighbours, at least %d of them\n",
              sci(options.eps.size() > 1 ? options.eps[1] / options.eps[0] : 0, 3).c_str(), sci(options.tolerance, 0).c_str(),
              sci(options.tail.eps_max, 0).c_str(), options.tail.min_differences);
  std::vector<CaseCauchy> result;
  for (char law_case : options.cases) {
    result.push_back(measure_case(law_case, options, cache, nodes));
    print_case(result.back());
  }

  std::printf("\nRates from the Cauchy differences (p +- standard error; predicted; verdict within %g)\n", options.rate_tolerance);
  std::printf("%-4s %-9s", "case", "predicted");
  for (const std::string& q : options.checked) std::printf(" %-17s", q.c_str());
  std::printf("\n");
  for (const CaseCauchy& c : result) {
    std::printf("%-4c %-9g", c.law_case, c.p_predicted);
    for (const std::string& q : options.checked)
      std::printf(" %-12s %-4s", rate_text(c.rate.at(q).fit).c_str(), c.pass.at(q) ? "pass" : "FAIL");
    std::printf("\n");
    for (const std::string& q : options.checked) {
      const auto& fit = c.rate.at(q).fit;
      char expected[96];
      std::snprintf(expected, sizeof expected, "p(%s, Cauchy differences, eps <= %s) = %g +- %g", q.c_str(),
                    sci(options.tail.eps_max, 0).c_str(), c.p_predicted, options.rate_tolerance);
      checks.push_back({std::string("convergence.") + c.law_case + ".rate." + q, c.pass.at(q), expected,
                        fit ? rate_text(fit) : "not measurable (fewer than " + std::to_string(options.tail.min_differences) +
                                                   " converged tail differences)",
                        std::to_string(options.rate_tolerance)});
    }
    if (out) write_case(*out, c, options);
  }
  return result;
}

}  // namespace thinlayer
