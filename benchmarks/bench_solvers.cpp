// Google Benchmark: the solvers of S5 on the bar's mesh levels (32 ... 512 contact nodes), the
// dovetail's limit mode at three levels, and its layer mode at ε = 1e-2 and 1e-4.
//
//   build/thinlayer_bench --benchmark_format=json --benchmark_out=bench.json
//   build/thinlayer_bench --benchmark_filter='Bar.*/64$'
//
// Every benchmark reports, beside its time, counters: `unknowns` (free DOFs), `contact_nodes`,
// `error` (|u - u_ref| / |u_ref| against the fast solver at residual 1e-12 on the same scene)
// and `residual` (SPEC §1.5). `linear` is one CHOLMOD factorisation + solve of the same mesh
// without contact: the denominator of the ratios that `thinlayer study timing` reports.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "cases/dovetail/dovetail.h"
#include "core/io/reference_tables.h"
#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"
#include "core/solvers/siconos_peers.h"
#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail_scenes.h"

namespace thinlayer {
namespace {

// One scene per level, built once and kept for every benchmark that needs it.
template <class Bulk>
struct Level {
  std::unique_ptr<Bulk> bulk;
  std::unique_ptr<ContactProblem> problem;
  Eigen::VectorXd reference;  // u of the fast solver at residual 1e-12
};

template <class Bulk>
Level<Bulk> make_level(std::unique_ptr<Bulk> bulk, Interface interface) {
  Level<Bulk> level;
  level.bulk = std::move(bulk);
  level.problem = std::make_unique<ContactProblem>(level.bulk->system(), std::vector<Interface>{std::move(interface)});
  SolverOptions tight;
  tight.tolerance = 1e-12;
  level.reference = solve_fast(*level.problem, level.bulk->condensed(), tight).u;
  return level;
}

using BarLevel = Level<BarBulk>;
using DovetailLevel = Level<DovetailLimitBulk>;

// The bar on n x n elements, Table 3's row 1.
BarLevel& bar_level(int n) {
  static std::map<int, BarLevel> levels;
  if (auto it = levels.find(n); it != levels.end()) return it->second;
  bar::MeshOptions mesh;
  mesh.nx = mesh.ny = n;
  auto bulk = std::make_unique<BarBulk>(mesh);
  Interface interface = bar::make_interface(bulk->model(), table3_law(load_table3_paper().at(0)));
  return levels.emplace(n, make_level(std::move(bulk), std::move(interface))).first->second;
}

void report(benchmark::State& state, const ContactProblem& problem, const SolveReport& r, const Eigen::VectorXd& ref) {
  state.counters["unknowns"] = problem.system().num_free();
  state.counters["contact_nodes"] = problem.num_nodes();
  state.counters["residual"] = r.residual.value();
  state.counters["error"] = (r.u - ref).norm() / ref.norm();
  state.counters["iterations"] = r.iterations;
  state.counters["converged"] = r.converged ? 1 : 0;
}

void BarLinear(benchmark::State& state) {
  BarLevel& level = bar_level(static_cast<int>(state.range(0)));
  const LinearSystem& system = level.bulk->system();
  for (auto _ : state) {
    const SparseCholesky factor(system.K());
    benchmark::DoNotOptimize(factor.solve(system.F()));
  }
  state.counters["unknowns"] = system.num_free();
}

void BarCondensation(benchmark::State& state) {
  BarLevel& level = bar_level(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(CondensedInterface(*level.problem).W().data());
  state.counters["unknowns"] = level.bulk->system().num_free();
}

// The fast solver as a user runs it once: condensation + active set.
void BarFastTotal(benchmark::State& state) {
  BarLevel& level = bar_level(static_cast<int>(state.range(0)));
  SolveReport r;
  for (auto _ : state) r = solve_fast(*level.problem);
  report(state, *level.problem, r, level.reference);
}

// Solve phases on the shared condensation (the cost of each further scene on the same bulk).
void BarFastSolve(benchmark::State& state) {
  BarLevel& level = bar_level(static_cast<int>(state.range(0)));
  SolveReport r;
  for (auto _ : state) r = solve_fast(*level.problem, level.bulk->condensed());
  report(state, *level.problem, r, level.reference);
}

template <PeerSolver peer>
void BarSiconos(benchmark::State& state) {
  BarLevel& level = bar_level(static_cast<int>(state.range(0)));
  SolveReport r;
  for (auto _ : state) r = solve_siconos(*level.problem, level.bulk->condensed(), peer);
  report(state, *level.problem, r, level.reference);
}

void BarRelaxation(benchmark::State& state) {
  BarLevel& level = bar_level(static_cast<int>(state.range(0)));
  SolverOptions o;
  o.max_iterations = 200000;
  SolveReport r;
  for (auto _ : state) r = solve_relaxation(*level.problem, o);
  report(state, *level.problem, r, level.reference);
}

// The dovetail's limit mode, case d, at element sizes 0.05, 0.025 and 0.0125 along S (levels
// 0, 1, 2).
DovetailLevel& dovetail_level(int level) {
  static std::map<int, DovetailLevel> levels;
  if (auto it = levels.find(level); it != levels.end()) return it->second;
  dovetail::MeshOptions mesh;
  mesh.h_interface = 0.05 / (1 << level);
  mesh.h_far = 4 * mesh.h_interface;  // the default ratio (0.1 / 0.025)
  auto bulk = std::make_unique<DovetailLimitBulk>(mesh);
  Interface interface =
      dovetail::make_limit_interface(bulk->model(), dovetail::limit_law(dovetail::exponents_of('d')));
  return levels.emplace(level, make_level(std::move(bulk), std::move(interface))).first->second;
}

// The fast solver as a user runs it once: condensation + active set.
void DovetailLimitFastTotal(benchmark::State& state) {
  DovetailLevel& level = dovetail_level(static_cast<int>(state.range(0)));
  SolveReport r;
  for (auto _ : state) r = solve_fast(*level.problem);
  report(state, *level.problem, r, level.reference);
  state.counters["h_interface"] = level.bulk->options().h_interface;
}

// The two parts of DovetailLimitFastTotal: the condensation (factorisations, W, g₀) ...
void DovetailLimitCondensation(benchmark::State& state) {
  DovetailLevel& level = dovetail_level(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(CondensedInterface(*level.problem).W().data());
  state.counters["unknowns"] = level.bulk->system().num_free();
  state.counters["h_interface"] = level.bulk->options().h_interface;
}

// ... and the active set on the shared condensation (with the final displacement solve).
void DovetailLimitFastSolve(benchmark::State& state) {
  DovetailLevel& level = dovetail_level(static_cast<int>(state.range(0)));
  SolveReport r;
  for (auto _ : state) r = solve_fast(*level.problem, level.bulk->condensed());
  report(state, *level.problem, r, level.reference);
  state.counters["h_interface"] = level.bulk->options().h_interface;
}

void DovetailLimitLinear(benchmark::State& state) {
  const DovetailLevel& level = dovetail_level(static_cast<int>(state.range(0)));
  const LinearSystem& system = level.bulk->system();
  // The two bodies bonded along S would be one solve; without contact they are two
  // independent clamped/pulled bodies, which is what one factorisation + solve costs here.
  for (auto _ : state) {
    const SparseCholesky factor(system.K());
    benchmark::DoNotOptimize(factor.solve(system.F()));
  }
  state.counters["unknowns"] = system.num_free();
  state.counters["h_interface"] = level.bulk->options().h_interface;
}

// The dovetail's layer mode, case d, at ε = 1e-2 (range 2) and 1e-4 (range 4): the whole solve
// (layer meshes, condensation, proximal active set), as `thinlayer solve` runs it.
void DovetailLayer(benchmark::State& state) {
  const double eps = std::pow(10.0, -static_cast<double>(state.range(0)));
  static DovetailLimitBulk bulk;
  DovetailScene s;
  for (auto _ : state)
    s = solve_dovetail_layer(bulk, dovetail::exponents_of('d'), eps, "d", SolverKind::Fast, SolverOptions{});
  state.counters["residual"] = s.report.residual.value();
  state.counters["iterations"] = s.report.iterations;
  state.counters["converged"] = s.report.converged ? 1 : 0;
  state.counters["eps"] = eps;
}

const std::vector<int64_t> bar_levels = {32, 64, 128, 256, 512};

BENCHMARK(BarLinear)->ArgsProduct({bar_levels})->Unit(benchmark::kMillisecond);
BENCHMARK(BarCondensation)->ArgsProduct({bar_levels})->Unit(benchmark::kMillisecond);
BENCHMARK(BarFastTotal)->ArgsProduct({bar_levels})->Unit(benchmark::kMillisecond);
BENCHMARK(BarFastSolve)->ArgsProduct({bar_levels})->Unit(benchmark::kMillisecond);
BENCHMARK(BarSiconos<PeerSolver::NSGS>)->Name("BarSiconosNSGS")->ArgsProduct({{32, 64, 128}})->Unit(benchmark::kMillisecond);
BENCHMARK(BarSiconos<PeerSolver::Lemke>)->Name("BarSiconosLemke")->ArgsProduct({{32, 64, 128}})->Unit(benchmark::kMillisecond);
BENCHMARK(BarRelaxation)->ArgsProduct({{32, 64}})->Unit(benchmark::kMillisecond);
BENCHMARK(DovetailLimitLinear)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(DovetailLimitFastTotal)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(DovetailLimitCondensation)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(DovetailLimitFastSolve)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(DovetailLayer)->Arg(2)->Arg(4)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace thinlayer

BENCHMARK_MAIN();
