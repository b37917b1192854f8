#include "studies/drivers/selection_control.h"

#include <cstdio>

#include "core/io/column_table.h"
#include "studies/drivers/convergence_study.h"
#include "studies/tools/format.h"
#include "studies/tools/mode_distance.h"

namespace thinlayer {

namespace {

struct Job {
  char law_case;
  LayerQuadrature quadrature;
  double eps, next;
};

DovetailSceneDef def_of(const Job& job, double eps, LayerSelection selection, double tolerance) {
  DovetailSceneDef d = layer_scene(job.law_case, eps, tolerance);
  d.quadrature = job.quadrature;
  d.selection = selection;
  return d;
}

// The jobs: every case × pair with the rule's quadrature, and case (e)'s first pair selective.
std::vector<Job> jobs_of(const SelectionControlOptions& options) {
  std::vector<Job> jobs;
  for (char c : options.cases)
    for (const auto& [eps, next] : options.pairs) jobs.push_back({c, LayerQuadrature::ByExponents, eps, next});
  if (options.cases.find('e') != std::string::npos && !options.pairs.empty())
    jobs.push_back({'e', LayerQuadrature::Selective, options.pairs.front().first, options.pairs.front().second});
  return jobs;
}

void print(const SelectionControlOptions& options, const std::vector<SelectionRow>& rows) {
  std::printf("\nControl (S2): the two selections of the floating layer (spring on its minus or plus face) at the same\n"
              "eps: their spread on what the problem determines, beside the Cauchy difference to the next eps\n");
  std::printf("  %-4s %-10s %-9s", "case", "quadrature", "eps");
  for (const std::string& q : options.quantities) std::printf(" %-21s", (q + " spread/step").c_str());
  std::printf("\n");
  for (const SelectionRow& r : rows) {
    std::printf("  %-4c %-10s %-9s", r.law_case, r.quadrature.c_str(), sci(r.eps, 2).c_str());
    for (size_t i = 0; i < r.spread.size(); ++i)
      std::printf(" %-21s", (sci(r.spread[i], 1) + " / " + sci(r.cauchy[i], 1)).c_str());
    std::printf("%s\n", r.converged ? "" : "  NOT converged");
  }
}

void write(H5Writer& out, const SelectionControlOptions& options, const std::vector<SelectionRow>& rows) {
  ColumnTable table;
  for (const SelectionRow& r : rows) {
    table.add("case", std::string(1, r.law_case));
    table.add("quadrature", r.quadrature);
    table.add("eps", r.eps);
    table.add("converged", r.converged ? 1 : 0);
    table.add("minus_scene", r.minus_id);
    table.add("plus_scene", r.plus_id);
    for (size_t i = 0; i < options.quantities.size(); ++i) {
      table.add("spread_" + options.quantities[i], r.spread[i]);
      table.add("cauchy_" + options.quantities[i], r.cauchy[i]);
    }
  }
  const std::string g = "/studies/convergence/controls/selection";
  table.write(out, g);
  out.attr(g, "agreement", options.agreement);
}

}  // namespace

std::vector<SelectionRow> run_selection_control(const SelectionControlOptions& options, DovetailSceneCache& cache,
                                                H5Writer* out, std::vector<Check>& checks) {
  cache.set_progress_tag("selection control");
  const std::vector<Job> jobs = jobs_of(options);
  std::vector<DovetailSceneDef> defs;
  for (const Job& j : jobs) {
    defs.push_back(def_of(j, j.eps, LayerSelection::MinusFace, options.tolerance));
    defs.push_back(def_of(j, j.eps, LayerSelection::PlusFace, options.tolerance));
    defs.push_back(def_of(j, j.next, LayerSelection::MinusFace, options.tolerance));
  }
  cache.solve(defs);
  const DovetailNodes nodes = dovetail_nodes(cache.bulk());
  std::vector<SelectionRow> rows;
  for (const Job& j : jobs) {
    const DovetailScene& minus = cache.get(def_of(j, j.eps, LayerSelection::MinusFace, options.tolerance));
    const DovetailScene& plus = cache.get(def_of(j, j.eps, LayerSelection::PlusFace, options.tolerance));
    const DovetailScene& next = cache.get(def_of(j, j.next, LayerSelection::MinusFace, options.tolerance));
    const ModeDistance spread = mode_distance(plus.record, minus.record, nodes);
    const ModeDistance step = mode_distance(minus.record, next.record, nodes);
    SelectionRow r{j.law_case, j.quadrature == LayerQuadrature::Selective ? "selective" : "rule", j.eps,
                   minus.report.converged && plus.report.converged, {}, {}, minus.record.id, plus.record.id};
    for (const std::string& q : options.quantities) {
      r.spread.push_back(spread.e.at(q));
      r.cauchy.push_back(step.e.at(q));
    }
    rows.push_back(r);
  }
  print(options, rows);

  for (char c : options.cases) {
    bool pass = true;
    std::string got;
    for (const SelectionRow& r : rows) {
      if (r.law_case != c || r.quadrature != "rule") continue;
      double largest = 0;
      for (double s : r.spread) largest = std::max(largest, s);
      pass = pass && r.converged && largest <= options.agreement;
      got += (got.empty() ? "" : "; ") + std::string("eps ") + sci(r.eps, 1) + ": largest spread " + sci(largest, 1) +
             (r.converged ? "" : " (a selection did not converge)");
    }
    checks.push_back({std::string("convergence.") + c + ".selections_agree", pass,
                      "the two selections of the layer agree on R_top, u and the stresses on S away from the corners "
                      "within " + sci(options.agreement, 0) + " (SPEC 1.5), both converged",
                      got, sci(options.agreement, 0)});
  }
  if (out) write(*out, options, rows);
  return rows;
}

}  // namespace thinlayer
