#include "studies/drivers/refinement_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/io/column_table.h"
#include "core/solvers/solver_revision.h"
#include "studies/tools/format.h"
#include "studies/tools/mode_distance.h"

namespace thinlayer {

namespace {

std::string two(double x) {
  if (!std::isfinite(x)) return "n/a";
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", x);
  return text;
}

// "0.50 (0.49, 0.50)": the rate where the grid ends and its last two local slopes; "—" without one.
std::string rate_cell(const RefinedRate& r) {
  if (!r.fit) return "— (" + std::to_string(r.counted()) + " counted)";
  std::string slopes;
  const std::vector<double>& s = r.local_slopes;
  for (std::size_t i = s.size() >= 2 ? s.size() - 2 : 0; i < s.size(); ++i) slopes += (slopes.empty() ? "" : ", ") + two(s[i]);
  return two(r.fit->p) + " (" + slopes + ")" + (r.run_reaches_end ? "" : " to " + sci(r.run_end_eps, 2));
}

// Every scene of the study with how it ended, and where it sits.
struct ListedScene {
  char law_case;
  std::string mesh, mode, selection;
  double eps;
  const SceneOutcome* outcome;
};

std::vector<ListedScene> every_scene(const RefinementResult& result) {
  std::vector<ListedScene> list;
  for (const RefinedCase& c : result.cases)
    for (const RefinedLevel& L : c.levels) {
      list.push_back({c.law_case, L.mesh, "limit", "", 0.0, &L.limit});
      for (std::size_t k = 0; k < result.eps.size(); ++k) {
        list.push_back({c.law_case, L.mesh, "layer", "minus", result.eps[k], &L.minus[k]});
        list.push_back({c.law_case, L.mesh, "layer", "plus", result.eps[k], &L.plus[k]});
      }
    }
  return list;
}

// What a scene without an answer takes out of the study.
std::string removes(const ListedScene& s, const std::vector<double>& eps) {
  if (s.mode == "limit") return "the floor on " + s.mesh;
  const std::size_t k = static_cast<std::size_t>(std::find(eps.begin(), eps.end(), s.eps) - eps.begin());
  std::string d;
  if (k > 0) d += "d(" + sci(eps[k - 1], 2) + " -> " + sci(eps[k], 2) + ")";
  if (k + 1 < eps.size()) d += std::string(d.empty() ? "" : ", ") + "d(" + sci(eps[k], 2) + " -> " + sci(eps[k + 1], 2) + ")";
  return (s.selection == "plus" ? "the selections' spread of " : "") + d;
}

std::string outcome_numbers(const SceneOutcome& o) {
  std::ostringstream s;
  if (!std::isnan(o.residual))
    s << "residual " << sci(o.residual, 1) << ", floor " << sci(o.floor, 1) << ", " << o.iterations << " steps, ";
  s << o.detail;
  if (!std::isnan(o.film_slip_over_h)) s << ", film_slip_over_h " << sci(o.film_slip_over_h, 2);
  char t[64];
  std::snprintf(t, sizeof t, ", %.1f s (%.1f s CPU)", o.seconds, o.cpu_seconds);
  s << t;
  if (!o.solver.empty()) s << " (" << o.solver << ")";
  return s.str();
}

void print_level(const RefinedCase& c, const RefinedLevel& L, const RefinementResult& result,
                 const RefinementStudyOptions& options) {
  std::printf("\ncase %c on %s (h %g along S, %d S nodes): Cauchy differences of the minus-face selection ('*': counted,\n"
              "'x': left out), the two selections' spread beside each scene's state\n",
              c.law_case, L.mesh.c_str(), L.h, L.S_nodes);
  std::printf("  %-9s %-16s %-16s %8s", "eps_k", "minus", "plus", "time[s]");
  for (const std::string& q : options.checked) std::printf(" %12s %9s", q.c_str(), "spread");
  std::printf("\n");
  for (std::size_t k = 0; k < result.eps.size(); ++k) {
    const SceneOutcome &m = L.minus[k], &p = L.plus[k];
    std::string minus = m.state;
    if (m.answered()) minus.append(" ").append(sci(m.residual, 0));
    std::printf("  %-9s %-16s %-16s %8.1f", sci(result.eps[k], 2).c_str(), minus.c_str(), p.state.c_str(),
                m.seconds + p.seconds);
    for (const std::string& q : options.checked) {
      const std::string d = k + 1 < result.eps.size() ? sci(L.difference.at(q)[k], 2) + (L.rate.at(q).left_out[k].empty() ? "*" : "x")
                                                      : "";
      std::printf(" %12s %9s", d.c_str(), sci(L.spread.at(q)[k], 1).c_str());
    }
    std::printf("\n");
  }
  std::printf("  %-52s", "rate where the grid ends (last local slopes)");
  for (const std::string& q : options.checked) std::printf(" %22s", rate_cell(L.rate.at(q)).c_str());
  std::printf("\n");
}

}  // namespace

void print_refinement(const RefinementResult& result, const RefinementStudyOptions& options) {
  std::printf("\nConvergence rates under refinement (S2, SPEC 3 S2 item 3): the layer model's Cauchy differences along\n"
              "eps %s ... %s (%zu thicknesses) on the meshes %s along S; every scene solved to residual %s under a\n"
              "wall-time cap of %g s; a difference counts when both scenes answered (converged, or at their proven\n"
              "round-off floor), it exceeds %g times the two selections' spread, eps_k <= %s, and no status changes\n"
              "below it; the rate is the Cauchy fit of the last %d counted differences in a row\n",
              sci(result.eps.front(), 2).c_str(), sci(result.eps.back(), 2).c_str(), result.eps.size(),
              [&] {
                std::string m;
                for (const std::string& s : result.meshes) m += (m.empty() ? "" : ", ") + s;
                return m;
              }().c_str(),
              sci(options.scenes.tolerance, 0).c_str(), options.scenes.scene_cap_s, options.rule.spread_factor,
              sci(options.rule.eps_max, 0).c_str(), options.rule.count);
  for (const RefinedCase& c : result.cases)
    for (const RefinedLevel& L : c.levels) print_level(c, L, result, options);

  std::printf("\nVerdicts (rate where the grid ends, and its last two local slopes, at each mesh; established when\n"
              "within %g of the prediction at h, h/2 and h/4 with the last two slopes within %g of each other):\n",
              options.rule.tolerance, options.rule.settle);
  for (const RefinedCase& c : result.cases)
    for (const std::string& q : options.checked)
      std::printf("  (%c) %-13s p = %-4s %s\n", c.law_case, q.c_str(), plain(c.p_predicted).c_str(), c.verdict.at(q).line().c_str());

  std::printf("\nScenes without an answer (never fitted; what each takes out of the study):\n");
  int none = 0;
  for (const ListedScene& s : every_scene(result)) {
    if (s.outcome->answered()) continue;
    ++none;
    std::printf("  (%c) %-5s %-5s %-9s %-5s %-14s %s; removes %s\n", s.law_case, s.mesh.c_str(), s.mode.c_str(),
                s.mode == "layer" ? sci(s.eps, 2).c_str() : "", s.selection.c_str(), s.outcome->state.c_str(),
                outcome_numbers(*s.outcome).c_str(), removes(s, result.eps).c_str());
  }
  if (none == 0) std::printf("  none\n");

  std::printf("\nFloor (S2 item 2): the layer at the thinnest answered eps against the limit law, per mesh (in brackets\n"
              "the bound on the eps-part still in it); its rate in h\n");
  for (const RefinedCase& c : result.cases) {
    std::printf("  case %c\n  %-6s %-9s %7s %-9s", c.law_case, "mesh", "h", "S nodes", "eps");
    for (const std::string& q : options.floor_checked) std::printf(" %20s", q.c_str());
    std::printf("\n");
    for (const RefinedLevel& L : c.levels) {
      std::printf("  %-6s %-9g %7d %-9s", L.mesh.c_str(), L.h, L.S_nodes, L.floor ? sci(L.floor_eps, 2).c_str() : "—");
      for (const std::string& q : options.floor_checked)
        std::printf(" %20s", L.floor ? (sci(L.floor->floor.at(q), 2) + " (" + sci(L.floor->eps_part.at(q), 1) + ")").c_str() : "—");
      std::printf("\n");
    }
    std::printf("  %-34s", "rate in h");
    for (const std::string& q : options.floor_checked) std::printf(" %20s", rate_text(c.floor_rate.at(q)).c_str());
    std::printf("\n");
  }

  std::vector<ListedScene> all = every_scene(result);
  double total = 0, cpu = 0;
  int solved = 0;
  for (const ListedScene& s : all)
    if (s.outcome->state != "not solved") total += s.outcome->seconds, cpu += s.outcome->cpu_seconds, ++solved;
  std::sort(all.begin(), all.end(), [](const ListedScene& a, const ListedScene& b) { return a.outcome->seconds > b.outcome->seconds; });
  std::printf("\nThe verdicts, the floor and the scenes without an answer in Markdown (studies/convergence_rates.md):\n\n%s",
              refinement_markdown(result, options).c_str());
  std::printf("\nScenes: %zu, %d of them solved (%d in this run, the rest read from the store), %.0f s of solving in all\n"
              "(%.0f s of CPU); the ten slowest:\n",
              all.size(), solved, result.solved_now, total, cpu);
  for (std::size_t i = 0; i < std::min<std::size_t>(10, all.size()) && all[i].outcome->seconds > 0; ++i)
    std::printf("  %8.1f s (%7.1f s CPU)  (%c) %-5s %-5s %-9s %-5s %s\n", all[i].outcome->seconds, all[i].outcome->cpu_seconds,
                all[i].law_case, all[i].mesh.c_str(),
                all[i].mode.c_str(), all[i].mode == "layer" ? sci(all[i].eps, 2).c_str() : "", all[i].selection.c_str(),
                all[i].outcome->state.c_str());
}

void write_refinement(H5Writer& out, const RefinementResult& result, const RefinementStudyOptions& options) {
  const std::string g = "/studies/convergence/refinement";
  out.described_dataset(g + "/eps", result.eps, "L", "the rate grid, decreasing");
  out.dataset(g + "/meshes", result.meshes);
  std::vector<double> h;
  for (const RefinedLevel& L : result.cases.front().levels) h.push_back(L.h);
  out.described_dataset(g + "/h_along_S", h, "L", "the spacing along S of each mesh (a group per case letter sits beside: not \"h\")");
  out.attr(g, "tolerance", options.scenes.tolerance);
  out.attr(g, "scene_cap_s", options.scenes.scene_cap_s);
  out.attr(g, "scene_cap_s_units", std::string("s"));
  out.attr(g, "solver_identity", solver_identity(SolverKind::Fast));
  out.attr(g, "spread_factor", options.rule.spread_factor);
  out.attr(g, "eps_max", options.rule.eps_max);
  out.attr(g, "rate_tolerance", options.rule.tolerance);
  out.attr(g, "settle", options.rule.settle);
  out.attr(g, "fitted_count", options.rule.count);
  std::string checked;
  for (const std::string& q : options.checked) checked += (checked.empty() ? "" : ",") + q;
  out.attr(g, "checked", checked);
  out.attr(g, "markdown", refinement_markdown(result, options));

  ColumnTable scenes;
  for (const ListedScene& s : every_scene(result)) {
    const SceneOutcome& o = *s.outcome;
    scenes.add("case", std::string(1, s.law_case));
    scenes.add("mesh", s.mesh);
    scenes.add("mode", s.mode);
    scenes.add("eps", s.eps);
    scenes.add("selection", s.selection);
    scenes.add("state", o.state);
    scenes.add("detail", o.detail);
    scenes.add("solver", o.solver);
    scenes.add("method", o.method);
    scenes.add("scene", o.id);
    scenes.add("wall_time_s", o.seconds);
    scenes.add("cpu_time_s", o.cpu_seconds);
    scenes.add("residual", o.residual);
    scenes.add("residual_floor", o.floor);
    scenes.add("iterations", o.iterations);
    scenes.add("film_slip_over_h", o.film_slip_over_h);
    scenes.add("removes", o.answered() ? std::string() : removes(s, result.eps));
  }
  scenes.write(out, g + "/scenes");

  ColumnTable verdicts, floors, floor_rates;
  for (const RefinedCase& c : result.cases) {
    for (const std::string& q : options.checked) {
      const RefinedVerdict& v = c.verdict.at(q);
      verdicts.add("case", std::string(1, c.law_case));
      verdicts.add("quantity", q);
      verdicts.add("p_predicted", c.p_predicted);
      verdicts.add("established", v.established ? 1 : 0);
      verdicts.add("rates", v.rates);
      verdicts.add("cause", v.cause);
      verdicts.add("line", v.line());
    }
    for (const RefinedLevel& L : c.levels) {
      floors.add("case", std::string(1, c.law_case));
      floors.add("mesh", L.mesh);
      floors.add("h", L.h);
      floors.add("S_nodes", L.S_nodes);
      floors.add("eps", L.floor ? L.floor_eps : std::nan(""));
      for (const std::string& q : distance_quantities()) {
        floors.add("floor_" + q, L.floor ? L.floor->floor.at(q) : std::nan(""));
        floors.add("eps_part_" + q, L.floor ? L.floor->eps_part.at(q) : std::nan(""));
      }
    }
    for (const std::string& q : distance_quantities()) {
      const auto& fit = c.floor_rate.at(q);
      floor_rates.add("case", std::string(1, c.law_case));
      floor_rates.add("quantity", q);
      floor_rates.add("rate", fit ? fit->p : std::nan(""));
      floor_rates.add("rate_stderr", fit ? fit->p_stderr : std::nan(""));
    }
  }
  verdicts.write(out, g + "/verdicts");
  floors.write(out, g + "/floor");
  floor_rates.write(out, g + "/floor_rates");

  // Per case and mesh: the differences, spreads and rates (group <case>/r<refinement>).
  for (const RefinedCase& c : result.cases)
    for (const RefinedLevel& L : c.levels) {
      const std::string lg = g + "/" + c.law_case + "/r" + std::to_string(options.scenes.refine.at(L.level));
      out.attr(lg, "mesh", L.mesh);
      out.attr(lg, "h", L.h);
      out.attr(lg, "S_nodes", L.S_nodes);
      out.dataset(lg + "/status_changes", L.status_changes);
      for (const std::string& q : distance_quantities()) {
        out.described_dataset(lg + "/d_" + q, L.difference.at(q), "",
                              "Cauchy difference between eps_k and eps_k+1 (minus-face selection), relative; NaN: a scene without an answer");
        out.described_dataset(lg + "/spread_" + q, L.spread.at(q), "",
                              "distance between the two selections at eps_k, relative; NaN: not measured");
      }
      for (const std::string& q : options.checked) {
        const RefinedRate& r = L.rate.at(q);
        out.dataset(lg + "/left_out_" + q, r.left_out);
        out.dataset(lg + "/local_slopes_" + q, r.local_slopes);
        out.attr(lg, "p_" + q, r.fit ? r.fit->p : std::nan(""));
        out.attr(lg, "p_" + q + "_stderr", r.fit ? r.fit->p_stderr : std::nan(""));
        out.attr(lg, "fitted_" + q, r.fit ? 1 : 0);
        out.attr(lg, "settled_" + q, r.settled ? 1 : 0);
        out.attr(lg, "run_first_" + q, r.run_first);
        out.attr(lg, "run_last_" + q, r.run_last);
      }
      std::vector<std::string> minus, plus;
      for (std::size_t k = 0; k < L.minus.size(); ++k) minus.push_back(L.minus[k].state), plus.push_back(L.plus[k].state);
      out.dataset(lg + "/minus_state", minus);
      out.dataset(lg + "/plus_state", plus);
    }
}

std::string refinement_markdown(const RefinementResult& result, const RefinementStudyOptions& options) {
  std::ostringstream md;
  md << "| case | quantity | predicted |";
  for (const char* m : {"h", "h/2", "h/4"}) md << " " << m << " |";
  md << " verdict |\n|---|---|---|---|---|---|---|\n";
  for (const RefinedCase& c : result.cases)
    for (const std::string& q : options.checked) {
      md << "| " << c.law_case << " | " << q << " | " << plain(c.p_predicted) << " |";
      for (const char* m : {"h", "h/2", "h/4"}) {
        const auto L = std::find_if(c.levels.begin(), c.levels.end(), [&](const RefinedLevel& l) { return l.mesh == std::string(m); });
        md << " " << (L == c.levels.end() ? "not run" : rate_cell(L->rate.at(q))) << " |";
      }
      const RefinedVerdict& v = c.verdict.at(q);
      md << " " << (v.established ? "established" : "not established: " + v.cause) << " |\n";
    }
  md << "\nThe floor (the layer at the thinnest answered ε against the limit law; its rate in h):\n\n| case | quantity |";
  for (const std::string& m : result.meshes) md << " " << m << " |";
  md << " rate in h |\n|---|---|";
  for (std::size_t i = 0; i <= result.meshes.size(); ++i) md << "---|";
  md << "\n";
  for (const RefinedCase& c : result.cases)
    for (const std::string& q : options.floor_checked) {
      md << "| " << c.law_case << " | " << q << " |";
      for (const RefinedLevel& L : c.levels)
        md << " " << (L.floor ? sci(L.floor->floor.at(q), 2) + " (" + sci(L.floor->eps_part.at(q), 1) + ")" : "—") << " |";
      md << " " << rate_text(c.floor_rate.at(q)) << " |\n";
    }
  md << "\nScenes without an answer:\n\n";
  int none = 0;
  for (const ListedScene& s : every_scene(result)) {
    if (s.outcome->answered()) continue;
    ++none;
    md << "- (" << s.law_case << ") " << s.mesh << " " << s.mode << (s.mode == "layer" ? " " + sci(s.eps, 2) + " " + s.selection : "")
       << ": " << s.outcome->state << ", " << outcome_numbers(*s.outcome) << "; removes " << removes(s, result.eps) << "\n";
  }
  if (none == 0) md << "- none\n";
  return md.str();
}

}  // namespace thinlayer
