#include "studies/drivers/skip_study.h"

#include <cstdio>
#include <string>

#include "cases/dovetail/dovetail.h"
#include "core/io/column_table.h"
#include "core/io/reference_tables.h"
#include "core/solvers/fast_solver.h"
#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "studies/tools/format.h"
#include "studies/tools/stopwatch.h"

namespace thinlayer {

namespace {

struct Shortcut {
  std::string name;        // check ids are timing.skip.<name>.*
  std::string scenes;      // what it was measured on
  double with_s = 0;       // median wall time with the shortcut, s
  double without_s = 0;    // and without it
  double difference = 0;   // max over the scenes of |u_with - u_without| / |u_without|
  int iterations_with = 0, iterations_without = 0;  // active-set steps, summed over the scenes
};

double relative_difference(const std::vector<Eigen::VectorXd>& a, const std::vector<Eigen::VectorXd>& b) {
  double worst = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) worst = std::max(worst, (a[i] - b[i]).norm() / b[i].norm());
  return worst;
}

// SPEC §1.5: what the problem determines are the adherents' displacements; a floating
// layer's position may differ between two valid answers (a warm start selects another).
Eigen::VectorXd adherents_part(const LinearSystem& system, const Eigen::VectorXd& u) {
  std::vector<double> kept;
  for (int i = 0; i < system.num_free(); ++i)
    if (!system.floating(i)) kept.push_back(u[i]);
  return Eigen::Map<const Eigen::VectorXd>(kept.data(), static_cast<Eigen::Index>(kept.size()));
}

std::vector<InterfaceLaw> table3_laws() {
  std::vector<InterfaceLaw> laws;
  for (const Table3Row& row : load_table3_paper())
    laws.push_back(table3_law(row));
  return laws;
}

std::vector<InterfaceLaw> dovetail_laws(const std::string& cases) {
  std::vector<InterfaceLaw> laws;
  for (char c : cases) laws.push_back(dovetail::limit_law(dovetail::exponents_of(c)));
  return laws;
}

// Laws on one bulk: one condensation shared by all (with) or one per law (without).
template <class MakeProblem>
Shortcut factorisation_reuse(const std::string& name, const std::string& scenes, const std::vector<InterfaceLaw>& laws,
                             MakeProblem make_problem, int repeats) {
  Shortcut s{name, scenes};
  std::vector<Eigen::VectorXd> with, without;
  s.with_s = median_time(repeats, [&] {
    with.clear();
    s.iterations_with = 0;
    const CondensedInterface shared(make_problem(laws.front()));
    for (const InterfaceLaw& law : laws) {
      const SolveReport r = solve_fast(make_problem(law), shared);
      with.push_back(r.u);
      s.iterations_with += r.iterations;
    }
  });
  s.without_s = median_time(repeats, [&] {
    without.clear();
    s.iterations_without = 0;
    for (const InterfaceLaw& law : laws) {
      const ContactProblem problem = make_problem(law);
      const SolveReport r = solve_fast(problem, CondensedInterface(problem));
      without.push_back(r.u);
      s.iterations_without += r.iterations;
    }
  });
  s.difference = relative_difference(with, without);
  return s;
}

// The same scenes solved with two sets of options, on shared condensations (solve phase only).
Shortcut compare_options(const std::string& name, const std::string& scenes,
                         const std::vector<const ContactProblem*>& problems,
                         const std::vector<const CondensedInterface*>& condensed,
                         const std::vector<SolverOptions>& with_options, const std::vector<SolverOptions>& without_options,
                         int repeats) {
  Shortcut s{name, scenes};
  std::vector<Eigen::VectorXd> with, without;
  auto run = [&](const std::vector<SolverOptions>& options, std::vector<Eigen::VectorXd>& u, int& iterations) {
    u.clear();
    iterations = 0;
    for (size_t i = 0; i < problems.size(); ++i) {
      const SolveReport r = solve_fast(*problems[i], *condensed[i], options[i]);
      u.push_back(adherents_part(problems[i]->system(), r.u));
      iterations += r.iterations;
    }
  };
  s.with_s = median_time(repeats, [&] { run(with_options, with, s.iterations_with); });
  s.without_s = median_time(repeats, [&] { run(without_options, without, s.iterations_without); });
  s.difference = relative_difference(with, without);
  return s;
}

}  // namespace

std::vector<Check> run_skip_study(const SkipStudyOptions& options, H5Writer* out) {
  const int repeats = options.repeats;
  std::vector<Shortcut> shortcuts;

  std::fprintf(stderr, "[timing] skip what a scene doesn't need: the bar\n");
  BarBulk bar_bulk(bar::MeshOptions{});
  auto bar_problem = [&](const InterfaceLaw& law) {
    return ContactProblem(bar_bulk.system(), {bar::make_interface(bar_bulk.model(), law)});
  };
  const std::vector<InterfaceLaw> rows = table3_laws();
  shortcuts.push_back(factorisation_reuse("factorisation_reuse_table3", "bar, the 6 Table 3 rows, limit mode", rows,
                                          bar_problem, repeats));

  std::fprintf(stderr, "[timing] skip what a scene doesn't need: the dovetail\n");
  DovetailLimitBulk dovetail_bulk;
  auto dovetail_problem = [&](const InterfaceLaw& law) {
    return ContactProblem(dovetail_bulk.system(), {dovetail::make_limit_interface(dovetail_bulk.model(), law)});
  };
  shortcuts.push_back(factorisation_reuse("factorisation_reuse_dovetail", "dovetail, the 9 limit laws of Table 2",
                                          dovetail_laws("abcdefghi"), dovetail_problem, repeats));

  {  // Frictionless laws: the tangential rows left out, or kept as slides with r_T = 0.
    std::vector<ContactProblem> problems;
    for (const InterfaceLaw& law : dovetail_laws("ace")) problems.push_back(dovetail_problem(law));
    std::vector<const ContactProblem*> p;
    for (const ContactProblem& q : problems) p.push_back(&q);
    const std::vector<const CondensedInterface*> c(p.size(), &dovetail_bulk.condensed());
    SolverOptions kept;
    kept.skip_frictionless_rows = false;
    shortcuts.push_back(compare_options("no_friction_rows", "dovetail limit, cases a, c, e (solve phase)", p, c,
                                        std::vector<SolverOptions>(p.size()), std::vector<SolverOptions>(p.size(), kept),
                                        repeats));
  }

  {  // Known statuses: each Table 3 row re-solved from its own answer is one linear solve.
    std::vector<ContactProblem> problems;
    for (const InterfaceLaw& law : rows) problems.push_back(bar_problem(law));
    std::vector<const ContactProblem*> p;
    std::vector<SolverOptions> warm;
    for (const ContactProblem& q : problems) {
      p.push_back(&q);
      SolverOptions o;
      o.initial_r = solve_fast(q, bar_bulk.condensed()).r;
      warm.push_back(o);
    }
    const std::vector<const CondensedInterface*> c(p.size(), &bar_bulk.condensed());
    shortcuts.push_back(compare_options("known_statuses", "bar, the 6 Table 3 rows from their own answer (solve phase)",
                                        p, c, warm, std::vector<SolverOptions>(p.size()), repeats));
  }

  {  // Warm starts along ε: each thickness starts from the previous one's forces and layer.
    std::fprintf(stderr, "[timing] skip what a scene doesn't need: warm starts along eps\n");
    const Table3Row row1 = load_table3_paper().at(0);
    const std::vector<double> eps = {1e-2, 1e-3, 1e-4};  // mm
    std::vector<Model> models;
    std::vector<std::unique_ptr<LinearSystem>> systems;
    std::vector<ContactProblem> problems;
    std::vector<std::unique_ptr<CondensedInterface>> condensed;
    models.reserve(eps.size());
    problems.reserve(eps.size());
    for (double e : eps) {
      bar::LayerOptions layer;
      layer.eps = e;
      layer.lambda_eps = e * row1.lambda_bar;
      layer.mu_eps = e * row1.mu_bar;
      models.push_back(bar::make_layer_model({}, layer));
      systems.push_back(std::make_unique<LinearSystem>(models.back()));
      problems.emplace_back(*systems.back(), bar::make_layer_interfaces(models.back()));
      condensed.push_back(std::make_unique<CondensedInterface>(problems.back()));
    }
    std::vector<const ContactProblem*> p;
    std::vector<const CondensedInterface*> c;
    std::vector<SolverOptions> warm(eps.size());
    for (size_t i = 0; i < eps.size(); ++i) {
      p.push_back(&problems[i]);
      c.push_back(condensed[i].get());
      if (i + 1 < eps.size()) {  // the warm start of ε_{i+1} is the answer at ε_i
        const SolveReport previous = solve_fast(problems[i], *condensed[i]);
        warm[i + 1].initial_r = previous.r;
        warm[i + 1].initial_w = previous.w;
      }
    }
    shortcuts.push_back(compare_options("warm_start_eps", "bar layer, row 1, eps 1e-2 -> 1e-3 -> 1e-4 (solve phase)", p,
                                        c, warm, std::vector<SolverOptions>(p.size()), repeats));
  }

  std::printf("\nSkip what a scene doesn't need (S5): medians of %d runs; difference = max |u_with - u_without| / "
              "|u_without| over the adherents (a floating layer's position is not unique, SPEC 1.5)\n\n", repeats);
  std::printf("%-30s %-58s %9s %9s %7s %9s %s\n", "shortcut", "scenes", "with[s]", "without[s]", "saving", "difference",
              "steps with/without");
  std::vector<Check> checks;
  ColumnTable table;
  for (const Shortcut& s : shortcuts) {
    std::printf("%-30s %-58s %9.4f %9.4f %6.1fx %9s %d/%d\n", s.name.c_str(), s.scenes.c_str(), s.with_s, s.without_s,
                s.without_s / s.with_s, sci(s.difference, 1).c_str(), s.iterations_with, s.iterations_without);
    // A shortcut changes the cost, never the answer: both paths solve to the SPEC residual 1e-10.
    checks.push_back({"timing.skip." + s.name + ".same_answer", s.difference <= 1e-8,
                      "|u_with - u_without| / |u_without| <= 1e-8", sci(s.difference, 1), "1e-8"});
    table.add("shortcut", s.name);
    table.add("scenes", s.scenes);
    table.add("time_with_s", s.with_s);
    table.add("time_without_s", s.without_s);
    table.add("saving", s.without_s / s.with_s);
    table.add("difference", s.difference);
    table.add("iterations_with", s.iterations_with);
    table.add("iterations_without", s.iterations_without);
  }
  if (out) {
    table.write(*out, "/studies/timing/skip");
    out->attr("/studies/timing/skip", "repeats", repeats);
  }
  return checks;
}

}  // namespace thinlayer
