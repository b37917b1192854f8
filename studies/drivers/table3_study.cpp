#include "studies/drivers/table3_study.h"

#include "studies/tools/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>

#include "cases/bar/bar_scenes.h"
#include "studies/tools/format.h"
#include "studies/parallel/scene_batch.h"

namespace thinlayer {

namespace {


// Where the statuses change along AD, found as the zero of a quantity that changes sign
// there, interpolated linearly between the two nodes that bracket it:
//   gap → contact: [u]_N (< 0 open, > 0 in contact for a finite K_N);
//   slide → stick: K_T |[u]_T| - f |σ_N| (> 0 where the spring alone would exceed the
//   Coulomb threshold, < 0 where it holds).
struct Transitions {
  double gap_contact = std::nan("");  // mm from A; NaN: no gap
  double stick_slip = std::nan("");   // mm from A; NaN: no slide zone
};

double crossing(const InterfaceFields& f, const std::vector<double>& q, bool first) {
  double found = std::nan("");
  for (size_t i = 0; i + 1 < q.size(); ++i)
    if ((q[i] > 0) != (q[i + 1] > 0) && (first ? q[i] <= 0 : q[i] > 0)) {
      const double x0 = f.x(i, 0), x1 = f.x(i + 1, 0);
      found = x0 + (x1 - x0) * q[i] / (q[i] - q[i + 1]);
      if (first) return found;
    }
  return found;
}

Transitions transitions(const InterfaceFields& f, const InterfaceLaw& law) {
  std::vector<double> normal(f.jump_N.data(), f.jump_N.data() + f.jump_N.size());
  std::vector<double> tangential(normal.size());
  for (size_t i = 0; i < normal.size(); ++i)
    tangential[i] = law.K_T() * std::abs(f.jump_T[i]) - law.friction * std::abs(f.sigma_N[i]);
  return {crossing(f, normal, true), crossing(f, tangential, false)};
}

// The interval in which the paper's counts put a transition (nodes every h from A).
std::string paper_bracket(int nodes_before, double h) {
  if (nodes_before <= 0) return "none";
  std::ostringstream s;
  s << "[" << (nodes_before - 1) * h << ", " << nodes_before * h << "]";
  return s.str();
}

std::string fmt_mm(double x) {
  if (std::isnan(x)) return "none";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

struct Variant {
  PlaneHypothesis plane;
  ElementType element;
  TriangleDiagonal diagonal;
  int nx, ny;
  double scale;
  std::string name() const {
    std::ostringstream s;
    s << "plane " << to_string(plane) << ", " << to_string(element);
    if (element == ElementType::P1) s << (diagonal == TriangleDiagonal::Right ? "/" : "\\");
    s << ", " << nx << "x" << ny << ", s " << scale;
    return s.str();
  }
};

// Counts over the 32 nodes the paper counts: with nx = 32 the 32 nodes of AD but D; with
// nx = 31 the 31 contact nodes plus D, which is pinned: stick when pressed, gap otherwise.
StatusCount paper_comparable_counts(const BarScene& scene, int nx) {
  StatusCount c = scene.counts;
  if (nx == 31) {
    if (scene.record.reactions.at("D").y() > 0) ++c.stick;
    else ++c.gap;
  }
  return c;
}

// Transition positions are written with -1 where there is no such transition.
constexpr double missing_transition = -1.0;
std::vector<double> no_nan(std::vector<double> v) {
  for (double& x : v)
    if (std::isnan(x)) x = missing_transition;
  return v;
}

struct RowRun {
  Table3Row paper;
  StatusCount baseline;
  BarScene fast, relaxation;
  double fast_time = 0, relaxation_time = 0, setup_time = 0, agreement = 0;
};

// One variant of the sensitivity study against one paper row.
struct SensitivityRow {
  Variant v;
  int row;
  StatusCount counts;
  Transitions t;
  double residual;
  bool converged, matches;
};

// What travels between ranks (studies/parallel/scene_batch.h).
void put(ByteWriter& w, const Transitions& t) { put(w, t.gap_contact), put(w, t.stick_slip); }
void get(ByteReader& r, Transitions& t) { get(r, t.gap_contact), get(r, t.stick_slip); }
void put(ByteWriter& w, const RowRun& r) {
  put(w, r.fast), put(w, r.relaxation), put(w, r.fast_time), put(w, r.relaxation_time), put(w, r.setup_time);
}
void get(ByteReader& r, RowRun& x) {
  get(r, x.fast), get(r, x.relaxation), get(r, x.fast_time), get(r, x.relaxation_time), get(r, x.setup_time);
}
void put(ByteWriter& w, const SensitivityRow& s) {
  put(w, s.v.plane), put(w, s.v.element), put(w, s.v.diagonal), put(w, s.v.nx), put(w, s.v.ny), put(w, s.v.scale);
  put(w, s.row), put(w, s.counts), put(w, s.t), put(w, s.residual), put(w, s.converged), put(w, s.matches);
}
void get(ByteReader& r, SensitivityRow& s) {
  get(r, s.v.plane), get(r, s.v.element), get(r, s.v.diagonal), get(r, s.v.nx), get(r, s.v.ny), get(r, s.v.scale);
  get(r, s.row), get(r, s.counts), get(r, s.t), get(r, s.residual), get(r, s.converged), get(r, s.matches);
}

// Cost estimates for spreading the scenes over ranks, in seconds on the 2-core development
// machine (measured with THINLAYER_SCENE_TIMES; docs/studies.md, "Studies over MPI ranks"). A task of
// limit solves on one mesh costs about its factorisation, ~2e-5 s per node (the sensitivity
// variants' 30 solves: 0.02-0.04 s; refinement 256x256: 1.5 s). A row with both solvers and a
// layer scene of the bar take 0.02-0.3 s, except a few that take seconds (row 6's relaxation,
// 19500 sweeps; row 4's layer at eps 1e-3, 6.5 s), which nothing known beforehand predicts.
double mesh_task_cost(int nx, int ny) { return 2e-5 * (nx + 1) * (ny + 1); }
constexpr double row_cost = 0.05;    // per repeat: both solvers
constexpr double layer_cost = 0.05;  // a layer scene of the bar (its own mesh and factorisation)

size_t batch_size(size_t rows, size_t eps, size_t levels, size_t variants) { return rows * (1 + eps) + levels + variants; }

}  // namespace

std::vector<Check> run_table3_study(const Table3StudyOptions& options, H5Writer* out) {
  const auto paper = load_table3_paper();
  const auto baseline = load_table3_baseline();
  if (baseline.size() != paper.size()) throw std::runtime_error("table3: baseline and paper tables differ in length");
  std::vector<Check> checks;
  auto progress = [&](const std::string& s) {
    if (options.verbose) std::cerr << "[table3] " << s << "\n";
  };

  // 1. The six rows, both solvers, default model.
  BarBulk bulk(bar::MeshOptions{});
  SolverOptions fast_options;
  SolverOptions relaxation_options;
  relaxation_options.tolerance = options.relaxation_tolerance;
  // Every scene of the study is independent: one batch, spread over the MPI ranks (if any).
  SceneBatch batch("table3", 1, options.verbose);
  std::vector<RowRun> runs(paper.size());
  for (size_t i = 0; i < paper.size(); ++i) {
    runs[i].paper = paper[i];
    runs[i].baseline = baseline[i];
    batch.add("row " + std::to_string(paper[i].row) + ", both solvers", row_cost * options.repeats, runs[i], [&, i] {
      RowRun run{paper[i], baseline[i], {}, {}, 0, 0, 0, 0};
      const InterfaceLaw law = table3_law(paper[i]);
      const std::string law_case = "table3-row-" + std::to_string(paper[i].row);
      std::vector<double> fast_times, relaxation_times;
      for (int rep = 0; rep < std::max(1, options.repeats); ++rep) {
        run.fast = solve_bar(bulk, law, law_case, SolverKind::Fast, fast_options);
        run.relaxation = solve_bar(bulk, law, law_case, SolverKind::Relaxation, relaxation_options);
        fast_times.push_back(run.fast.report.wall_time_s);
        relaxation_times.push_back(run.relaxation.report.wall_time_s);
      }
      run.fast_time = median(fast_times);
      run.relaxation_time = median(relaxation_times);
      run.setup_time = bulk.condensed().setup_time_s();
      return run;
    });
  }

  // Thin-layer mode at decreasing ε (each scene builds its own layer).
  const std::vector<double> layer_eps = {1e-2, 1e-3, 1e-4};
  std::vector<std::vector<BarLayerScene>> layer(paper.size(), std::vector<BarLayerScene>(layer_eps.size()));
  for (size_t i = 0; i < paper.size(); ++i)
    for (size_t k = 0; k < layer_eps.size(); ++k) {
      const double eps = layer_eps[k];
      std::ostringstream label;
      label << "row " << paper[i].row << ", layer eps " << eps;
      batch.add(label.str(), layer_cost, layer[i][k], [&, i, eps] {
        return solve_bar_layer(bar::MeshOptions{}, paper[i].lambda_bar, paper[i].mu_bar, eps,
                               "table3-row-" + std::to_string(paper[i].row), SolverKind::Fast, fast_options);
      });
    }

  // 3. Transitions along AD under refinement (nx = ny), default model otherwise: one task per
  // mesh, whose six laws share its factorisation.
  std::vector<int> levels = {32};
  if (options.refinement) levels = {32, 64, 128, 256};
  std::vector<std::vector<Transitions>> refined_at(levels.size());  // per level, per row
  for (size_t k = 0; k < levels.size(); ++k) {
    const int n = levels[k];
    batch.add("refinement " + std::to_string(n) + "x" + std::to_string(n), mesh_task_cost(n, n),
              refined_at[k], [&, n] {
                BarBulk fine(bar::MeshOptions{n, n, ElementType::Q1, TriangleDiagonal::Right, PlaneHypothesis::Strain});
                std::vector<Transitions> t;
                for (const Table3Row& p : paper) {
                  const InterfaceLaw law = table3_law(p);
                  const BarScene s =
                      solve_bar(fine, law, "table3-row-" + std::to_string(p.row), SolverKind::Fast, fast_options);
                  t.push_back(transitions(s.record.interfaces.at(0), law));
                }
                return t;
              });
  }

  // 2. The sensitivity study: which variants of the model reproduce which paper rows. One task
  // per mesh variant: its 5 scales x 6 rows share its factorisation.
  std::vector<Variant> variants;
  if (options.sensitivity)
    for (PlaneHypothesis plane : {PlaneHypothesis::Strain, PlaneHypothesis::Stress})
      for (int ny : {8, 16, 32, 64})
        for (auto [element, diagonal] : {std::pair{ElementType::Q1, TriangleDiagonal::Right},
                                         std::pair{ElementType::P1, TriangleDiagonal::Right},
                                         std::pair{ElementType::P1, TriangleDiagonal::Left}})
          for (int nx : {31, 32}) variants.push_back({plane, element, diagonal, nx, ny, 1.0});
  const std::vector<double> scales = {1.0, 10.0, 100.0, 1e3, 1e4};
  std::vector<std::vector<SensitivityRow>> by_variant(variants.size());
  for (size_t k = 0; k < variants.size(); ++k) {
    const Variant v = variants[k];
    batch.add("sensitivity: " + v.name(), mesh_task_cost(v.nx, v.ny), by_variant[k],
              [&, v] {
                BarBulk variant_bulk(bar::MeshOptions{v.nx, v.ny, v.element, v.diagonal, v.plane});
                std::vector<SensitivityRow> rows;
                for (double scale : scales)
                  for (const Table3Row& p : paper) {
                    const InterfaceLaw law = InterfaceLaw::make(scale * p.lambda_bar, scale * p.mu_bar, bar::friction);
                    const BarScene s = solve_bar(variant_bulk, law, "table3-row-" + std::to_string(p.row),
                                                 SolverKind::Fast, fast_options);
                    const StatusCount c = paper_comparable_counts(s, v.nx);
                    rows.push_back({{v.plane, v.element, v.diagonal, v.nx, v.ny, scale}, p.row, c,
                                    transitions(s.record.interfaces.at(0), law), s.report.residual.value(),
                                    s.report.converged, c == p.paper});
                  }
                return rows;
              });
  }

  progress(std::to_string(batch_size(paper.size(), layer_eps.size(), levels.size(), variants.size())) +
           " tasks: six rows, thin-layer mode, refinement, sensitivity");
  batch.run();
  for (RowRun& run : runs) {
    const auto& gf = run.fast.record.interfaces.at(0);
    const auto& gr = run.relaxation.record.interfaces.at(0);
    const double diff = std::sqrt((gr.jump_N - gf.jump_N).squaredNorm() + (gr.jump_T - gf.jump_T).squaredNorm());
    const double norm = std::sqrt(gf.jump_N.squaredNorm() + gf.jump_T.squaredNorm());
    run.agreement = diff / norm;
  }
  std::map<int, std::vector<Transitions>> refined;  // nx -> per row
  for (size_t k = 0; k < levels.size(); ++k) refined[levels[k]] = refined_at[k];
  std::vector<SensitivityRow> sensitivity;
  for (const auto& rows : by_variant) sensitivity.insert(sensitivity.end(), rows.begin(), rows.end());

  std::printf("\nTable 3: the bar in limit mode (Q1 32x32, plane strain, f = 1; counts gap/slide/stick out of 32;\n"
              "status tolerance %g; fast solver tolerance %g, relaxation %g; times are medians of %d runs)\n\n",
              default_status_tolerance, fast_options.tolerance, relaxation_options.tolerance, options.repeats);
  std::printf("%3s %9s %11s | %9s %9s | %9s %4s %9s %9s | %9s %6s %9s %8s | %9s\n", "row", "mu_bar", "lambda_bar",
              "paper", "baseline", "fast", "it", "residual", "time [s]", "relax", "sweeps", "residual", "time [s]",
              "|du|/|u|");
  for (const RowRun& r : runs) {
    std::printf("%3d %9.3g %11.3g | %9s %9s | %9s %4d %9.2e %9.2e | %9s %6d %9.2e %8.3f | %9.2e\n", r.paper.row,
                r.paper.mu_bar, r.paper.lambda_bar, counts_text(r.paper.paper).c_str(), counts_text(r.baseline).c_str(),
                counts_text(r.fast.counts).c_str(), r.fast.report.iterations, r.fast.report.residual.value(),
                r.fast_time, counts_text(r.relaxation.counts).c_str(), r.relaxation.report.iterations,
                r.relaxation.report.residual.value(), r.relaxation_time, r.agreement);
  }
  std::printf("\n(fast: + %.3f s once for the factorisation and condensation shared by all rows; |du|/|u|: relative\n"
              " L2 distance between the two solvers' interface jumps)\n", runs.front().setup_time);

  for (const RowRun& r : runs) {
    const std::string row = "table3.row" + std::to_string(r.paper.row);
    checks.push_back({row + ".fast.baseline", r.fast.counts == r.baseline, counts_text(r.baseline),
                      counts_text(r.fast.counts), "exact"});
    checks.push_back({row + ".relaxation.baseline", r.relaxation.counts == r.baseline,
                      counts_text(r.baseline), counts_text(r.relaxation.counts), "exact"});
    checks.push_back({row + ".fast.converged", r.fast.report.converged, "residual <= " + sci(fast_options.tolerance),
                      sci(r.fast.report.residual.value()), sci(fast_options.tolerance)});
    checks.push_back({row + ".relaxation.converged", r.relaxation.report.converged,
                      "residual <= " + sci(relaxation_options.tolerance), sci(r.relaxation.report.residual.value()),
                      sci(relaxation_options.tolerance)});
    checks.push_back({row + ".solvers_agree", r.agreement <= 1e-8, "<= 1e-8", sci(r.agreement), "1e-8"});
  }

  // Thin-layer mode at decreasing ε: the combined counts must approach the limit mode's.
  std::printf("\nThin-layer mode (layer of thickness eps under AD, lambda_eps = eps lambda_bar, mu_eps = eps mu_bar,\n"
              "Signorini-Coulomb on both faces): combined counts (gap if either face is open, else slide if either\n"
              "slides), fast solver\n\n%3s | %9s |", "row", "limit");
  for (double eps : layer_eps) std::printf(" eps %-7g %-4s %8s |", eps, "it", "residual");
  std::printf("\n");
  for (size_t i = 0; i < paper.size(); ++i) {
    std::printf("%3d | %9s |", paper[i].row, counts_text(baseline[i]).c_str());
    for (const BarLayerScene& l : layer[i])
      std::printf(" %-11s %-4d %8.1e |", counts_text(l.counts.combined).c_str(), l.report.iterations,
                  l.report.residual.value());
    std::printf("\n");
    const BarLayerScene& thinnest = layer[i].back();
    const std::string row = "table3.row" + std::to_string(paper[i].row);
    checks.push_back({row + ".layer_eps1e-4.converged", thinnest.report.converged,
                      "residual <= " + sci(fast_options.tolerance), sci(thinnest.report.residual.value()),
                      sci(fast_options.tolerance)});
    checks.push_back({row + ".layer_eps1e-4.limit_counts", thinnest.counts.combined == baseline[i],
                      counts_text(baseline[i]), counts_text(thinnest.counts.combined), "exact"});
  }

  const double h = bar::side / 32;
  std::printf("\nTransitions along AD (mm from A), Q1, plane strain, nx = ny = %s; the paper's counts put them in:\n",
              options.refinement ? "32, 64, 128, 256" : "32");
  std::printf("%3s | %-26s %-13s | %-26s %-13s\n", "row", "gap-contact (refinement)", "paper", "stick-slip (refinement)", "paper");
  for (size_t i = 0; i < paper.size(); ++i) {
    std::string gc, ss;
    for (int n : levels) {
      gc += fmt_mm(refined[n][i].gap_contact) + " ";
      ss += fmt_mm(refined[n][i].stick_slip) + " ";
    }
    const StatusCount& pc = paper[i].paper;
    std::printf("%3d | %-26s %-13s | %-26s %-13s\n", paper[i].row, gc.c_str(), paper_bracket(pc.gap, h).c_str(),
                ss.c_str(), pc.slide > 0 ? paper_bracket(pc.gap + pc.slide, h).c_str() : "none");
  }

  if (options.sensitivity) {
    std::printf("\nSensitivity study: %zu solves (plane strain/stress x ny 8,16,32,64 x Q1, P1/, P1\\ x nx 31,32 x\n"
                "s 1,10,100,1e3,1e4 on lambda_bar and mu_bar x 6 rows). With nx = 31, D is counted as the 32nd node.\n\n",
                sensitivity.size());
    int unconverged = 0;
    for (const auto& s : sensitivity) unconverged += !s.converged;
    std::printf("All converged to 1e-10: %s (%d not)\n\n", unconverged ? "NO" : "yes", unconverged);
    checks.push_back({"table3.sensitivity.converged", unconverged == 0, "0 unconverged", std::to_string(unconverged),
                      sci(fast_options.tolerance)});
    for (size_t i = 0; i < paper.size(); ++i) {
      const RowRun& r = runs[i];
      const StatusCount& pc = r.paper.paper;
      const StatusCount& bc = r.baseline;
      std::printf("row %d: paper %s, project %s", r.paper.row, counts_text(pc).c_str(), counts_text(bc).c_str());
      if (pc == bc) {
        std::printf(" -> identical.");
      } else {
        std::printf(" -> differs by gap %+d, slide %+d, stick %+d.", bc.gap - pc.gap, bc.slide - pc.slide, bc.stick - pc.stick);
      }
      std::vector<std::string> matches;
      for (const auto& s : sensitivity)
        if (s.row == r.paper.row && s.matches) matches.push_back(s.v.name());
      const size_t per_row = sensitivity.size() / paper.size();
      std::printf(" %zu of %zu variants reproduce the paper's row", matches.size(), per_row);
      if (!matches.empty()) {
        std::printf(":\n");
        for (size_t k = 0; k < matches.size() && k < 8; ++k) std::printf("    %s\n", matches[k].c_str());
        if (matches.size() > 8) std::printf("    ... and %zu more (all in results.h5)\n", matches.size() - 8);
      } else {
        std::printf(".\n");
      }
    }
    // One factor at a time from the default model: how each factor moves the counts.
    std::printf("\nOne factor at a time from the default (plane strain, Q1, 32x32, s 1): counts per row\n");
    std::printf("%-34s", "variant");
    for (const auto& p : paper) std::printf(" %9s", ("row " + std::to_string(p.row)).c_str());
    std::printf("\n");
    auto is_default = [](const Variant& v) {
      return v.plane == PlaneHypothesis::Strain && v.element == ElementType::Q1 && v.nx == 32 && v.ny == 32 && v.scale == 1;
    };
    auto differs_in_one = [&](const Variant& v) {
      int changed = (v.plane != PlaneHypothesis::Strain) + (v.element != ElementType::Q1) + (v.nx != 32) + (v.ny != 32) +
                    (v.scale != 1);
      return changed <= 1;
    };
    std::printf("%-34s", "paper");
    for (const auto& p : paper) std::printf(" %9s", counts_text(p.paper).c_str());
    std::printf("\n");
    std::string last;
    for (const auto& s : sensitivity) {
      if (!differs_in_one(s.v)) continue;
      const std::string name = s.v.name() + (is_default(s.v) ? " (default)" : "");
      if (name != last) {
        if (!last.empty()) std::printf("\n");
        std::printf("%-34s", name.c_str());
        last = name;
      }
      std::printf(" %8s%s", counts_text(s.counts).c_str(), s.matches ? "*" : " ");
    }
    std::printf("\n(* = the paper's counts)\n");
  }

  if (out) {
    for (const RowRun& r : runs) {
      write_scene(*out, r.fast.record);
      write_scene(*out, r.relaxation.record);
    }
    for (const auto& row_scenes : layer)
      for (const BarLayerScene& l : row_scenes) write_scene(*out, l.record);
    const std::string g = "/studies/table3";
    std::vector<int> row, pg, ps, pk, bg, bs, bk, fg, fs, fk, rg, rs, rk, fit, rit;
    std::vector<double> ft, rt, fres, rres, agree;
    for (const RowRun& r : runs) {
      row.push_back(r.paper.row);
      pg.push_back(r.paper.paper.gap); ps.push_back(r.paper.paper.slide); pk.push_back(r.paper.paper.stick);
      bg.push_back(r.baseline.gap); bs.push_back(r.baseline.slide); bk.push_back(r.baseline.stick);
      fg.push_back(r.fast.counts.gap); fs.push_back(r.fast.counts.slide); fk.push_back(r.fast.counts.stick);
      rg.push_back(r.relaxation.counts.gap); rs.push_back(r.relaxation.counts.slide); rk.push_back(r.relaxation.counts.stick);
      fit.push_back(r.fast.report.iterations); rit.push_back(r.relaxation.report.iterations);
      ft.push_back(r.fast_time); rt.push_back(r.relaxation_time);
      fres.push_back(r.fast.report.residual.value()); rres.push_back(r.relaxation.report.residual.value());
      agree.push_back(r.agreement);
    }
    const std::map<std::string, const std::vector<int>*> ints = {
        {"row", &row}, {"paper_gap", &pg}, {"paper_slide", &ps}, {"paper_stick", &pk}, {"baseline_gap", &bg},
        {"baseline_slide", &bs}, {"baseline_stick", &bk}, {"fast_gap", &fg}, {"fast_slide", &fs}, {"fast_stick", &fk},
        {"relaxation_gap", &rg}, {"relaxation_slide", &rs}, {"relaxation_stick", &rk}, {"fast_iterations", &fit},
        {"relaxation_iterations", &rit}};
    for (const auto& [name, v] : ints) out->dataset(g + "/rows/" + name, *v);
    const std::map<std::string, const std::vector<double>*> doubles = {
        {"fast_time_s", &ft}, {"relaxation_time_s", &rt}, {"fast_residual", &fres},
        {"relaxation_residual", &rres}, {"interface_jump_distance", &agree}};
    for (const auto& [name, v] : doubles) out->dataset(g + "/rows/" + name, *v);
    out->attr(g, "status_tolerance", default_status_tolerance);
    out->attr(g, "timing_repeats", options.repeats);
    out->attr(g, "missing_transition_mm", missing_transition);

    std::vector<int> levels_out(levels.begin(), levels.end());
    out->dataset(g + "/refinement/n", levels_out);
    for (size_t i = 0; i < paper.size(); ++i) {
      std::vector<double> gc, ss;
      for (int n : levels) {
        gc.push_back(refined[n][i].gap_contact);
        ss.push_back(refined[n][i].stick_slip);
      }
      out->dataset(g + "/refinement/row" + std::to_string(i + 1) + "/gap_contact_mm", no_nan(gc));
      out->dataset(g + "/refinement/row" + std::to_string(i + 1) + "/stick_slip_mm", no_nan(ss));
    }
    if (!sensitivity.empty()) {
      std::vector<std::string> plane, element;
      std::vector<int> nx, ny, srow, gap, slide, stick, converged, matches;
      std::vector<double> scale, gc, ss, res;
      for (const auto& s : sensitivity) {
        plane.push_back(to_string(s.v.plane));
        element.push_back(s.v.element == ElementType::Q1 ? "Q1"
                          : s.v.diagonal == TriangleDiagonal::Right ? "P1-right" : "P1-left");
        nx.push_back(s.v.nx); ny.push_back(s.v.ny); scale.push_back(s.v.scale); srow.push_back(s.row);
        gap.push_back(s.counts.gap); slide.push_back(s.counts.slide); stick.push_back(s.counts.stick);
        converged.push_back(s.converged); matches.push_back(s.matches);
        gc.push_back(s.t.gap_contact); ss.push_back(s.t.stick_slip); res.push_back(s.residual);
      }
      const std::string sg = g + "/sensitivity";
      out->dataset(sg + "/plane", plane);
      out->dataset(sg + "/element", element);
      for (const auto& [name, v] : std::map<std::string, const std::vector<int>*>{
               {"nx", &nx}, {"ny", &ny}, {"row", &srow}, {"gap", &gap}, {"slide", &slide}, {"stick", &stick},
               {"converged", &converged}, {"matches_paper", &matches}})
        out->dataset(sg + "/" + name, *v);
      for (const auto& [name, v] : std::map<std::string, const std::vector<double>*>{
               {"scale", &scale}, {"gap_contact_mm", &gc}, {"stick_slip_mm", &ss}, {"residual", &res}})
        out->dataset(sg + "/" + name, no_nan(*v));
    }
  }
  return checks;
}

}  // namespace thinlayer
