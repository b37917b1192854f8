#include "studies/drivers/dovetail_study.h"

#include <cstdio>
#include <iostream>
#include <sstream>

#include "cases/dovetail/dovetail_scenes.h"
#include "studies/tools/format.h"
#include "studies/parallel/scene_batch.h"

namespace thinlayer {

namespace {

// Statuses of S that differ between the combined layer statuses and the limit mode's.
int status_differences(const SceneRecord& layer, const SceneRecord& limit) {
  const auto& a = layer.combined_status;
  const auto& b = limit.interfaces.at(0).status;
  int d = 0;
  for (size_t k = 0; k < std::min(a.size(), b.size()); ++k) d += a[k] != b[k];
  return d;
}

// Cost estimates for spreading the scenes over ranks (seconds, measured on the development
// machine; docs/studies.md, "Studies over MPI ranks"): a layer scene takes ~100 times a limit one; the
// relaxation grows with its cap.
constexpr double limit_cost = 0.05;
constexpr double layer_cost = 5.0;
double relaxation_cost(int cap) { return 2e-3 * cap; }

// The relaxation solver's columns of a scene's row (with --relaxation-cap): converged or stopped at
// the cap, its sweeps, its residual; its record written beside the fast solver's.
void relaxation_column(const DovetailScene& r, H5Writer* out) {
  std::printf(" | %s %6d %9s", r.report.converged ? "conv" : "CAP ", r.report.iterations,
              sci(r.report.residual.value(), 2).c_str());
  if (out) write_scene(*out, r.record);
}

}  // namespace

std::vector<Check> run_dovetail_study(const DovetailStudyOptions& options, H5Writer* out) {
  std::vector<Check> checks;
  DovetailLimitBulk bulk;
  const SolverOptions fast;
  SolverOptions fast_layer;
  fast_layer.friction_path = options.friction_path;
  SolverOptions relaxation;
  relaxation.max_iterations = options.relaxation_cap;
  std::printf("\nDovetail (SPEC 2.2): %d nodes on S, f = %g, pull-out (%g, %g) at 45 degrees; counts gap/slide/stick;\n"
              "layer mode: S+ (tenon/layer), S- (layer/base), combined; 'diff' = nodes of S whose combined status\n"
              "differs from the limit mode's; fast solver, tolerance %g\n\n",
              static_cast<int>(bulk.meshes().base.node_set("S").size()), bulk.friction(), dovetail::pull_x,
              dovetail::pull_y, fast.tolerance);
  if (!options.friction_path.empty()) {
    std::printf("layer scenes solved along a friction path: f =");
    for (double t : options.friction_path) std::printf(" %g,", t * bulk.friction());
    std::printf(" then %g (the iterations and times below include every stage)\n\n", bulk.friction());
  }
  std::printf("%-4s %-7s | %-9s %-9s %-9s %4s | %5s %9s %8s %8s", "case", "eps", "S+", "S-", "combined", "diff",
              "it", "residual", "solve[s]", "setup[s]");
  if (options.relaxation_cap) std::printf(" | %-22s", "relaxation (sweeps, residual)");
  std::printf("\n");
  // Every scene, spread over the MPI ranks (if any); one at a time on a rank, since the limit
  // scenes share the bulk's factorisation. Per case: limit, [limit relaxation], then per eps:
  // layer, [layer relaxation].
  const bool relax = options.relaxation_cap > 0;
  const size_t per_case = (1 + relax) * (1 + options.eps.size());
  std::vector<DovetailScene> solved(options.cases.size() * per_case);
  SceneBatch batch("dovetail", 1, options.verbose);
  for (size_t k = 0; k < options.cases.size(); ++k) {
    const char c = options.cases[k];
    const dovetail::Exponents e = dovetail::exponents_of(c);
    const std::string name(1, c);
    DovetailScene* slot = &solved[k * per_case];
    batch.add("case " + name + " limit", limit_cost, *slot++,
              [&, e, name] { return solve_dovetail_limit(bulk, e, name, SolverKind::Fast, fast); });
    if (relax)
      batch.add("case " + name + " limit relaxation", relaxation_cost(options.relaxation_cap), *slot++,
                [&, e, name] { return solve_dovetail_limit(bulk, e, name, SolverKind::Relaxation, relaxation); });
    for (double eps : options.eps) {
      std::ostringstream label;
      label << "case " << c << " layer eps " << eps;
      batch.add(label.str(), layer_cost, *slot++,
                [&, e, name, eps] { return solve_dovetail_layer(bulk, e, eps, name, SolverKind::Fast, fast_layer); });
      if (relax)
        batch.add(label.str() + " relaxation", relaxation_cost(options.relaxation_cap), *slot++, [&, e, name, eps] {
          return solve_dovetail_layer(bulk, e, eps, name, SolverKind::Relaxation, relaxation);
        });
    }
  }
  batch.run();

  const DovetailScene* next = solved.data();
  for (char c : options.cases) {
    const std::string name(1, c);
    const DovetailScene& limit = *next++;
    std::printf("%-4c %-7s | %-9s %-9s %-9s %4s | %5d %9s %8.4f %8.4f", c, "limit", "", "", counts_text(limit.limit).c_str(), "",
                limit.report.iterations, sci(limit.report.residual.value(), 2).c_str(), limit.report.wall_time_s,
                limit.record.numbers.at("setup_time_s"));
    if (out) write_scene(*out, limit.record);
    checks.push_back({"dovetail." + name + ".limit.converged", limit.report.converged, "residual <= 1e-10",
                      sci(limit.report.residual.value(), 2), "1e-10"});
    if (options.relaxation_cap) relaxation_column(*next++, out);
    std::printf("\n");
    for (double eps : options.eps) {
      const DovetailScene& s = *next++;
      std::printf("%-4s %-7g | %-9s %-9s %-9s %4d | %5d %9s %8.4f %8.4f", "", eps, counts_text(s.counts.plus_face).c_str(),
                  counts_text(s.counts.minus_face).c_str(), counts_text(s.counts.combined).c_str(),
                  status_differences(s.record, limit.record), s.report.iterations,
                  sci(s.report.residual.value(), 2).c_str(), s.report.wall_time_s, s.record.numbers.at("setup_time_s"));
      if (out) write_scene(*out, s.record);
      std::ostringstream id;
      id << "dovetail." << c << ".layer_eps" << eps << ".converged";
      checks.push_back({id.str(), s.report.converged, "residual <= 1e-10", sci(s.report.residual.value(), 2), "1e-10"});
      if (options.relaxation_cap) relaxation_column(*next++, out);
      std::printf("\n");
      std::fflush(stdout);
    }
  }
  return checks;
}

}  // namespace thinlayer
