#include "studies/drivers/refinement_study.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/io/scene_record.h"
#include "studies/drivers/convergence_study.h"
#include "studies/drivers/refinement_output.h"
#include "studies/tools/format.h"
#include "studies/tools/mode_distance.h"

namespace thinlayer {

namespace {

constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

// The meshes a rate must hold at (SPEC §3 S2 item 3), with any finer one the run adds.
std::vector<int> required_refinements(const std::vector<int>& refine) {
  std::set<int> r(refine.begin(), refine.end());
  r.insert({1, 2, 4});
  return {r.begin(), r.end()};
}

std::string mesh_name_of(int r) { return r == 1 ? "h" : "h/" + std::to_string(r); }

// One case on one mesh: its scenes read back (and written to the results file), the Cauchy
// differences of the minus-face selection, the two selections' spread, the rates and the floor.
RefinedLevel measure_level(RefinementScenes& scenes, int level, char law_case, const RefinementStudyOptions& options,
                           H5Writer* out) {
  RefinedLevel L;
  L.level = level;
  L.mesh = scenes.mesh_name(level);
  L.h = scenes.h(level);
  const DovetailNodes nodes = dovetail_nodes(scenes.bulk(level));
  L.S_nodes = static_cast<int>(nodes.S.size());
  const std::vector<double>& eps = options.scenes.eps;
  const std::size_t n = eps.size();
  std::vector<std::optional<DovetailScene>> minus, plus;
  for (double e : eps) {
    L.minus.emplace_back(), L.plus.emplace_back();
    minus.push_back(scenes.load(scenes.find(level, law_case, "layer", e, LayerSelection::MinusFace), L.minus.back()));
    plus.push_back(scenes.load(scenes.find(level, law_case, "layer", e, LayerSelection::PlusFace), L.plus.back()));
  }
  const std::optional<DovetailScene> limit = scenes.load(scenes.find(level, law_case, "limit", 0, {}), L.limit);
  if (out) {
    for (const auto* list : {&minus, &plus})
      for (const std::optional<DovetailScene>& s : *list)
        if (s) write_scene(*out, s->record);
    if (limit) write_scene(*out, limit->record);
  }

  for (const std::string& q : distance_quantities()) {
    L.difference[q].assign(n - 1, unknown);
    L.spread[q].assign(n, unknown);
  }
  L.status_changes.assign(n - 1, -1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    if (!L.minus[k].answered() || !L.minus[k + 1].answered()) continue;
    const ModeDistance d = mode_distance(minus[k]->record, minus[k + 1]->record, nodes);
    for (const auto& [q, e] : d.e) L.difference[q][k] = e;
    L.status_changes[k] = d.status_diff;
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!L.minus[k].answered() || !L.plus[k].answered()) continue;
    for (const auto& [q, e] : mode_distance(plus[k]->record, minus[k]->record, nodes).e) L.spread[q][k] = e;
  }

  std::vector<bool> answered;
  for (const SceneOutcome& o : L.minus) answered.push_back(o.answered());
  for (const std::string& q : options.checked) {
    std::vector<double> spread(n - 1, unknown);  // the larger of the difference's two scenes' (unknown if either is)
    for (std::size_t k = 0; k + 1 < n; ++k)
      if (!std::isnan(L.spread[q][k]) && !std::isnan(L.spread[q][k + 1])) spread[k] = std::max(L.spread[q][k], L.spread[q][k + 1]);
    L.rate[q] = refined_rate({eps, answered, L.difference[q], spread, L.status_changes}, options.rule);
  }

  for (std::size_t k = n - 1; k-- > 0 && limit && L.limit.answered();)
    if (L.minus[k].answered() && L.minus[k + 1].answered()) {
      L.floor = floor_point(minus[k]->record, minus[k + 1]->record, limit->record, nodes, predicted_rate(law_case),
                            eps[k + 1] / eps[k]);
      L.floor_eps = eps[k + 1];
      break;
    }
  return L;
}

void judge(RefinedCase& c, const RefinementStudyOptions& options, std::vector<Check>& checks) {
  const std::vector<int> required = required_refinements(options.scenes.refine);
  const std::string case_id = std::string("convergence.refine.") + c.law_case;
  for (const std::string& q : options.checked) {
    std::vector<MeshRate> meshes;
    for (int r : required) {
      MeshRate m{mesh_name_of(r), false, {}};
      for (const RefinedLevel& L : c.levels)
        if (L.mesh == m.mesh) m.run = true, m.rate = L.rate.at(q);
      meshes.push_back(m);
    }
    c.verdict[q] = refined_verdict(meshes, c.p_predicted, options.rule);
    checks.push_back({case_id + "." + q, c.verdict[q].established,
                      "rate " + plain(c.p_predicted) + " +- " + plain(options.rule.tolerance) +
                          " at h, h/2 and h/4 along S, the last two local slopes within " + plain(options.rule.settle) +
                          " (SPEC 3 S2 item 3)",
                      c.verdict[q].line(), plain(options.rule.tolerance)});
  }
  for (const std::string& q : distance_quantities()) {
    std::vector<double> h, floor;
    for (const RefinedLevel& L : c.levels)
      if (L.floor) h.push_back(L.h), floor.push_back(L.floor->floor.at(q));
    c.floor_rate[q] = fit_power_law(h, floor);
  }
  for (const std::string& q : options.floor_checked) {
    std::vector<double> floor, eps_part;
    std::vector<bool> answered;
    for (const RefinedLevel& L : c.levels) {
      floor.push_back(L.floor ? L.floor->floor.at(q) : unknown);
      eps_part.push_back(L.floor ? L.floor->eps_part.at(q) : unknown);
      answered.push_back(L.floor.has_value());
    }
    Check check = floor_check(q, floor, eps_part, answered, c.floor_rate.at(q));
    std::string missing;
    for (int r : required)
      if (std::none_of(c.levels.begin(), c.levels.end(), [&](const RefinedLevel& L) { return L.mesh == mesh_name_of(r); }))
        missing += (missing.empty() ? "" : ", ") + mesh_name_of(r);
    if (!missing.empty()) check.pass = false, check.got += "; " + missing + " not run";
    checks.push_back({case_id + ".floor." + q, check.pass, check.expected, check.got, check.tolerance});
  }
}

}  // namespace

RefinementResult run_refinement_study(const RefinementStudyOptions& options, H5Writer* out) {
  RefinementScenes scenes(options.scenes);
  RefinementResult result;
  result.eps = options.scenes.eps;
  result.solved_now = scenes.solve();
  for (int level = 0; level < static_cast<int>(options.scenes.refine.size()); ++level)
    result.meshes.push_back(scenes.mesh_name(level));
  for (char c : options.scenes.cases) {
    RefinedCase rc;
    rc.law_case = c;
    rc.p_predicted = predicted_rate(c);
    for (int level = 0; level < static_cast<int>(options.scenes.refine.size()); ++level)
      rc.levels.push_back(measure_level(scenes, level, c, options, out));
    judge(rc, options, result.checks);
    result.cases.push_back(std::move(rc));
  }
  print_refinement(result, options);
  if (out) write_refinement(*out, result, options);
  return result;
}

}  // namespace thinlayer
