// Issue 33's gate experiment: the outer Newton alone (core/solvers/outer_newton.h) on layer
// scenes, seeded from the limit-mode answer. Per scene: the factorisations until the load-scale
// statuses stop changing (the combined status of every point of S whose final force is above
// τ = 1e-2 and 1e-6 of the largest), the factorisations to the tolerance, the residual, time, and
// the bonded solve of the same mesh; with --ladder the current solver's steps and time beside it.
//
//   build/thinlayer_two_scale_gate --dovetail d,e,f --eps 1e-3,1e-4 --h 0.025,0.0125,0.00625
//   build/thinlayer_two_scale_gate --seeds 9,23,55 [--ladder]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "benchmarks/bonded_solve.h"
#include "cases/bar/bar.h"
#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "cases/scene/scene_file_scenes.h"
#include "cases/scene/scene_spec.h"
#include "core/io/reference_tables.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/layer_dual.h"
#include "core/linalg/anderson.h"
#include "benchmarks/two_scale_lab/projected_newton.h"
#include <set>
#include <limits>
#include "core/solvers/mixed_system.h"
#include "benchmarks/two_scale_lab/outer_newton.h"
#include "core/solvers/solver_choice.h"
#include "core/solvers/tnnmg.h"
#include "core/solvers/layer_interior_point.h"
#include "core/linalg/factor_memory.h"
#include "studies/parallel/blas_threads.h"
#include "studies/tools/scene_generator.h"

namespace thinlayer {
namespace {

struct Settings {
  OuterNewtonOptions outer;
  std::string slide_on = "both";   // both | minus | plus: the faces a limit slide seeds as slides
  std::string spring_on = "open";  // open | all | none: the columns whose translations the spring holds
  bool ladder = false;
  bool reference = true;           // the ladder at 1e-12 as the reference (its statuses define "settled")
  std::string method = "newton";   // newton | projected
  bool follow = false;             // springs anchored at the mean of the facing adherent nodes
  bool hold_film = false;          // the limit-open nodes' rows kept gap through the spring steps
  std::string seed = "limit";      // limit | reference
  std::string start = "limit";     // tnnmg: limit | bonded
  bool tresca_reference = false;   // tnnmg: run A, Tresca with the reference answer's thresholds
  int smoothing_sweeps = 1;
  int closing_rounds = 0;
  bool releasing = false;
  double handover = 0;             // ipm: hand over to the descent at this iterate residual
  double hybrid = 1e3;
  bool newton_crossover = true;
};

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

// The limit answer's status at S node k as an Active of one face.
Active face_status(int status, double sigma_T, bool slides) {
  if (status == 0) return Active::Gap;
  if (status == 1 && slides) return sigma_T > 0 ? Active::SlidePositive : Active::SlideNegative;
  return Active::Stick;
}

// The layer problem's seed (interfaces S+ then S-, node k of each is node k of the limit S) and
// the band columns the spring holds (column of S- node k).
struct Seed {
  std::vector<Active> statuses;
  std::vector<std::vector<int>> spring_columns;
  std::vector<std::array<int, 2>> anchor_faces;
};

Seed seed_from_limit(const ContactProblem& layer, const InterfaceFields& limit, const Settings& s) {
  const int m = static_cast<int>(limit.status.size());
  Seed seed;
  if (layer.num_nodes() != 2 * m) throw std::runtime_error("gate: the layer's faces do not match the limit's S");
  seed.statuses.resize(2 * m);
  for (int k = 0; k < m; ++k) {
    seed.statuses[k] = face_status(limit.status[k], limit.sigma_T[k], s.slide_on != "minus");
    seed.statuses[m + k] = face_status(limit.status[k], limit.sigma_T[k], s.slide_on != "plus");
  }
  const LinearSystem& system = layer.system();
  const FloatingBand& band = system.floating_bands().at(0);
  std::vector<int> node_of_free(system.num_free(), -1);
  for (size_t q = 0; q < band.free_dof.size(); q += 2)
    if (band.free_dof[q] >= 0) node_of_free[band.free_dof[q]] = static_cast<int>(q / 2);
  seed.spring_columns.resize(1);
  for (int k = 0; k < m; ++k) {
    const bool open = limit.status[k] == 0;
    if (s.spring_on == "none" || (s.spring_on == "open" && !open)) continue;
    const int free = system.free_index(layer.node(m + k).plus_dof_x);  // S-: the layer is its plus side
    seed.spring_columns[0].push_back(band.layout.column_of(node_of_free.at(free)));
    seed.anchor_faces.push_back({layer.node(k).plus_dof_x, layer.node(m + k).minus_dof_x});  // tenon, base
  }
  return seed;
}

// The combined status (SPEC §2.2) of every point of S from the forces r of a layer answer (S+ then
// S-), classified as the results are (SPEC §1.2, relative tolerance 1e-6, interface by interface).
std::vector<NodeStatus> combined_statuses(const ContactProblem& problem, const Eigen::VectorXd& r) {
  const int m = problem.num_nodes() / 2;
  std::vector<std::vector<NodeStatus>> face(2);
  for (int f = 0; f < 2; ++f) {
    std::vector<InterfaceLaw> laws;
    Eigen::VectorXd sN(m), sT(m);
    for (int k = 0; k < m; ++k) {
      const int node = f * m + k;
      laws.push_back(problem.law(node));
      sN[k] = r[2 * node] / problem.node(node).length;
      sT[k] = r[2 * node + 1] / problem.node(node).length;
    }
    face[f] = classify_statuses(laws, sN, sT, default_status_tolerance);
  }
  std::vector<NodeStatus> out(m);
  for (int k = 0; k < m; ++k) out[k] = combined_status(face[0][k], face[1][k]);
  return out;
}

NodeStatus as_node(Active a) {
  return a == Active::Gap ? NodeStatus::Gap
         : (a == Active::SlidePositive || a == Active::SlideNegative) ? NodeStatus::Slide
                                                                       : NodeStatus::Stick;
}

// The first factorisation from which the combined statuses solved agree, on every point of S
// carrying more than τ of the reference's largest force, with the reference answer's (a tightly
// converged solve of the same scene): 0 if they never do.
int settled_at(const ContactProblem& problem, const OuterNewtonRun& run, const Eigen::VectorXd& reference, double tau,
               bool spring_only = false) {
  const int m = problem.num_nodes() / 2;
  const std::vector<NodeStatus> target = combined_statuses(problem, reference);
  auto force = [&](int k) {
    return std::max(reference.segment<2>(2 * k).norm(), reference.segment<2>(2 * (m + k)).norm());
  };
  double peak = 0;
  for (int k = 0; k < m; ++k) peak = std::max(peak, force(k));
  auto agrees = [&](const OuterStep& step) {
    for (int k = 0; k < m; ++k)
      if (force(k) > tau * peak && combined_status(as_node(step.statuses[k]), as_node(step.statuses[m + k])) != target[k])
        return false;
    return true;
  };
  int first = 0;
  const int last = spring_only ? run.spring_steps : static_cast<int>(run.steps.size());
  for (int j = last - 1; j >= 0 && agrees(run.steps[j]); --j) first = j + 1;
  if (std::getenv("GATE_DETAIL")) {
    std::fprintf(stderr, "tau %g: load rows disagreeing per step:", tau);
    for (const OuterStep& step : run.steps) {
      int wrong = 0;
      for (int k = 0; k < m; ++k)
        wrong += force(k) > tau * peak &&
                 combined_status(as_node(step.statuses[k]), as_node(step.statuses[m + k])) != target[k];
      std::fprintf(stderr, " %d", wrong);
    }
    std::fprintf(stderr, "\n");
  }
  return first;
}

int to_tolerance(const OuterNewtonRun& run, double tolerance) {
  for (size_t j = 0; j < run.steps.size(); ++j)
    if (run.steps[j].residual <= tolerance) return static_cast<int>(j) + 1;
  return -1;
}

void print_header() {
  std::printf("%-40s %5s | %6s %6s %6s %6s %6s %5s | %9s %4s | %7s %7s %6s | %s\n", "scene", "n_S", "set2", "set6", "sprS2",
              "spring", "total", "toTol", "residual", "conv", "time_s", "bonded", "ratio", "ladder");
}

// The second experiment: the projected Newton method on the eliminated layer's Tresca problems at
// one spring (every row, globally convergent), then the statuses solved exactly without spring and
// polished by Newton steps on the whole sparse system. Each QP iteration is one dense solve.
OuterNewtonRun projected_newton_run(const ContactProblem& problem, const Settings& s, int& qp_iterations) {
  OuterNewtonRun run;
  const CondensedInterface ci(problem);
  const Condensed c = condense(problem, ci, 0.01, true);
  const Eigen::MatrixXd K_s = s.outer.film_spring * adherent_stiffness(problem) * ci.floating_selection(LayerSelection::MinusFace);
  const Condensed reduced = eliminate_layer(c, K_s, Eigen::VectorXd::Zero(c.S.rows()));
  const int m = problem.num_nodes();
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * m), none, lo(2 * m), hi(2 * m), sN = Eigen::VectorXd::Zero(m);
  const double infinity = std::numeric_limits<double>::infinity();
  AndersonAcceleration anderson(5);
  auto record = [&](const Eigen::VectorXd& x) {
    run.steps.push_back({guess_statuses(reduced, x, jump_part(reduced, x, none)), x, 0.0, true});
  };
  qp_iterations = 0;
  for (int update = 0; update < 100; ++update) {
    for (int k = 0; k < m; ++k) {
      lo[2 * k] = reduced.normal[k] ? -infinity : 0.0;
      hi[2 * k] = 0;
      lo[2 * k + 1] = -sN[k];
      hi[2 * k + 1] = sN[k];
    }
    const ProjectedNewtonRun qp = solve_box_qp_projected(reduced.W, reduced.g0, lo, hi, r, 500, record);
    qp_iterations += qp.iterations;
    Eigen::VectorXd image(m);
    for (int k = 0; k < m; ++k) image[k] = reduced.tangential[k] ? reduced.friction[k] * std::max(0.0, -r[2 * k]) : 0.0;
    const double change = (image - sN).norm() / std::max(image.norm(), 1e-300);
    if (s.outer.verbose)
      std::fprintf(stderr, "  projected Newton: update %d, %d iterations, %s, threshold change %.3e\n", update,
                   qp.iterations, qp.optimal ? "optimal" : "not optimal", change);
    if (qp.optimal && change <= 1e-10) break;
    sN = anderson.next(sN, image).cwiseMax(0.0);
  }
  run.spring_steps = static_cast<int>(run.steps.size());
  // The statuses found, solved exactly and polished on the whole sparse system.
  MixedSystem mixed(problem);
  const Condensed rules = law_rules(problem, mixed.row_stiffness());
  std::vector<Active> statuses = guess_statuses(reduced, r, jump_part(reduced, r, none));
  std::set<std::vector<Active>> tried;
  double best = infinity;
  for (int step = 0; step <= s.outer.polish_steps && tried.insert(statuses).second; ++step) {
    const MixedSystem::Answer a = mixed.solve(statuses);
    const double residual = contact_residual(problem, a.u, a.r, a.band_z).value();
    run.steps.push_back({statuses, a.r, residual, false});
    if (residual < best) {
      best = residual;
      run.report.r = a.r;
      run.report.residual = contact_residual(problem, a.u, a.r, a.band_z);
    }
    if (residual <= 1e-10) break;
    Eigen::VectorXd d = problem.jumps(a.u);
    statuses = guess_statuses(rules, a.r, d);
  }
  run.report.converged = best <= 1e-10;
  return run;
}

void run_scene(const std::string& name, const ContactProblem& problem, const InterfaceFields& limit,
               const Settings& s) {
  Seed seed = seed_from_limit(problem, limit, s);
  SolverOptions solver;
  // The reference: the current solver at a tight tolerance (its steps and time at the default
  // tolerance with --ladder).
  std::string ladder = "-";
  if (s.ladder) {
    const auto t0 = std::chrono::steady_clock::now();
    const SolveReport r = solve_fast(problem, solver);
    std::ostringstream o;
    o << r.iterations << " steps " << seconds_since(t0) << " s " << (r.converged ? "conv" : "NOT") << " "
      << r.residual.value();
    ladder = o.str();
  }
  SolverOptions tight;
  tight.tolerance = 1e-12;
  SolveReport reference;
  if (s.reference) reference = solve_fast(problem, tight);
  else reference.r = Eigen::VectorXd::Zero(2 * problem.num_nodes());  // no reference: settle columns meaningless
  if (s.outer.verbose) std::fprintf(stderr, "reference: %s\n", reference.message.c_str());
  if (s.seed == "reference") {  // the reference's own statuses: a control of the Newton's rules
    Condensed rules;
    rules.kappa = problem.kappa();
    for (int k = 0; k < problem.num_nodes(); ++k) {
      rules.normal.push_back(true);
      rules.tangential.push_back(problem.law(k).friction > 0);
      rules.friction.push_back(problem.law(k).friction);
      rules.bilateral.push_back(false);
    }
    seed.statuses = guess_statuses(rules, reference.r, problem.jumps(reference.u));
  }
  const double bonded = bonded_solve_seconds(problem);
  if (s.method == "projected") {
    int qp = 0;
    const auto t0 = std::chrono::steady_clock::now();
    const OuterNewtonRun run = projected_newton_run(problem, s, qp);
    const double t = seconds_since(t0);
    std::printf("%-40s %5d | qp %5d settle(1e-2) %5d settle(1e-6) %5d | exact %3d | %9.2e %4s | %7.3f %7.3f %6.1f\n",
                name.c_str(), problem.num_nodes() / 2, qp, settled_at(problem, run, reference.r, 1e-2, true),
                settled_at(problem, run, reference.r, 1e-6, true), static_cast<int>(run.steps.size()) - run.spring_steps,
                run.report.residual.value(), run.report.converged ? "yes" : "NO", t, bonded, t / bonded);
    std::fflush(stdout);
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  OuterNewtonOptions outer = s.outer;
  if (s.follow) outer.anchor_faces = seed.anchor_faces;
  if (s.hold_film) {
    const int m = static_cast<int>(limit.status.size());
    outer.held.assign(2 * m, false);
    for (int k = 0; k < m; ++k) outer.held[k] = outer.held[m + k] = limit.status[k] == 0;
  }
  const OuterNewtonRun run = solve_outer_newton(problem, seed.statuses, seed.spring_columns, solver, outer);
  const double t = seconds_since(start);
  const int tol = to_tolerance(run, solver.tolerance);
  if (std::getenv("GATE_DETAIL") && run.spring_steps > 0) {
    // The spring phase's last statuses on the load's rows, the reference's on the film's: solved.
    Condensed rules;
    rules.kappa = problem.kappa();
    for (int k = 0; k < problem.num_nodes(); ++k) {
      rules.normal.push_back(true);
      rules.tangential.push_back(problem.law(k).friction > 0);
      rules.friction.push_back(problem.law(k).friction);
      rules.bilateral.push_back(false);
    }
    const std::vector<Active> exact = guess_statuses(rules, reference.r, problem.jumps(reference.u));
    std::vector<Active> hybrid = exact;
    const std::vector<Active>& spring = run.steps[run.spring_steps - 1].statuses;
    double peak = 0;
    for (int k = 0; k < problem.num_nodes(); ++k) peak = std::max(peak, reference.r.segment<2>(2 * k).norm());
    int differ = 0;
    for (int k = 0; k < problem.num_nodes(); ++k)
      if (reference.r.segment<2>(2 * k).norm() >= 1e-6 * peak) {
        hybrid[k] = spring[k];
        if (spring[k] != exact[k]) {
          ++differ;
          std::fprintf(stderr, "  load node %d: spring phase %d, reference %d (r %.3e %.3e)\n", k,
                       static_cast<int>(spring[k]), static_cast<int>(exact[k]), reference.r[2 * k], reference.r[2 * k + 1]);
        }
      }
    MixedSystem mixed(problem);
    const MixedSystem::Answer a = mixed.solve(hybrid);
    std::fprintf(stderr, "hybrid (spring phase on the load rows, %d per-face differences): residual %.3e\n", differ,
                 contact_residual(problem, a.u, a.r, a.band_z).value());
  }
  std::printf("%-40s %5d | %6d %6d %6d %6d %6zu %5s | %9.2e %4s | %7.3f %7.3f %6.1f | %s\n", name.c_str(),
              problem.num_nodes() / 2, settled_at(problem, run, reference.r, 1e-2),
              settled_at(problem, run, reference.r, 1e-6), settled_at(problem, run, reference.r, 1e-2, true),
              run.spring_steps,
              run.steps.size(), tol > 0 ? std::to_string(tol).c_str() : "-", run.report.residual.value(),
              run.report.converged ? "yes" : "NO", t, bonded, t / bonded, ladder.c_str());
  std::fflush(stdout);
}

// The limit answer on the layer model (issue 40's start): each adherent node as the limit answer
// has it (same body, same node), each band column interpolated between the adherent nodes facing
// its two ends; the thresholds f·max(0, −σ_N ℓ) of the limit's S node k on both faces' node k.
struct LayerStart {
  Eigen::VectorXd y, thresholds, r;
};
LayerStart layer_start(const Model& limit_model, const SceneRecord& limit, const Model& layer_model,
                       const ContactProblem& layer) {
  const LinearSystem& system = layer.system();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(layer_model.num_dofs());
  for (size_t b = 0; b < layer_model.bodies.size(); ++b)
    for (size_t a = 0; a < limit_model.bodies.size(); ++a)
      if (limit_model.bodies[a].name == layer_model.bodies[b].name) {
        const int from = limit_model.dof_offset(static_cast<int>(a)) / 2, to = layer_model.dof_offset(static_cast<int>(b));
        for (int i = 0; i < layer_model.bodies[b].mesh.num_nodes(); ++i)
          for (int c = 0; c < 2; ++c) u[to + 2 * i + c] = limit.u(from + i, c);
      }
  const FloatingBand& band = system.floating_bands().at(0);
  const int band_offset = layer_model.dof_offset(band.body);
  const BandLayout& L = band.layout;
  std::vector<int> partner(L.columns * (L.across + 1), -1);  // band node -> adherent global dof
  for (int k = 0; k < layer.num_nodes(); ++k) {
    const InterfaceNode& n = layer.node(k);
    for (auto [mine, other] : {std::pair{n.plus_dof_x, n.minus_dof_x}, std::pair{n.minus_dof_x, n.plus_dof_x}})
      if (mine >= band_offset && mine < band_offset + 2 * L.columns * (L.across + 1)) partner[(mine - band_offset) / 2] = other;
  }
  for (int i = 0; i < L.columns; ++i) {
    const int foot = partner[L.node(i, 0)], top = partner[L.node(i, L.across)];
    for (int j = 0; j <= L.across; ++j)
      for (int c = 0; c < 2; ++c) {
        const double uf = foot >= 0 ? u[foot + c] : 0.0, ut = top >= 0 ? u[top + c] : uf;
        u[band_offset + 2 * L.node(i, j) + c] = uf + (ut - uf) * j / L.across;
      }
  }
  Eigen::VectorXd u_free(system.num_free());
  for (int g = 0; g < layer_model.num_dofs(); ++g)
    if (system.free_index(g) >= 0) u_free[system.free_index(g)] = u[g];
  LayerStart out;
  out.y = MixedSystem(layer).unknowns(u_free);
  const InterfaceFields& S = limit.interfaces.at(0);
  const int m = static_cast<int>(S.sigma_N.size());
  out.thresholds = Eigen::VectorXd::Zero(layer.num_nodes());
  out.r = Eigen::VectorXd::Zero(2 * layer.num_nodes());
  for (int k = 0; k < layer.num_nodes(); ++k) {
    out.thresholds[k] = layer.law(k).friction * std::max(0.0, -S.sigma_N[k % m] * layer.node(k).length);
    out.r[2 * k] = S.sigma_N[k % m] * layer.node(k).length;
    out.r[2 * k + 1] = S.sigma_T[k % m] * layer.node(k).length;
  }
  return out;
}

// Issue 40's gate: the layer descent (core/solvers/tnnmg.h) from the limit answer (run B) or, with
// --tresca-reference, on the Tresca problem of the reference answer's thresholds (run A).
void tnnmg_scene(const std::string& name, const ContactProblem& problem, const Model& layer_model,
                 const Model& limit_model, const SceneRecord& limit, const Settings& s) {
  SolverOptions solver;
  TnnmgOptions opt;
  opt.verbose = s.outer.verbose;
  opt.smoothing_sweeps = s.smoothing_sweeps;
  opt.closing_rounds = s.closing_rounds;
  opt.releasing = s.releasing;
  if (s.start == "limit") {
    const LayerStart st = layer_start(limit_model, limit, layer_model, problem);
    opt.start_y = st.y;
    opt.start_thresholds = st.thresholds;
  }
  if (s.tresca_reference) {
    SolverOptions tight;
    tight.tolerance = 1e-12;
    const SolveReport reference = solve_fast(problem, tight);
    Eigen::VectorXd t = Eigen::VectorXd::Zero(problem.num_nodes());
    for (int k = 0; k < problem.num_nodes(); ++k)
      t[k] = problem.law(k).friction * std::max(0.0, -reference.r[2 * k]);
    opt.tresca_thresholds = t;
    if (s.start == "reference") {  // a control: the reference answer itself
      opt.start_y = MixedSystem(problem).unknowns(reference.u);
      opt.start_thresholds = t;
    }
    if (s.outer.verbose) {  // the reference's rows, as the descent names them
      const Eigen::VectorXd d = problem.jumps(reference.u);
      for (int row = 0; row < 2 * problem.num_nodes(); ++row) {
        const double r = reference.r[row], scale = reference.r.cwiseAbs().maxCoeff();
        int code = 0;
        if (row % 2 == 0) code = std::abs(r) > 1e-9 * scale ? 1 : 0;
        else if (std::abs(r) > 1e-9 * scale) code = std::abs(std::abs(r) - t[row / 2]) <= 1e-6 * t[row / 2] ? (r < 0 ? 2 : 3) : 1;
        opt.reference_rows.push_back(code);
      }
    }
  }
  const double bonded = bonded_solve_seconds(problem);
  if (s.method == "ipm" && !opt.reference_rows.empty()) {
    const int m = problem.num_nodes();
    auto code = [](int v) { return "o|+-"[v]; };
    std::string sp, sm;
    for (int k = 0; k < m / 2; ++k) {
      sp += code(opt.reference_rows[2 * k]), sp += code(opt.reference_rows[2 * k + 1]);
      sm += code(opt.reference_rows[m + 2 * k]), sm += code(opt.reference_rows[m + 2 * k + 1]);
    }
    std::fprintf(stderr, "reference S+ %s\nreference S- %s\n", sp.c_str(), sm.c_str());
  }
  if (s.method == "ipm") {
    InteriorPointOptions ipm;
    ipm.verbose = opt.verbose;
    ipm.tresca_thresholds = opt.tresca_thresholds;
    ipm.hybrid_margin = s.hybrid;
    ipm.newton_crossover = s.newton_crossover;
    if (s.start == "limit" || s.start == "reference") {
      ipm.start_y = opt.start_y;
      if (s.start == "limit") ipm.start_r = layer_start(limit_model, limit, layer_model, problem).r;
    }
    const auto t0 = std::chrono::steady_clock::now();
    if (s.handover > 0) ipm.stop_at_iterate_residual = s.handover;
    InteriorPointRun run = solve_layer_interior_point(problem, solver, ipm);
    if (s.handover > 0 && !run.report.converged) {  // the descent from the interior iterate
      TnnmgOptions t;
      t.verbose = opt.verbose;
      t.closing_rounds = s.closing_rounds;
      t.releasing = s.releasing;
      t.start_y = run.last_y;
      t.start_thresholds = Eigen::VectorXd::Zero(problem.num_nodes());
      for (int k = 0; k < problem.num_nodes(); ++k)
        t.start_thresholds[k] = problem.law(k).friction * std::max(0.0, -run.last_r[2 * k]);
      t.max_factorisations = 40 - run.factorisations;
      const TnnmgRun tr = solve_tnnmg(problem, solver, t);
      run.factorisations += tr.factorisations;
      if (tr.report.residual.value() < run.report.residual.value()) run.report = tr.report;
      std::fprintf(stderr, "handover at %.2e: tnnmg %d LUs, residual %.2e\n", run.last_residual, tr.factorisations,
                   tr.report.residual.value());
    }
    const double t = seconds_since(t0);
    std::printf("%-40s %5d | %4d LUs %3d ipm %3d crossover | %9.2e %4s | %7.3f %7.3f %6.1f\n", name.c_str(),
                problem.num_nodes() / 2, run.factorisations, run.iterations, run.crossovers, run.report.residual.value(),
                run.report.converged ? "yes" : "NO", t, bonded, t / bonded);
    std::fflush(stdout);
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const TnnmgRun run = solve_tnnmg(problem, solver, opt);
  const double t = seconds_since(t0);
  int coulomb = 0, clipped = 0, shifted = 0;
  double smooth = 0;
  for (const TnnmgStep& st : run.steps) coulomb += st.coulomb, clipped += st.clipped, shifted += st.shifted, smooth += st.smoothing_s;
  std::printf("%-40s %5d | %4d LUs %3zu steps (%d coulomb, %d clipped, %d shifted) | %9.2e %4s | %7.3f (smooth %.3f) %7.3f %6.1f\n",
              name.c_str(), problem.num_nodes() / 2, run.factorisations, run.steps.size(), coulomb, clipped, shifted,
              run.report.residual.value(), run.report.converged ? "yes" : "NO", t, smooth, bonded, t / bonded);
  std::fflush(stdout);
}

void dovetail_scene(const dovetail::MeshOptions& mesh, double friction, const dovetail::Exponents& e,
                    const std::string& law_case, double eps, const std::string& name, const Settings& s) {
  DovetailLimitBulk bulk(mesh, friction);
  const DovetailScene limit = solve_dovetail_limit(bulk, e, law_case, SolverKind::Fast, SolverOptions{});
  const dovetail::LayerMeshes meshes = dovetail::make_layer_meshes(bulk.meshes(), eps, mesh.layer_elements);
  const Model model = dovetail::make_layer_model(meshes, e);
  const LinearSystem system(model);
  const ContactProblem problem(system, dovetail::make_layer_interfaces(model, friction));
  if (s.method == "tnnmg" || s.method == "ipm") return tnnmg_scene(name, problem, model, bulk.model(), limit.record, s);
  run_scene(name, problem, limit.record.interfaces.at(0), s);
}

void bar_scene(const GeneratedScene& g, const std::string& name, const Settings& s) {
  bar::MeshOptions mesh;
  mesh.nx = mesh.ny = g.bar_nx;
  mesh.load_scale = g.load_scale;
  const Table3Row row = load_table3_paper().at(g.bar_row - 1);
  BarBulk bulk(mesh);
  const BarScene limit = solve_bar(bulk, table3_law(row), "row", SolverKind::Fast, SolverOptions{});
  bar::LayerOptions layer;
  layer.eps = g.eps;
  layer.lambda_eps = g.eps * row.lambda_bar;
  layer.mu_eps = g.eps * row.mu_bar;
  layer.layer_elements = g.layer_elements;
  const Model model = bar::make_layer_model(mesh, layer);
  const LinearSystem system(model);
  const ContactProblem problem(system, bar::make_layer_interfaces(model));
  run_scene(name, problem, limit.record.interfaces.at(0), s);
}

// Limit mode of a scene file, from the bonded solve: every node stuck, then Newton on the whole
// sparse system (no film: the Newton alone).
void scene_limit(const std::string& file, double interface_h, const Settings& s) {
  SceneSpec spec = read_scene_spec(file);
  if (interface_h > 0) {
    const double ratio = *spec.h_far / *spec.h_interface;
    spec.h_interface = interface_h;
    spec.h_far = interface_h * ratio;
  }
  SceneFileBulk bulk(spec);
  const ContactProblem problem(bulk.system(), bulk.limit_interfaces(0));
  const std::vector<Active> seed(problem.num_nodes(), Active::Stick);
  SolverOptions solver;
  const double bonded = bonded_solve_seconds(problem);
  const auto start = std::chrono::steady_clock::now();
  const OuterNewtonRun run = solve_outer_newton(problem, seed, {}, solver, s.outer);
  const double t = seconds_since(start);
  std::printf("%-40s %5d | %6d steps | %9.2e %4s | %7.3f %7.3f %6.1f\n", file.c_str(), problem.num_nodes(),
              static_cast<int>(run.steps.size()), run.report.residual.value(), run.report.converged ? "yes" : "NO", t,
              bonded, t / bonded);
  std::fflush(stdout);
}

int main(int argc, char** argv) {
  use_one_blas_thread();
  keep_factor_memory();
  Settings s;
  std::vector<std::string> cases, eps, hs, seeds, scenes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--dovetail") cases = split(value());
    else if (a == "--eps") eps = split(value());
    else if (a == "--h") hs = split(value());
    else if (a == "--seeds") seeds = split(value());
    else if (a == "--scene-limit") scenes = split(value());
    else if (a == "--spring") s.outer.film_spring = std::stod(value());
    else if (a == "--stages") for (const std::string& x : split(value())) s.outer.spring_stages.push_back(std::stod(x));
    else if (a == "--freeze") s.outer.freeze_below = std::stod(value());
    else if (a == "--freeze-measure") s.outer.freeze_measure = std::stoi(value());
    else if (a == "--freeze-from") s.outer.freeze_from_step = std::stoi(value());
    else if (a == "--max-steps") s.outer.max_steps = std::stoi(value());
    else if (a == "--slide-on") s.slide_on = value();
    else if (a == "--spring-on") s.spring_on = value();
    else if (a == "--ladder") s.ladder = true;
    else if (a == "--no-reference") s.reference = false;
    else if (a == "--method") s.method = value();
    else if (a == "--hold-film") s.hold_film = true;
    else if (a == "--follow") s.follow = true;
    else if (a == "--film") s.outer.film_inner = true;
    else if (a == "--band") s.outer.film_inner = s.outer.band_inner = true;
    else if (a == "--band-spring") s.outer.band_spring = std::stod(value());
    else if (a == "--film-scale") s.outer.film_scale = std::stod(value());
    else if (a == "--seed") s.seed = value();
    else if (a == "--start") s.start = value();
    else if (a == "--tresca-reference") s.tresca_reference = true;
    else if (a == "--sweeps") s.smoothing_sweeps = std::stoi(value());
    else if (a == "--closing") s.closing_rounds = std::stoi(value());
    else if (a == "--releasing") s.releasing = true;
    else if (a == "--handover") s.handover = std::stod(value());
    else if (a == "--hybrid") s.hybrid = std::stod(value());
    else if (a == "--no-newton-crossover") s.newton_crossover = false;
    else if (a == "--verbose") s.outer.verbose = true;
    else throw std::invalid_argument("unknown argument " + a);
  }
  for (const std::string& scene : scenes)
    for (const std::string& h : hs.empty() ? std::vector<std::string>{"0"} : hs) scene_limit(scene, std::stod(h), s);
  if (!scenes.empty()) return 0;
  print_header();
  for (const std::string& h : hs)
    for (const std::string& c : cases)
      for (const std::string& e : eps) {
        dovetail::MeshOptions mesh;
        mesh.h_interface = std::stod(h);
        dovetail_scene(mesh, dovetail::friction, dovetail::exponents_of(c[0]), c, std::stod(e),
                       "dovetail " + c + " eps " + e + " h " + h, s);
      }
  for (const std::string& seed : seeds) {
    const GeneratedScene g = generate_scene(std::stoi(seed));
    const std::string name = "seed " + seed + " " + g.describe().substr(g.describe().find(':') + 1);
    if (g.kind == GeneratedScene::Kind::Dovetail) {
      dovetail::MeshOptions mesh;
      mesh.h_interface = g.h_interface;
      mesh.layer_elements = g.layer_elements;
      const std::string law_case = g.law_case ? std::string(1, g.law_case) : "";
      dovetail_scene(mesh, g.friction, g.exponents, law_case, g.eps, name.substr(0, 40), s);
    } else if (g.kind == GeneratedScene::Kind::Bar) {
      bar_scene(g, name.substr(0, 40), s);
    } else {
      std::printf("%s: a scene file (not in the gate)\n", name.c_str());
    }
  }
  return 0;
}

}  // namespace
}  // namespace thinlayer

int main(int argc, char** argv) {
  try {
    return thinlayer::main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "thinlayer_two_scale_gate: %s\n", e.what());
    return 2;
  }
}
