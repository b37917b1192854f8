#include "studies/drivers/validity_map_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "core/io/output_target.h"
#include "studies/tools/format.h"

namespace thinlayer {

namespace {

const std::map<std::string, std::string>& descriptions() {
  static const std::map<std::string, std::string> d = {
      {"reactions", "the reactions, every support group together: |R_a - R_b| / |R_b|"},
      {"u", "the adherents' nodal displacements, relative L2 (scale: the largest |u| of the limit)"},
      {"peel_at_d", "the peak peel sigma_N at distance d from each bondline end, relative"},
      {"shear_at_d", "the peak |sigma_T| at distance d from each bondline end, relative"},
      {"sigma_N", "sigma_N on the plus face over every bondline, relative L2 (S2's norm)"},
      {"sigma_T", "sigma_T on the plus face over every bondline, relative L2 (S2's norm)"},
  };
  return d;
}

// The marker of a cell in the printed grids: the measured distance in %, "~" after it where the mesh
// does not resolve it, "x" where the cell did not converge.
std::string entry(const MapCell& c, const std::string& q, double factor) {
  const MapJudgement j = judge(c, q, factor);
  if (!j.converged) return "x";
  std::string s = significant(100 * j.measured, 2);
  if (c.fine.h > 0 && !j.resolved) s += "~";
  return s;
}

// Order one judged on the map: per quantity, at the cells above the mesh floor, how often the layer is
// within a third of the order-0 distance from the first-order answer u1, and the median ratio.
void print_order_one(const ValidityMapResult& r, const ValidityMapOptions& o) {
  std::printf("\n  Order one: the layer against the first-order answer u1 (at %s, cells above the mesh floor; ratio = order 1 / order 0):\n",
              r.h_fine > 0 ? "h/2" : "h");
  for (const std::string& q : map_quantities()) {
    std::vector<double> ratios;
    int third = 0;
    for (const MapCell& c : r.cells) {
      const MapJudgement j = judge(c, q, o.factor);
      if (!j.converged || !j.resolved) continue;
      ratios.push_back(j.order1_ratio());
      third += 3 * j.order1 <= j.measured;
    }
    std::sort(ratios.begin(), ratios.end());
    const std::string median = ratios.empty() ? "-" : significant(ratios[ratios.size() / 2], 2);
    std::printf("    %-11s order 1 <= order 0 / 3 at %d of %zu resolved cells; median ratio %s\n", q.c_str(), third,
                ratios.size(), median.c_str());
  }
}

}  // namespace

void print_validity_map(const ValidityMapResult& r, const ValidityMapOptions& o) {
  std::printf("\nValidity map of %s (SPEC 3 S3): the finite spring law of a glue at its own thickness t\n"
              "(K_N = (lambda_g + 2 mu_g)/t, K_T = mu_g/t) against the meshed layer of the same glue\n"
              "  L = %s mm, E_a = %s (the adherents' Young's modulus); peaks at d = %s mm from each bondline end (%s)\n",
              r.scene.c_str(), plain(r.L).c_str(), plain(r.E_a).c_str(), plain(r.d).c_str(), r.d_reason.c_str());
  if (r.h_fine > 0)
    std::printf("  read at h/2 = %s mm (and h = %s mm: '~' the mesh moves it by more than half, not resolved); "
                "'x' not converged\n",
                plain(r.h_fine).c_str(), plain(r.h).c_str());
  for (double nu : o.nu)
    for (const std::string& q : {std::string("u"), std::string("reactions"), std::string("peel_at_d"), std::string("shear_at_d")}) {
      std::printf("\n  nu_g %s, %s (%%): rows t/L, columns E_g/E_a\n  %-9s", plain(nu).c_str(), q.c_str(), "t/L");
      for (double E : o.E_ratio) std::printf(" %8s", sci(E, 1).c_str());
      std::printf("\n");
      for (double t : o.t_over_L) {
        std::printf("  %-9s", sci(t, 1).c_str());
        for (double E : o.E_ratio)
          for (const MapCell& c : r.cells)
            if (c.spec.nu == nu && c.spec.E_ratio == E && c.spec.t_over_L == t) std::printf(" %8s", entry(c, q, o.factor).c_str());
        std::printf("\n");
      }
    }
  // Every cell that failed, and why (the verdict of each scene: core/solvers/stop_verdict.h).
  for (const MapCell& c : r.cells) {
    const std::string why = c.coarse.failure + c.fine.failure;
    if (why.empty()) continue;
    std::printf("  x at t/L %s, E_g/E_a %s, nu_g %s: %s\n", sci(c.spec.t_over_L, 1).c_str(), sci(c.spec.E_ratio, 1).c_str(),
                plain(c.spec.nu).c_str(), why.substr(0, why.size() - 2).c_str());
  }
  // SPEC 3 S6 judged on the map.
  std::printf("\n  SPEC 3 S6, the limit-mode estimate against the measured distance (at %s, cells above the mesh floor):\n",
              r.h_fine > 0 ? "h/2" : "h");
  for (const std::string& q : map_quantities()) {
    int resolved = 0, within = 0;
    for (const MapCell& c : r.cells) {
      const MapJudgement j = judge(c, q, o.factor);
      if (j.converged && j.resolved) ++resolved, within += j.within;
    }
    std::printf("    %-11s within a factor %s at %d of %d resolved cells\n", q.c_str(), plain(o.factor).c_str(), within, resolved);
  }
  print_order_one(r, o);
  // The paper's rule.
  int degenerate = 0, measured = 0;
  double worst = 0;
  for (const MapCell& c : r.cells)
    if (c.rule_solved) {
      ++degenerate;
      if (c.rule_measured.count("u")) worst = std::max(worst, c.rule_measured.at("u")), ++measured;
    }
  // Only the cells whose rule's answer is usable give a distance (none: none is claimed).
  const std::string cost = measured == 0 ? "no usable answer of its law"
                                         : "its law against the layer: u up to " + significant(100 * worst, 3) + " % at " +
                                               std::to_string(measured) + " of them";
  std::printf("\n  The paper's 3 %% / 30x rule picks a 0 or inf law at %d of %zu cells (%s)\n", degenerate, r.cells.size(),
              cost.c_str());
  for (const MapCell& c : r.cells)
    if (c.rule_solved && !c.rule_measured.count("u"))
      std::printf("    no distance at t/L %s, E_g/E_a %s, nu_g %s: %s\n", sci(c.spec.t_over_L, 1).c_str(),
                  sci(c.spec.E_ratio, 1).c_str(), plain(c.spec.nu).c_str(),
                  c.rule_failure.substr(0, c.rule_failure.size() - 2).c_str());
  int converged = 0;
  for (const MapCell& c : r.cells) converged += judge(c, "u", o.factor).converged;
  std::printf("  %zu cells, %d converged at every level; wall time %.1f s on %d rank(s) x %d thread(s)\n", r.cells.size(),
              converged, r.wall_time_s, r.ranks, r.threads);
}

std::string validity_map_csv(const ValidityMapResult& r, const ValidityMapOptions& o) {
  std::ostringstream csv;
  csv.precision(10);
  csv << "# thinlayer validity map (SPEC 3 S3) of " << r.scene << ": one row per cell; the finite law at the glue's own "
      << "thickness against the meshed layer; L = " << r.L << " mm, E_a = " << r.E_a << ", d = " << r.d << " mm, h = " << r.h
      << " mm, h/2 = " << r.h_fine << " mm\n"
      << "# distances are relative (1 = 100 %): measured_<q> at h/2 (at h where there is no h/2), measured_h_<q> at h, "
      << "estimate_<q> SPEC 3 S6's at the same level (interior_<q> without its end cells), floor_<q> = |measured_h - measured|, "
      << "resolved_<q>: above the mesh floor (measured > 2 floor and 4 elements over the shear-lag length), ends_resolved_<q>: "
      << "h/2 <= 3t (the estimate judged is estimate_<q>, else interior_<q>), within_<q>: the judged estimate within the factor, "
      << "rule_<q> the paper's rule's law against the layer (empty where it picks the finite law)\n"
      << "# order one (the last columns): order1_<q> the layer against the first-order answer u1 at h/2 (u1 without its end "
      << "cells where ends_resolved_<q> = 0, as the estimate judged), order1_h_<q> the same at h, order1_ratio_<q> = "
      << "order1_<q> / measured_<q>, order1_resolved_<q>: order1 > 2 |order1_h - order1|, order1_full_<q> and "
      << "order1_interior_<q> against u1 with and without its end cells at h/2\n";
  csv << "t_over_L,E_ratio,nu,thickness_mm,E_g,shear_lag_mm,law_case,rule_case,converged,failure";
  for (const std::string& q : map_quantities())
    csv << ",measured_" << q << ",measured_h_" << q << ",estimate_" << q << ",interior_" << q << ",floor_" << q << ",resolved_"
        << q << ",ends_resolved_" << q << ",within_" << q << ",rule_" << q;
  for (const std::string& q : map_quantities())
    csv << ",order1_" << q << ",order1_h_" << q << ",order1_ratio_" << q << ",order1_resolved_" << q << ",order1_full_" << q
        << ",order1_interior_" << q;
  csv << "\n";
  for (const MapCell& c : r.cells) {
    std::string failure = c.coarse.failure.empty() ? c.fine.failure : c.coarse.failure;
    for (char& ch : failure)
      if (ch == ',' || ch == '\n') ch = ';';
    csv << c.spec.t_over_L << "," << c.spec.E_ratio << "," << c.spec.nu << "," << c.thickness << "," << c.E << ","
        << c.shear_lag << ",\""
        << c.law_case << "\",\"" << c.rule_case << "\"," << (judge(c, "u", o.factor).converged ? 1 : 0) << ",\"" << failure
        << "\"";
    for (const std::string& q : map_quantities()) {
      const MapJudgement j = judge(c, q, o.factor);
      csv << "," << j.measured << "," << (c.coarse.measured.count(q) ? c.coarse.measured.at(q) : 0.0) << "," << j.estimate
          << "," << j.interior << "," << j.floor << "," << (j.resolved ? 1 : 0) << "," << (j.ends_resolved ? 1 : 0) << ","
          << (j.within ? 1 : 0) << ",";
      if (c.rule_solved && c.rule_measured.count(q)) csv << c.rule_measured.at(q);
    }
    for (const std::string& q : map_quantities()) {
      const MapJudgement j = judge(c, q, o.factor);
      const MapCellLevel& read = c.fine.h > 0 ? c.fine : c.coarse;
      auto at = [&q](const std::map<std::string, double>& m) { return m.count(q) ? m.at(q) : 0.0; };
      const double order1_h = at(j.ends_resolved ? c.coarse.order1 : c.coarse.order1_interior);
      csv << "," << j.order1 << "," << order1_h << "," << j.order1_ratio() << ","
          << (j.order1_resolved ? 1 : 0) << "," << at(read.order1) << "," << at(read.order1_interior);
    }
    csv << "\n";
  }
  return csv.str();
}

void write_validity_map(H5Writer& out, const ValidityMapResult& r, const ValidityMapOptions& o) {
  const std::string g = "/studies/validity_map/" + r.scene;
  std::vector<double> t, E, nu, thickness, Eg, h, h_fine, layer_time, limit_time, estimate_time;
  std::vector<int> converged, rule_solved;
  std::vector<std::string> law, rule, failure;
  for (const MapCell& c : r.cells) {
    t.push_back(c.spec.t_over_L);
    E.push_back(c.spec.E_ratio);
    nu.push_back(c.spec.nu);
    thickness.push_back(c.thickness);
    Eg.push_back(c.E);
    converged.push_back(judge(c, "u", o.factor).converged ? 1 : 0);
    law.push_back(c.law_case);
    rule.push_back(c.rule_case);
    rule_solved.push_back(c.rule_solved ? 1 : 0);
    failure.push_back(c.coarse.failure.empty() ? c.fine.failure : c.coarse.failure);
    layer_time.push_back(c.coarse.layer_time_s + c.fine.layer_time_s);
    limit_time.push_back(c.coarse.limit_time_s + c.fine.limit_time_s);
    estimate_time.push_back(c.coarse.estimate_time_s + c.fine.estimate_time_s);
  }
  out.described_dataset(g + "/t_over_L", t, "1", "the glue's thickness over L (SPEC 1.3's characteristic length)");
  out.described_dataset(g + "/E_ratio", E, "1", "the glue's Young's modulus over the adherents' E_a");
  out.described_dataset(g + "/nu", nu, "1", "the glue's Poisson ratio");
  out.described_dataset(g + "/thickness", thickness, "mm", "the glue's thickness t of the cell");
  out.described_dataset(g + "/E_g", Eg, "stress unit of the scene", "the glue's Young's modulus of the cell");
  std::vector<double> shear_lag;
  for (const MapCell& c : r.cells) shear_lag.push_back(c.shear_lag);
  out.described_dataset(g + "/shear_lag", shear_lag, "mm", "the joint's shear-lag length sqrt(E*_a L t / mu_g)");
  out.described_dataset(g + "/converged", converged, "", "1: the layer and the finite law reached the tolerance at h and h/2");
  out.described_dataset(g + "/failure", failure, "", "a scene that could not be solved (refused, threw), or empty");
  out.described_dataset(g + "/law_case", law, "", "the finite law's Table 1 class, per bondline");
  out.described_dataset(g + "/rule_case", rule, "", "the paper's 3 % / 30x rule's choice, per bondline (SPEC 1.3)");
  out.described_dataset(g + "/rule_solved", rule_solved, "", "1: the rule picks another law than the finite one; rule_<q> is its distance");
  out.described_dataset(g + "/layer_time_s", layer_time, "s", "the layer scenes' wall time (both levels)");
  out.described_dataset(g + "/limit_time_s", limit_time, "s", "the finite law's limit scenes' wall time (both levels)");
  out.described_dataset(g + "/estimate_time_s", estimate_time, "s", "SPEC 3 S6's estimate's wall time (both levels)");
  for (const std::string& q : map_quantities()) {
    std::vector<double> measured, measured_h, estimate, interior, floor, rule_q;
    std::vector<int> resolved, within, ends;
    for (const MapCell& c : r.cells) {
      const MapJudgement j = judge(c, q, o.factor);
      measured.push_back(j.measured);
      measured_h.push_back(c.coarse.measured.count(q) ? c.coarse.measured.at(q) : 0.0);
      estimate.push_back(j.estimate);
      interior.push_back(j.interior);
      ends.push_back(j.ends_resolved ? 1 : 0);
      floor.push_back(j.floor);
      resolved.push_back(j.resolved ? 1 : 0);
      within.push_back(j.within ? 1 : 0);
      rule_q.push_back(c.rule_solved && c.rule_measured.count(q) ? c.rule_measured.at(q) : -1.0);
    }
    const std::string d = descriptions().at(q);
    out.described_dataset(g + "/measured_" + q, measured, "1 (relative)", "the finite law against the layer at h/2: " + d);
    out.described_dataset(g + "/measured_h_" + q, measured_h, "1 (relative)", "the same at h: " + d);
    out.described_dataset(g + "/estimate_" + q, estimate, "1 (relative)", "SPEC 3 S6's estimate from the limit mode alone, at h/2: " + d);
    out.described_dataset(g + "/interior_" + q, interior, "1 (relative)", "the same estimate without its end cells, at h/2: " + d);
    out.described_dataset(g + "/ends_resolved_" + q, ends, "", "1: h/2 <= 3t, the mesh resolves the layer's end zone: estimate_<q> is judged, else interior_<q>");
    out.described_dataset(g + "/floor_" + q, floor, "1 (relative)", "the mesh floor, |measured at h - measured at h/2|: " + d);
    out.described_dataset(g + "/resolved_" + q, resolved, "",
        "1: above the mesh floor: measured > 2 floor (the mesh moves it by less than half) and 4 elements over the shear-lag length");
    out.described_dataset(g + "/within_" + q, within, "", "1: the judged estimate (estimate_ or interior_) within the factor of the measured distance");
    out.described_dataset(g + "/rule_" + q, rule_q, "1 (relative)", "the paper's rule's law against the layer at h/2 (-1: it picks the finite law): " + d);
  }
  for (const std::string& q : map_quantities()) {  // order one: the layer against the first-order answer u1
    std::vector<double> order1, order1_h, ratio;
    std::vector<int> resolved;
    for (const MapCell& c : r.cells) {
      const MapJudgement j = judge(c, q, o.factor);
      const auto& coarse = j.ends_resolved ? c.coarse.order1 : c.coarse.order1_interior;
      order1.push_back(j.order1);
      order1_h.push_back(coarse.count(q) ? coarse.at(q) : 0.0);
      ratio.push_back(j.order1_ratio());
      resolved.push_back(j.order1_resolved ? 1 : 0);
    }
    const std::string d = descriptions().at(q);
    out.described_dataset(g + "/order1_" + q, order1, "1 (relative)",
        "order one: the layer against the first-order answer u1 at h/2 (u1 without its end cells where ends_resolved_<q> is 0): " + d);
    out.described_dataset(g + "/order1_h_" + q, order1_h, "1 (relative)", "the same at h: " + d);
    out.described_dataset(g + "/order1_ratio_" + q, ratio, "1", "order1_<q> / measured_<q>: order one's distance over order zero's");
    out.described_dataset(g + "/order1_resolved_" + q, resolved, "", "1: order1 > 2 |order1_h - order1| (the mesh moves it by less than half)");
  }
  out.attr(g, "description", std::string("SPEC 3 S3, the engineer's validity map: one row per cell (nu outermost, then "
                                         "E_ratio, then t_over_L); studies/drivers/validity_map.h"));
  out.attr(g, "characteristic_length", r.L);
  out.attr(g, "characteristic_length_units", std::string("mm"));
  out.attr(g, "E_a", r.E_a);
  out.attr(g, "peak_distance", r.d);
  out.attr(g, "peak_distance_units", std::string("mm"));
  out.attr(g, "peak_distance_reason", r.d_reason);
  out.attr(g, "h", r.h);
  out.attr(g, "h_fine", r.h_fine);
  out.attr(g, "factor", o.factor);
  out.attr(g, "wall_time_s", r.wall_time_s);
  out.attr(g, "wall_time_ranks", r.ranks);  // "time" in the name: a spread file differs here only (tests/compare_results.py)
  out.attr(g, "wall_time_threads", r.threads);
  out.attr(g, "law", std::string("the finite spring law of the glue at its own thickness: lambda_bar = lambda_g/t, "
                                 "mu_bar = mu_g/t (bilateral where both faces are bonded; Table 1's with f otherwise)"));
  out.write_beside("validity_map_" + r.scene + ".csv", OutputKind::Csv, validity_map_csv(r, o));
}

}  // namespace thinlayer
