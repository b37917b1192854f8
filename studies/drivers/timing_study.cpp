#include "studies/drivers/timing_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "cases/dovetail/dovetail.h"
#include "core/io/column_table.h"
#include "core/io/reference_tables.h"
#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"
#include "core/solvers/siconos_peers.h"
#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "studies/tools/format.h"
#include "studies/tools/rate_fit.h"
#include "studies/tools/stopwatch.h"

namespace thinlayer {

TimingStudyOptions TimingStudyOptions::quick() {
  TimingStudyOptions o;
  o.fast_levels = {32, 64, 128};
  o.peer_levels = {32, 64};
  o.peer_tolerances = {1e-10};
  o.dovetail_h = {0.05, 0.025};
  o.layer_eps = {1e-4};
  return o;
}

namespace {

constexpr double error_floor = 1e-16;  // round-off: a smaller error is stored as this
constexpr double no_reference = -1;    // error column of a solve without a tight reference

// One timed solve. Solvers: "linear" (factorisation + solve, no contact), "fast" (condensation
// + active set), "fast-solve" (the active set on the shared condensation), "relaxation",
// "siconos-nsgs" and "siconos-lemke" (solve phase on the shared condensation), "fast-layer"
// (layer mode: meshes, condensation and proximal active set).
struct Row {
  std::string solver, level;
  int contact_nodes = 0, unknowns = 0, iterations = 0;
  double tolerance = 0, time_s = 0, error = 0, residual = 0, ratio_to_linear = 0;
  bool converged = false;
};

double relative_error(const Eigen::VectorXd& u, const Eigen::VectorXd& reference) {
  return std::max((u - reference).norm() / reference.norm(), error_floor);
}

Row timed_row(const std::string& solver, const std::string& level, const ContactProblem& problem, double tolerance,
              double time_s, double linear_s, const SolveReport& r, const Eigen::VectorXd& reference) {
  return {solver,
          level,
          problem.num_nodes(),
          problem.system().num_free(),
          r.iterations,
          tolerance,
          time_s,
          relative_error(r.u, reference),
          r.residual.value(),
          time_s / linear_s,
          r.converged};
}

double linear_solve_time(const LinearSystem& system, int repeats, const std::string& level) {
  return median_time(repeats, [&] {
    const SparseCholesky factor(system.K());
    const Eigen::VectorXd u = factor.solve(system.F());
    if (!u.allFinite()) throw std::runtime_error("timing: the linear solve of " + level + " failed");
  });
}

// The tight reference of one scene, and a check that it is tight.
Eigen::VectorXd reference_solution(const ContactProblem& problem, const CondensedInterface& condensed,
                                   const TimingStudyOptions& o, const std::string& level, std::vector<Check>& checks) {
  SolverOptions tight;
  tight.tolerance = o.reference_tolerance;
  const SolveReport reference = solve_fast(problem, condensed, tight);
  checks.push_back({"timing." + level + ".reference_converged", reference.converged,
                    "residual <= " + sci(o.reference_tolerance, 0), sci(reference.residual.value(), 1),
                    sci(o.reference_tolerance, 0)});
  return reference.u;
}

bool contains(const std::vector<int>& v, int x) { return std::find(v.begin(), v.end(), x) != v.end(); }

// The bar, Table 3 row 1, limit mode: every solver at level n.
void bar_level(const TimingStudyOptions& o, int n, std::vector<Row>& rows, std::vector<Check>& checks) {
  std::fprintf(stderr, "[timing] bar %d x %d\n", n, n);
  bar::MeshOptions mesh;
  mesh.nx = mesh.ny = n;
  BarBulk bulk(mesh);
  const std::string level = "bar-" + std::to_string(n);
  const double linear = linear_solve_time(bulk.system(), o.repeats, level);
  rows.push_back({"linear", level, n, bulk.system().num_free(), 1, 0.0, linear, no_reference, 0.0, 1.0, true});

  const Table3Row row1 = load_table3_paper().at(0);
  const ContactProblem problem(bulk.system(),
                               {bar::make_interface(bulk.model(), table3_law(row1))});
  const Eigen::VectorXd reference = reference_solution(problem, bulk.condensed(), o, level, checks);

  if (contains(o.fast_levels, n)) {
    SolveReport r;
    // As a user runs one scene: factorisation and condensation, then the active set.
    const double total = median_time(o.repeats, [&] { r = solve_fast(problem, CondensedInterface(problem)); });
    rows.push_back(timed_row("fast", level, problem, SolverOptions{}.tolerance, total, linear, r, reference));
    checks.push_back({"timing." + level + ".fast.error", r.converged && rows.back().error <= 1e-8,
                      "converged, error to the reference <= 1e-8", sci(rows.back().error, 1), "1e-8"});
    const double solve = median_time(o.repeats, [&] { r = solve_fast(problem, bulk.condensed()); });
    rows.push_back(timed_row("fast-solve", level, problem, SolverOptions{}.tolerance, solve, linear, r, reference));
  }
  if (contains(o.relaxation_levels, n))
    for (double tol : o.relaxation_tolerances) {
      SolverOptions opt;
      opt.tolerance = tol;
      opt.max_iterations = o.relaxation_cap;
      SolveReport r;
      const double t = median_time(o.repeats, [&] { r = solve_relaxation(problem, opt); });
      rows.push_back(timed_row("relaxation", level, problem, tol, t, linear, r, reference));
    }
  if (contains(o.peer_levels, n))
    for (PeerSolver peer : {PeerSolver::NSGS, PeerSolver::Lemke})
      for (double tol : o.peer_tolerances) {
        SolverOptions opt;
        opt.tolerance = tol;
        opt.max_iterations = o.peer_cap;
        SolveReport r;
        const double t = median_time(o.repeats, [&] { r = solve_siconos(problem, bulk.condensed(), peer, opt); });
        rows.push_back(timed_row(to_string(peer), level, problem, tol, t, linear, r, reference));
      }
}

// The dovetail, case d, limit mode at element size h along S; layer mode at the given ε on
// the default mesh, timed whole (layer meshes, condensation, solve) against the linear solve
// of the limit-mode mesh of the same h (the layer adds two rows of elements along S).
void dovetail_levels(const TimingStudyOptions& o, std::vector<Row>& rows, std::vector<Check>& checks) {
  const dovetail::Exponents d = dovetail::exponents_of('d');
  for (double h : o.dovetail_h) {
    std::fprintf(stderr, "[timing] dovetail, h = %g along S\n", h);
    dovetail::MeshOptions mesh;
    mesh.h_interface = h;
    mesh.h_far = std::min(1.0, 4 * h);  // the default ratio, 0.1 / 0.025
    DovetailLimitBulk bulk(mesh);
    const std::string level = "dovetail-h" + plain(h);
    const double linear = linear_solve_time(bulk.system(), o.repeats, level);
    rows.push_back({"linear", level, 0, bulk.system().num_free(), 1, 0.0, linear, no_reference, 0.0, 1.0, true});
    const ContactProblem problem(bulk.system(), {dovetail::make_limit_interface(bulk.model(), dovetail::limit_law(d))});
    const Eigen::VectorXd reference = reference_solution(problem, bulk.condensed(), o, level, checks);
    SolveReport r;
    const double total = median_time(o.repeats, [&] { r = solve_fast(problem, CondensedInterface(problem)); });
    rows.push_back(timed_row("fast", level, problem, SolverOptions{}.tolerance, total, linear, r, reference));

    if (h != dovetail::MeshOptions{}.h_interface) continue;
    for (double eps : o.layer_eps) {
      std::fprintf(stderr, "[timing] dovetail layer, case d, eps = %g\n", eps);
      DovetailScene s;
      const double t = median_time(o.layer_eps.size() > 1 ? o.repeats : 1, [&] {
        s = solve_dovetail_layer(bulk, d, eps, "d", SolverKind::Fast, SolverOptions{});
      });
      // No tight reference in layer mode (its solves stop at 1e-10): the residual tells the accuracy.
      // unknowns: two per node of the three bodies (the few fixed ones included)
      rows.push_back({"fast-layer", "dovetail-layer-eps" + plain(eps), problem.num_nodes(),
                      static_cast<int>(s.record.nodes.rows() * 2), s.report.iterations, SolverOptions{}.tolerance, t,
                      no_reference, s.report.residual.value(), t / linear, s.report.converged});
    }
  }
}

// How time grows with the unknowns on the bar's levels: t ≈ C n^p, p by least squares on log–log.
struct Scaling {
  std::string solver;
  PowerLawFit fit;
};

std::vector<Scaling> scaling(const std::vector<Row>& rows) {
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> points;
  for (const Row& r : rows) {
    if (r.level.rfind("bar-", 0) != 0) continue;
    const bool tight = r.tolerance == 0 || r.tolerance == SolverOptions{}.tolerance;  // one point per level
    if (!tight || (r.solver != "linear" && !r.converged)) continue;
    points[r.solver].first.push_back(r.unknowns);
    points[r.solver].second.push_back(r.time_s);
  }
  std::vector<Scaling> out;
  for (const auto& [solver, xy] : points)
    if (const auto fit = fit_power_law(xy.first, xy.second)) out.push_back({solver, *fit});
  return out;
}

struct Target {
  std::string target, goal, measured;
  bool met = false;
};

const Row* find_row(const std::vector<Row>& rows, const std::string& solver, const std::string& level,
                    double tolerance = SolverOptions{}.tolerance) {
  for (const Row& r : rows)
    if (r.solver == solver && r.level == level && (r.solver == "linear" || r.tolerance == tolerance)) return &r;
  return nullptr;
}

std::vector<Target> targets(const std::vector<Row>& rows, const std::vector<Scaling>& fits) {
  std::vector<Target> out;
  {  // limit mode ≤ 1.5 × linear, at every level
    double worst = 0;
    std::string where;
    for (const Row& r : rows)
      if (r.solver == "fast" && r.ratio_to_linear > worst) {
        worst = r.ratio_to_linear;
        where = r.level;
      }
    out.push_back({"limit-mode contact solve (condensation + active set) / one linear solve", "<= 1.5",
                   "worst " + fixed(worst, 2) + " (" + where + ")", worst > 0 && worst <= 1.5});
  }
  for (const Row& r : rows)
    if (r.solver == "fast-layer" && r.level == "dovetail-layer-eps0.0001")
      out.push_back({"layer-mode solve at eps 1e-4 / one linear solve", "<= 3",
                     fixed(r.ratio_to_linear, 1) + (r.converged ? "" : " (not converged)"),
                     r.converged && r.ratio_to_linear <= 3});
  for (const Row& r : rows) {  // ≥ 100 × faster than the relaxation at residual 1e-10
    if (r.solver != "relaxation" || r.tolerance != 1e-10) continue;
    // Whole solve against whole solve: the relaxation needs no factorisation, the fast solver's
    // time includes its own. Its solve phase alone (each further scene on the bulk) is shown too.
    const Row* fast = find_row(rows, "fast", r.level);
    const Row* fast_solve = find_row(rows, "fast-solve", r.level);
    if (!fast || !fast_solve) continue;
    out.push_back({"relaxation / fast (whole solves) at residual 1e-10, " + r.level, ">= 100",
                   r.converged ? fixed(r.time_s / fast->time_s, 1) + " (against the solve phase alone: " +
                                     fixed(r.time_s / fast_solve->time_s, 0) + ")"
                               : "the relaxation never got there (" + std::to_string(r.iterations) + " sweeps)",
                   !r.converged || r.time_s / fast->time_s >= 100});
  }
  for (const Row& r : rows) {  // faster than the peers, solve phase against solve phase
    if (r.solver.rfind("siconos-", 0) != 0 || r.tolerance != 1e-10) continue;
    const Row* fast = find_row(rows, "fast-solve", r.level);
    if (!fast) continue;
    const double ratio = r.time_s / fast->time_s;
    out.push_back({r.solver + " / fast (solve phases) at residual 1e-10, " + r.level, "> 1",
                   fixed(ratio, 1) + (r.converged ? "" : " (the peer stopped at residual " + sci(r.residual, 1) + ")"),
                   ratio > 1 || !r.converged});
  }
  const Scaling* linear = nullptr;
  for (const Scaling& s : fits)
    if (s.solver == "linear") linear = &s;
  if (linear)
    for (const Scaling& s : fits) {
      if (s.solver == "linear") continue;
      const double margin = 2 * std::hypot(s.fit.p_stderr, linear->fit.p_stderr);
      out.push_back({"growth exponent of " + s.solver + " against the factorisation's (" + fixed(linear->fit.p, 2) + ")",
                     "<= " + fixed(linear->fit.p, 2) + " + 2 s.e.",
                     fixed(s.fit.p, 2) + " +- " + fixed(s.fit.p_stderr, 2), s.fit.p <= linear->fit.p + margin});
    }
  return out;
}

void print(const std::vector<Row>& rows, const std::vector<Scaling>& fits, const std::vector<Target>& goals,
           const TimingStudyOptions& o) {
  std::printf("\nRun time against error (S5): error = |u - u_ref| / |u_ref| against the fast solver at residual %g;\n"
              "medians of %d runs; ratio = time / one CHOLMOD factorisation + solve of the same mesh without contact\n"
              "(layer mode: of the limit-mode mesh). fast = condensation + active set; fast-solve, siconos-*: solve\n"
              "phase on the shared condensation.\n\n",
              o.reference_tolerance, o.repeats);
  std::printf("%-14s %-24s %8s %9s | %9s %10s %10s %7s %8s %s\n", "solver", "level", "unknowns", "tolerance",
              "time[s]", "error", "residual", "it", "ratio", "");
  for (const Row& r : rows)
    std::printf("%-14s %-24s %8d %9s | %9.4f %10s %10s %7d %8.2f %s\n", r.solver.c_str(), r.level.c_str(), r.unknowns,
                r.tolerance ? sci(r.tolerance, 0).c_str() : "-", r.time_s,
                r.error == no_reference ? "-" : sci(r.error, 2).c_str(), r.residual ? sci(r.residual, 1).c_str() : "-",
                r.iterations, r.ratio_to_linear, r.converged ? "" : "NOT converged");
  std::printf("\nGrowth with the number of unknowns on the bar, t ~ C n^p (least squares on log-log):\n");
  for (const Scaling& s : fits)
    std::printf("  %-14s p = %.2f +- %.2f (%d levels)\n", s.solver.c_str(), s.fit.p, s.fit.p_stderr, s.fit.points);
  std::printf("\nTargets (goals, reported, not tests):\n");
  for (const Target& t : goals)
    std::printf("  %-4s %-78s goal %-18s measured %s\n", t.met ? "met" : "NOT", t.target.c_str(), t.goal.c_str(),
                t.measured.c_str());
}

void write(H5Writer& out, const std::vector<Row>& rows, const std::vector<Scaling>& fits,
           const std::vector<Target>& goals, const TimingStudyOptions& o) {
  const std::string g = "/studies/timing";
  ColumnTable solves, linear, scaling_table, target_table;
  for (const Row& r : rows) {
    if (r.solver == "linear") {
      linear.add("level", r.level);
      linear.add("unknowns", r.unknowns);
      linear.add("time_s", r.time_s);
      continue;
    }
    solves.add("solver", r.solver);
    solves.add("level", r.level + (r.solver == "relaxation" || r.solver.rfind("siconos-", 0) == 0
                                       ? " tol " + sci(r.tolerance, 0)
                                       : ""));
    solves.add("mesh", r.level);
    solves.add("contact_nodes", r.contact_nodes);
    solves.add("unknowns", r.unknowns);
    solves.add("iterations", r.iterations);
    solves.add("converged", r.converged ? 1 : 0);
    solves.add("tolerance", r.tolerance);
    solves.add("time_s", r.time_s);
    solves.add("error", r.error);
    solves.add("residual", r.residual);
    solves.add("ratio_to_linear", r.ratio_to_linear);
  }
  for (const Scaling& s : fits) {
    scaling_table.add("solver", s.solver);
    scaling_table.add("exponent", s.fit.p);
    scaling_table.add("exponent_stderr", s.fit.p_stderr);
    scaling_table.add("points", s.fit.points);
  }
  for (const Target& t : goals) {
    target_table.add("target", t.target);
    target_table.add("goal", t.goal);
    target_table.add("measured", t.measured);
    target_table.add("met", t.met ? 1 : 0);
  }
  solves.write(out, g);
  linear.write(out, g + "/linear");
  scaling_table.write(out, g + "/scaling");
  target_table.write(out, g + "/targets");
  out.attr(g, "error_floor", error_floor);
  out.attr(g, "no_reference", no_reference);
  out.attr(g, "repeats", o.repeats);
  out.attr(g, "reference", std::string("fast solver at residual ") + sci(o.reference_tolerance, 0));
  out.attr(g, "case", std::string("bar: Table 3 row 1, limit mode, Q1 n x n; dovetail: case d"));
}

}  // namespace

std::vector<Check> run_timing_study(const TimingStudyOptions& options, H5Writer* out) {
  std::vector<int> levels = options.fast_levels;
  for (const auto* more : {&options.relaxation_levels, &options.peer_levels})
    for (int n : *more)
      if (!contains(levels, n)) levels.push_back(n);
  std::sort(levels.begin(), levels.end());

  std::vector<Row> rows;
  std::vector<Check> checks;
  for (int n : levels) bar_level(options, n, rows, checks);
  dovetail_levels(options, rows, checks);
  const std::vector<Scaling> fits = scaling(rows);
  const std::vector<Target> goals = targets(rows, fits);
  print(rows, fits, goals, options);
  if (out) write(*out, rows, fits, goals, options);
  return checks;
}

}  // namespace thinlayer
