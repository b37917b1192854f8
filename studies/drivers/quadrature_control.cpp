#include "studies/drivers/quadrature_control.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "studies/drivers/convergence_study.h"
#include "studies/tools/format.h"
#include "studies/tools/mode_distance.h"
#include "studies/tools/zigzag.h"

namespace thinlayer {

namespace {

// σ_N on S+ (daN/mm²) at the right flank's nodes, from the bottom corner up.
std::vector<double> flank_sigma_N(const SceneRecord& r, const std::vector<int>& flank) {
  std::vector<double> v;
  for (int k : flank) v.push_back(r.interfaces.front().sigma_N[k]);
  return v;
}

// `flank_away`: the right flank's nodes away from its corners (there σ_N's own curvature is large).
QuadratureSide measure_side(const std::vector<const DovetailScene*>& scenes, const DovetailNodes& nodes,
                            const std::vector<int>& flank_away, const std::vector<double>& eps) {
  QuadratureSide side;
  for (size_t k = 0; k < scenes.size(); ++k) {
    side.converged.push_back(scenes[k]->report.converged);
    side.ids.push_back(scenes[k]->record.id);
    side.zigzag_rms.push_back(rms(alternating_part(flank_sigma_N(scenes[k]->record, flank_away))));
    if (k + 1 < scenes.size()) {
      const ModeDistance d = mode_distance(scenes[k]->record, scenes[k + 1]->record, nodes);
      side.d_sigma_N_away.push_back(d.e.at("sigma_N_away"));
    }
  }
  side.slope = fit_power_law(std::vector<double>(eps.begin(), eps.end() - 1), side.d_sigma_N_away);
  return side;
}

void print(const QuadratureControlOptions& options, const QuadratureControl& c) {
  std::printf("\nControl (S2): case %c's layer with selective integration (the rule of the other cases) beside the\n"
              "rule's full integration (cases/layer_quadrature.h): the zigzag of sigma_N on the right flank away from\n"
              "its corners (rms of its alternating part, daN/mm^2), the reach of the zigzag selective integration adds (nodes), and the\n"
              "Cauchy differences of sigma_N_away\n",
              options.law_case);
  std::printf("  %-10s | %-10s %-10s | %-8s | %-12s %-12s\n", "eps", "zig sel.", "zig rule", "reach", "d sel.",
              "d rule");
  for (size_t k = 0; k < c.eps.size(); ++k) {
    const bool last = k + 1 == c.eps.size();
    std::printf("  %-10s | %-10s %-10s | %-8s | %-12s %-12s%s%s\n", sci(c.eps[k], 2).c_str(),
                sci(c.selective.zigzag_rms[k], 2).c_str(), sci(c.rule.zigzag_rms[k], 2).c_str(),
                std::isfinite(c.reach[k]) ? fixed(c.reach[k], 2).c_str() : "-",
                last ? "" : sci(c.selective.d_sigma_N_away[k], 2).c_str(),
                last ? "" : sci(c.rule.d_sigma_N_away[k], 2).c_str(), c.selective.converged[k] ? "" : "  selective NOT converged",
                c.rule.converged[k] ? "" : "  rule NOT converged");
  }
  std::printf("  slope of sigma_N_away's differences (every pair, shown only): selective %s, rule %s;\n"
              "  reach ~ eps^q: q = %s (derived %g)\n",
              rate_text(c.selective.slope).c_str(), rate_text(c.rule.slope).c_str(), rate_text(c.reach_fit).c_str(),
              options.predicted_reach_exponent);
}

void write(H5Writer& out, const QuadratureControlOptions& options, const QuadratureControl& c) {
  const std::string g = "/studies/convergence/controls/quadrature";
  out.dataset(g + "/eps", c.eps);
  out.dataset(g + "/reach", c.reach);
  for (const auto& [name, side] : {std::pair{"selective", &c.selective}, std::pair{"rule", &c.rule}}) {
    const std::string s = g + "/" + name;
    out.dataset(s + "/converged", std::vector<int>(side->converged.begin(), side->converged.end()));
    out.dataset(s + "/layer_scene", side->ids);
    out.dataset(s + "/zigzag_rms", side->zigzag_rms);
    out.dataset(s + "/d_sigma_N_away", side->d_sigma_N_away);
    out.attr(s, "slope_sigma_N_away", side->slope ? side->slope->p : 0.0);
    out.attr(s, "slope_sigma_N_away_stderr", side->slope ? side->slope->p_stderr : 0.0);
    out.attr(s, "fitted", side->slope ? 1 : 0);
  }
  out.attr(g, "law_case", std::string(1, options.law_case));
  out.attr(g, "reach_exponent", c.reach_fit ? c.reach_fit->p : 0.0);
  out.attr(g, "reach_exponent_stderr", c.reach_fit ? c.reach_fit->p_stderr : 0.0);
  out.attr(g, "reach_fitted", c.reach_fit ? 1 : 0);
  out.attr(g, "predicted_reach_exponent", options.predicted_reach_exponent);
}

}  // namespace

QuadratureControl run_quadrature_control(const QuadratureControlOptions& options, DovetailSceneCache& cache,
                                         H5Writer* out) {
  cache.set_progress_tag("quadrature control");
  std::vector<DovetailSceneDef> selective_defs, rule_defs;
  for (double eps : options.eps) {
    rule_defs.push_back(layer_scene(options.law_case, eps, options.tolerance));
    selective_defs.push_back(rule_defs.back());
    selective_defs.back().quadrature = LayerQuadrature::Selective;
  }
  std::vector<DovetailSceneDef> all = rule_defs;
  all.insert(all.end(), selective_defs.begin(), selective_defs.end());
  cache.solve(all);
  const DovetailNodes nodes = dovetail_nodes(cache.bulk());
  const std::vector<int> flank = right_flank_nodes(nodes), flank_away = right_flank_nodes(nodes, default_corner_radius);

  std::vector<const DovetailScene*> selective, rule;
  for (size_t k = 0; k < options.eps.size(); ++k) {
    selective.push_back(&cache.get(selective_defs[k]));
    rule.push_back(&cache.get(rule_defs[k]));
  }
  QuadratureControl c;
  c.eps = options.eps;
  c.selective = measure_side(selective, nodes, flank_away, options.eps);
  c.rule = measure_side(rule, nodes, flank_away, options.eps);
  // The zigzag selective integration adds: the alternating part of the difference of the two.
  std::vector<double> reach_eps, reach;
  for (size_t k = 0; k < options.eps.size(); ++k) {
    const std::vector<double> a = flank_sigma_N(selective[k]->record, flank), b = flank_sigma_N(rule[k]->record, flank);
    std::vector<double> difference(a.size());
    for (size_t i = 0; i < a.size(); ++i) difference[i] = a[i] - b[i];
    const std::optional<double> r = zigzag_reach(alternating_part(difference));
    c.reach.push_back(r ? *r : std::numeric_limits<double>::quiet_NaN());
    if (r) reach_eps.push_back(options.eps[k]), reach.push_back(*r);
  }
  c.reach_fit = fit_power_law(reach_eps, reach);
  print(options, c);
  if (out) write(*out, options, c);
  return c;
}

}  // namespace thinlayer
