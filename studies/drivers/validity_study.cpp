#include "studies/drivers/validity_study.h"

#include <algorithm>
#include <cstdio>

#include "core/io/column_table.h"
#include "studies/tools/bisection.h"
#include "studies/tools/format.h"

namespace thinlayer {

namespace {

struct Job {
  ValidityRow row;
  Bracket bracket;
  bool bisect = false;
};

// The bracket from the samples: the largest sampled ε within τ and the next sampled ε above it.
Job initial(const CaseConvergence& c, double tau, const std::string& quantity) {
  std::vector<size_t> order(c.eps.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return c.eps[a] < c.eps[b]; });
  auto e = [&](size_t i) { return c.distance[i].e.at(quantity); };
  Job job;
  job.row.law_case = c.law_case;
  job.row.tau = tau;
  job.row.quantity = quantity;
  const size_t largest = order.back(), smallest = order.front();
  if (e(largest) <= tau) {
    job.row = {c.law_case, tau, quantity, "at_least", c.eps[largest], e(largest), 0.0, 0, c.converged[largest]};
    return job;
  }
  int within = -1;
  for (size_t k = 0; k < order.size(); ++k)
    if (e(order[k]) <= tau) within = static_cast<int>(k);
  if (within < 0) {
    job.row = {c.law_case, tau, quantity, "below_range", c.eps[smallest], e(smallest), c.eps[smallest], 0,
               c.converged[smallest]};
    return job;
  }
  const size_t lo = order[within], hi = order[within + 1];
  job.row.status = "found";
  job.row.converged = c.converged[lo] && c.converged[hi];  // the scenes the answer rests on
  job.bracket = {c.eps[lo], e(lo), c.eps[hi], e(hi)};
  job.bisect = true;
  return job;
}

// The case's samples: the convergence study's, and those of `extra_eps` (the rate grid, already
// solved) that it does not have.
CaseConvergence with_samples(const CaseConvergence& c, const std::vector<double>& extra_eps, double tolerance,
                             DovetailSceneCache& cache, const DovetailNodes& nodes, double corner_radius) {
  CaseConvergence all = c;
  const DovetailScene& limit = cache.get(limit_scene(c.law_case, tolerance));
  for (double eps : extra_eps) {
    if (std::find(all.eps.begin(), all.eps.end(), eps) != all.eps.end()) continue;
    const DovetailScene& layer = cache.get(layer_scene(c.law_case, eps, tolerance));
    all.eps.push_back(eps);
    all.distance.push_back(mode_distance(layer.record, limit.record, nodes, corner_radius));
    all.converged.push_back(layer.report.converged);
  }
  return all;
}

}  // namespace

std::vector<ValidityRow> run_validity_study(const ValidityStudyOptions& options, const ConvergenceResult& samples,
                                            const ConvergenceStudyOptions& convergence, DovetailSceneCache& cache,
                                            H5Writer* out, std::vector<Check>& checks) {
  cache.set_progress_tag("validity");
  const DovetailNodes nodes = dovetail_nodes(cache.bulk());
  std::vector<Job> jobs;
  std::vector<DovetailSceneDef> extra;
  for (const CaseConvergence& c : samples.cases)
    for (double eps : options.extra_eps) extra.push_back(layer_scene(c.law_case, eps, convergence.tolerance));
  cache.solve(extra);
  for (const CaseConvergence& sampled : samples.cases) {
    const CaseConvergence c =
        with_samples(sampled, options.extra_eps, convergence.tolerance, cache, nodes, convergence.corner_radius);
    for (const std::string& q : options.quantities)
      for (double tau : options.taus) jobs.push_back(initial(c, tau, q));
  }

  // Bisection in rounds: the midpoints of every open bracket are solved together (in parallel).
  for (int step = 0; step < options.bisection_steps; ++step) {
    std::vector<DovetailSceneDef> round;
    for (const Job& j : jobs)
      if (j.bisect) round.push_back(layer_scene(j.row.law_case, log_midpoint(j.bracket), convergence.tolerance));
    cache.solve(round);
    for (Job& j : jobs) {
      if (!j.bisect) continue;
      const double eps = log_midpoint(j.bracket);
      const DovetailScene& layer = cache.get(layer_scene(j.row.law_case, eps, convergence.tolerance));
      const DovetailScene& limit = cache.get(limit_scene(j.row.law_case, convergence.tolerance));
      const double e = mode_distance(layer.record, limit.record, nodes, convergence.corner_radius).e.at(j.row.quantity);
      j.bracket = narrow(j.bracket, eps, e, j.row.tau);
      j.row.converged = j.row.converged && layer.report.converged;
      ++j.row.bisection_steps;
    }
  }

  std::printf("\nThickness validity (S3): the largest eps at which the limit law stays within tau of the layer model,\n"
              "on each determined quantity (the adherents' displacements u, the tenon-top reaction R_top, the\n"
              "stresses on S), by %d bisection steps on log eps between samples; paper: valid up to %g\n\n",
              options.bisection_steps, options.paper_claim);
  std::printf("%-4s %-8s %-5s | %-11s %-10s %-11s %-10s | %s\n", "case", "quantity", "tau", "eps_max", "error",
              "first eps>", "status", "valid at paper's 1e-3?");
  std::vector<ValidityRow> rows;
  for (Job& j : jobs) {
    ValidityRow r = j.row;
    if (j.bisect) {
      r.eps_max = j.bracket.eps_within;
      r.error_at_eps_max = j.bracket.error_within;
      r.eps_beyond = j.bracket.eps_beyond;
    }
    const bool valid_at_claim = r.eps_max >= options.paper_claim && r.status != "below_range";
    std::printf("%-4c %-8s %-5g | %-11s %-10s %-11s %-10s | %s\n", r.law_case, r.quantity.c_str(), r.tau,
                (r.status == "at_least" ? ">= " + sci(r.eps_max, 1) : r.status == "below_range" ? "< " + sci(r.eps_max, 1)
                                                                                                 : sci(r.eps_max, 2))
                    .c_str(),
                sci(r.error_at_eps_max, 2).c_str(), r.status == "found" ? sci(r.eps_beyond, 2).c_str() : "-",
                r.status.c_str(), valid_at_claim ? "yes" : "no");
    char tau_pct[16];
    std::snprintf(tau_pct, sizeof tau_pct, "%g", r.tau * 100);
    checks.push_back({std::string("validity.") + r.law_case + "." + r.quantity + ".tau" + tau_pct + "pct.converged",
                      r.converged,
                      "every scene of the bracket at residual <= " + sci(convergence.tolerance, 0),
                      r.converged ? "all converged" : "a scene did not converge", sci(convergence.tolerance, 0)});
    rows.push_back(r);
  }

  if (out) {
    ColumnTable table;
    for (const ValidityRow& r : rows) {
      table.add("case", std::string(1, r.law_case));
      table.add("quantity", r.quantity);
      table.add("tau", r.tau);
      table.add("status", r.status);
      table.add("eps_max", r.eps_max);
      table.add("error_at_eps_max", r.error_at_eps_max);
      table.add("eps_beyond", r.eps_beyond);
      table.add("bisection_steps", r.bisection_steps);
      table.add("converged", r.converged ? 1 : 0);
    }
    const std::string g = "/studies/validity";
    table.write(*out, g);
    std::string quantities;
    for (const std::string& q : options.quantities) quantities += (quantities.empty() ? "" : ",") + q;
    out->attr(g, "quantities", quantities);
    out->attr(g, "paper_claim", options.paper_claim);
  }
  return rows;
}

}  // namespace thinlayer
