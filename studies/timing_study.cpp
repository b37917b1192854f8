#include "studies/timing_study.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/io/column_table.h"
#include "core/io/reference_tables.h"
#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"
#include "studies/bar_scenes.h"
#include "studies/format.h"
#include "studies/stopwatch.h"

namespace thinlayer {

namespace {

constexpr double error_floor = 1e-16;  // round-off: a smaller error is stored as this

struct Row {
  std::string solver, level;
  int contact_nodes = 0, unknowns = 0, iterations = 0;
  double tolerance = 0, time_s = 0, error = 0, ratio_to_linear = 0;
  bool converged = false;
};

double relative_error(const Eigen::VectorXd& u, const Eigen::VectorXd& reference) {
  return std::max((u - reference).norm() / reference.norm(), error_floor);
}

}  // namespace

std::vector<Check> run_timing_study(const TimingStudyOptions& options, H5Writer* out) {
  const Table3Row row1 = load_table3_paper().at(0);
  const InterfaceLaw law = InterfaceLaw::make(row1.lambda_bar, row1.mu_bar, 1.0);
  std::vector<int> levels = options.fast_levels;
  for (int n : options.relaxation_levels)
    if (std::find(levels.begin(), levels.end(), n) == levels.end()) levels.push_back(n);
  std::sort(levels.begin(), levels.end());

  std::printf("\nRun time against error (S5, quick): the bar, Table 3 row 1, limit mode, Q1 n x n with n contact\n"
              "nodes; error = |u - u_ref| / |u_ref| against the fast solver at residual %g; times are medians of %d runs;\n"
              "ratio = time / (one CHOLMOD factorisation + solve of the same mesh, no contact)\n\n",
              options.reference_tolerance, options.repeats);
  std::printf("%-11s %-9s %8s %9s | %9s %10s %7s %9s %s\n", "solver", "level", "unknowns", "tolerance", "time[s]",
              "error", "it", "ratio", "");
  std::vector<Row> rows;
  std::vector<Check> checks;
  for (int n : levels) {
    std::fprintf(stderr, "[timing] bar %d x %d\n", n, n);
    bar::MeshOptions mesh;
    mesh.nx = mesh.ny = n;
    BarBulk bulk(mesh);
    const std::string level = "bar-" + std::to_string(n);
    const int unknowns = bulk.system().num_free();
    const double linear = median_time(options.repeats, [&] {
      const SparseCholesky factor(bulk.system().K());
      const Eigen::VectorXd u = factor.solve(bulk.system().F());
      if (!u.allFinite()) throw std::runtime_error("timing: the linear solve of " + level + " failed");
    });
    Row lin{"linear", level, n, unknowns, 1, 0.0, linear, 0.0, 1.0, true};
    rows.push_back(lin);
    std::printf("%-11s %-9s %8d %9s | %9.4f %10s %7s %9s\n", "linear", level.c_str(), unknowns, "-", linear, "-", "-",
                "1");
    const ContactProblem problem(bulk.system(), {bar::make_interface(bulk.model(), law)});
    SolverOptions tight;
    tight.tolerance = options.reference_tolerance;
    const SolveReport reference = solve_fast(problem, bulk.condensed(), tight);
    checks.push_back({"timing." + level + ".reference_converged", reference.converged,
                      "residual <= " + sci(options.reference_tolerance, 0), sci(reference.residual.value(), 1),
                      sci(options.reference_tolerance, 0)});

    if (std::find(options.fast_levels.begin(), options.fast_levels.end(), n) != options.fast_levels.end()) {
      // The whole fast solve as a user runs it: factorisation and condensation, then the active set.
      SolveReport r;
      const double t = median_time(options.repeats, [&] {
        const CondensedInterface condensed(problem);
        r = solve_fast(problem, condensed, SolverOptions{});
      });
      Row row{"fast", level, n, unknowns, r.iterations, SolverOptions{}.tolerance, t, relative_error(r.u, reference.u),
              t / linear, r.converged};
      rows.push_back(row);
      checks.push_back({"timing." + level + ".fast.error", r.converged && row.error <= 1e-8,
                        "converged, error to the reference <= 1e-8", sci(row.error, 1), "1e-8"});
    }
    if (std::find(options.relaxation_levels.begin(), options.relaxation_levels.end(), n) !=
        options.relaxation_levels.end())
      for (double tol : options.relaxation_tolerances) {
        SolverOptions o;
        o.tolerance = tol;
        o.max_iterations = options.relaxation_cap;
        SolveReport r;
        const double t = median_time(options.repeats, [&] { r = solve_relaxation(problem, o); });
        rows.push_back({"relaxation", level, n, unknowns, r.iterations, tol, t, relative_error(r.u, reference.u),
                        t / linear, r.converged});
      }
    for (const Row& r : rows)
      if (r.level == level && r.solver != "linear")
        std::printf("%-11s %-9s %8d %9s | %9.4f %10s %7d %9.1f %s\n", r.solver.c_str(), r.level.c_str(), r.unknowns,
                    sci(r.tolerance, 0).c_str(), r.time_s, sci(r.error, 2).c_str(), r.iterations, r.ratio_to_linear,
                    r.converged ? "" : "NOT converged (cap)");
  }

  if (out) {
    const std::string g = "/studies/timing";
    ColumnTable solves, linear;
    for (const Row& r : rows) {
      if (r.solver == "linear") {
        linear.add("level", r.level);
        linear.add("time_s", r.time_s);
        continue;
      }
      solves.add("solver", r.solver);
      solves.add("level", r.level + (r.solver == "relaxation" ? " tol " + sci(r.tolerance, 0) : ""));
      solves.add("contact_nodes", r.contact_nodes);
      solves.add("unknowns", r.unknowns);
      solves.add("iterations", r.iterations);
      solves.add("converged", r.converged ? 1 : 0);
      solves.add("tolerance", r.tolerance);
      solves.add("time_s", r.time_s);
      solves.add("error", r.error);
      solves.add("ratio_to_linear", r.ratio_to_linear);
    }
    solves.write(*out, g);
    linear.write(*out, g + "/linear");
    out->attr(g, "error_floor", error_floor);
    out->attr(g, "repeats", options.repeats);
    out->attr(g, "reference", std::string("fast solver at residual ") + sci(options.reference_tolerance, 0));
    out->attr(g, "case", std::string("bar, Table 3 row 1, limit mode, Q1 n x n"));
  }
  return checks;
}

}  // namespace thinlayer
