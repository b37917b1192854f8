#include "studies/drivers/floor_study.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "cases/dovetail/dovetail_scenes.h"
#include "studies/drivers/convergence_study.h"
#include "studies/tools/format.h"
#include "studies/tools/mode_distance.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {

namespace {

// One mesh level: the limit scene and the layer at ε and ε·ρ, in the shared cache if it holds
// this mesh (its scenes are written with the rest of it), else in a cache of the level's own.
FloorLevel measure_level(const FloorStudyOptions& options, double h, DovetailSceneCache& shared, H5Writer* out) {
  dovetail::MeshOptions mesh = shared.bulk().options();
  mesh.h_interface = h;
  mesh.h_far = std::max(mesh.h_far, h);
  const bool own = mesh.h_interface != shared.bulk().options().h_interface || mesh.h_far != shared.bulk().options().h_far;
  std::unique_ptr<DovetailLimitBulk> bulk;
  std::unique_ptr<DovetailSceneCache> own_cache;
  if (own) {
    bulk = std::make_unique<DovetailLimitBulk>(mesh);
    own_cache = std::make_unique<DovetailSceneCache>(*bulk, options.threads, options.verbose, "convergence floor h " + plain(h));
  }
  DovetailSceneCache& cache = own ? *own_cache : shared;
  cache.set_progress_tag("convergence floor h " + plain(h));
  const DovetailSceneDef limit = limit_scene(options.law_case, options.tolerance),
                         thick = layer_scene(options.law_case, options.eps.at(0), options.tolerance),
                         thin = layer_scene(options.law_case, options.eps.at(1), options.tolerance);
  cache.solve({limit, thick, thin});
  const DovetailNodes nodes = dovetail_nodes(cache.bulk());
  const DovetailScene &L = cache.get(limit), &A = cache.get(thick), &B = cache.get(thin);
  FloorLevel level;
  level.h = h;
  level.S_nodes = static_cast<int>(nodes.S.size());
  level.converged = L.report.converged && A.report.converged && B.report.converged;
  level.solve_time_s = own ? cache.solve_time_s() : 0.0;
  const FloorPoint point = floor_point(A.record, B.record, L.record, nodes, predicted_rate(options.law_case),
                                      options.eps.at(1) / options.eps.at(0));
  level.floor = point.floor;
  level.eps_part = point.eps_part;
  if (out && own) cache.write(*out);
  return level;
}

void print(const FloorStudyOptions& options, const FloorResult& r, const std::vector<std::string>& quantities) {
  std::printf("\nFloor (S2): case %c, the layer at eps %s against the limit law, as h along S shrinks; in brackets the\n"
              "bound on the eps-part still in it (its Cauchy difference to eps %s, summed over the geometric tail)\n",
              options.law_case, sci(options.eps.at(1), 2).c_str(), sci(options.eps.at(0), 0).c_str());
  std::printf("  %-8s %7s", "h", "S nodes");
  for (const std::string& q : quantities) std::printf(" %20s", q.c_str());
  std::printf("\n");
  for (const FloorLevel& l : r.levels) {
    std::printf("  %-8g %7d", l.h, l.S_nodes);
    for (const std::string& q : quantities)
      std::printf(" %9s (%8s)", sci(l.floor.at(q), 2).c_str(), sci(l.eps_part.at(q), 1).c_str());
    std::printf("%s\n", l.converged ? "" : "  NOT converged");
  }
  std::printf("  %-16s", "rate in h");
  for (const std::string& q : quantities) std::printf(" %20s", rate_text(r.rate.at(q)).c_str());
  std::printf("\n");
}

void write(H5Writer& out, const FloorStudyOptions& options, const FloorResult& r) {
  const std::string g = "/studies/convergence/floor";
  std::vector<double> h;
  std::vector<int> nodes, converged;
  for (const FloorLevel& l : r.levels) {
    h.push_back(l.h);
    nodes.push_back(l.S_nodes);
    converged.push_back(l.converged);
  }
  out.dataset(g + "/h", h);
  out.dataset(g + "/S_nodes", nodes);
  out.dataset(g + "/converged", converged);
  for (const auto& [q, fit] : r.rate) {
    std::vector<double> floor, eps_part;
    for (const FloorLevel& l : r.levels) {
      floor.push_back(l.floor.at(q));
      eps_part.push_back(l.eps_part.at(q));
    }
    out.dataset(g + "/floor_" + q, floor);
    out.dataset(g + "/eps_part_" + q, eps_part);
    out.attr(g, "rate_" + q, fit ? fit->p : 0.0);
    out.attr(g, "rate_" + q + "_stderr", fit ? fit->p_stderr : 0.0);
    out.attr(g, "fitted_" + q, fit ? 1 : 0);
  }
  out.attr(g, "law_case", std::string(1, options.law_case));
  out.attr(g, "eps", options.eps.at(1));
  out.attr(g, "eps_previous", options.eps.at(0));
}

}  // namespace

FloorPoint floor_point(const SceneRecord& thick, const SceneRecord& thin, const SceneRecord& limit,
                       const DovetailNodes& nodes, double p, double rho) {
  const ModeDistance floor = mode_distance(thin, limit, nodes), step = mode_distance(thick, thin, nodes);
  FloorPoint point;
  for (const auto& [q, e] : floor.e) {
    point.floor[q] = e;
    point.eps_part[q] = step.e.at(q) * std::pow(rho, p) / (1 - std::pow(rho, p));  // Σ of the geometric tail
  }
  return point;
}

Check floor_check(const std::string& quantity, const std::vector<double>& floor, const std::vector<double>& eps_part,
                  const std::vector<bool>& converged, const std::optional<PowerLawFit>& rate) {
  bool shrinks = true, eps_part_small = true, all_converged = true;
  std::string got;
  for (size_t i = 0; i < floor.size(); ++i) {
    if (i > 0) shrinks = shrinks && floor[i] < floor[i - 1];
    eps_part_small = eps_part_small && eps_part[i] <= 0.1 * floor[i];
    all_converged = all_converged && converged[i];
    got += (got.empty() ? "" : ", ") + sci(floor[i], 2);
  }
  got += "; rate in h " + rate_text(rate);
  if (!eps_part_small) got += "; eps-part not below a tenth of the floor";
  if (!all_converged) got += "; a scene did not converge";
  return {"", shrinks && eps_part_small && all_converged,
          "floor of " + quantity + " shrinking at every halving of h, its eps-part below a tenth of it", got,
          "strictly decreasing"};
}

FloorResult run_floor_study(const FloorStudyOptions& options, DovetailSceneCache& shared, H5Writer* out,
                            std::vector<Check>& checks) {
  if (options.eps.size() != 2 || !(options.eps[1] < options.eps[0]))
    throw std::invalid_argument("floor study: a pair of thicknesses, the second the thinner");
  FloorResult r;
  for (double h : options.h) r.levels.push_back(measure_level(options, h, shared, out));
  const std::vector<std::string>& quantities = distance_quantities();
  for (const std::string& q : quantities) {
    std::vector<double> h, floor;
    for (const FloorLevel& l : r.levels) {
      h.push_back(l.h);
      floor.push_back(l.floor.at(q));
    }
    r.rate[q] = fit_power_law(h, floor);
  }
  print(options, r, quantities);

  for (const std::string& q : options.checked) {
    std::vector<double> floor, eps_part;
    std::vector<bool> converged;
    for (const FloorLevel& l : r.levels) {
      floor.push_back(l.floor.at(q));
      eps_part.push_back(l.eps_part.at(q));
      converged.push_back(l.converged);
    }
    const Check verdict = floor_check(q, floor, eps_part, converged, r.rate.at(q));
    checks.push_back({"convergence.floor." + q, verdict.pass, verdict.expected, verdict.got, verdict.tolerance});
  }
  if (out) write(*out, options, r);
  return r;
}

}  // namespace thinlayer
