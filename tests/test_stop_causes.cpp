// Every solve that does not converge names its cause (SolveReport::stop_cause), and no result
// with a NaN or Inf is ever written (issue 5, the stress tests of S5).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include <unistd.h>

#include "cases/bar/bar.h"
#include "core/io/scene_record.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"
#include "cases/dovetail/dovetail_scenes.h"

namespace thinlayer {
namespace {

const InterfaceLaw compliant = InterfaceLaw::make(450, 540, 1.0);  // daN/mm³

bar::MeshOptions small_bar(double load_scale = 1) { return {.nx = 8, .ny = 8, .load_scale = load_scale}; }

TEST(StopCause, ConvergedSolvesSayConverged) {
  const Model model = bar::make_model(small_bar());
  const LinearSystem system(model);
  const ContactProblem problem(system, {bar::make_interface(model, compliant)});
  for (const SolveReport& r : {solve_fast(problem), solve_relaxation(problem)}) {
    SCOPED_TRACE(r.solver);
    EXPECT_TRUE(r.converged) << r.message;
    EXPECT_EQ(r.stop_cause, StopCause::Converged);
  }
}

TEST(StopCause, ACappedSolveSaysIterationCapNotConverged) {
  const Model model = bar::make_model(small_bar());
  const LinearSystem system(model);
  const ContactProblem problem(system, {bar::make_interface(model, compliant)});
  SolverOptions capped;
  capped.max_iterations = 1;
  const SolveReport fast = solve_fast(problem, capped);
  capped.max_iterations = 5;
  const SolveReport relaxation = solve_relaxation(problem, capped);
  for (const SolveReport& r : {fast, relaxation}) {
    SCOPED_TRACE(r.solver);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.stop_cause, StopCause::IterationCap);
    EXPECT_NE(r.message.find("iteration cap"), std::string::npos) << r.message;
  }
  EXPECT_GT(fast.condition_estimate, 1.0);  // estimated, and a condition number is >= 1
}

// SPEC §1.5: a solve may stop above the tolerance only at its round-off floor, and the residual it
// is judged by is the answer's own (evaluated in extended precision). The floor is what rounding
// the answer to double moves the residual by: rounding a converged answer to single precision
// (2^29 times coarser) moves it by at most that many floors, and a solve stopped early (a stall,
// not precision) sits far above its floor and is not called "round-off floor".
TEST(RoundOffFloor, BoundsWhatRoundingTheAnswerMovesTheResidualBy) {
  bar::LayerOptions layer;
  layer.eps = 1e-3;
  layer.lambda_eps = 1e-3 * 4.5e8;  // Table 3's row 1: a layer far stiffer than the bar
  layer.mu_eps = 1e-3 * 5.4e8;
  const Model model = bar::make_layer_model(small_bar(), layer);
  const LinearSystem system(model);
  const ContactProblem problem(system, bar::make_layer_interfaces(model));
  const CondensedInterface condensed(problem);
  const SolveReport answer = solve_fast(problem, condensed, {});
  ASSERT_TRUE(answer.converged) << answer.message;
  const double floor = answer.residual.floor();
  ASSERT_GT(floor, 0);
  // The answer rounded to float, each DOF and force: its residual grows, but within the floor
  // scaled by the ratio of the two precisions' unit round-offs (the floor is a first-order bound,
  // a sum of magnitudes: measured 1.4e-7 against the bound 2.0e-4 here, the answer at 9.9e-15).
  const auto to_float = [](const Eigen::VectorXd& v) { return v.cast<float>().cast<double>().eval(); };
  const Eigen::VectorXd w = to_float(answer.w);
  const Residual rounded = contact_residual(problem, condensed.displacement(problem, to_float(answer.r), w),
                                            to_float(answer.r), condensed.band_coordinates(w));
  const double precision_ratio = std::ldexp(1.0, 53 - 24);
  EXPECT_GT(rounded.value(), 1e3 * answer.residual.value());  // rounding did move it
  EXPECT_LT(rounded.value(), precision_ratio * floor + answer.residual.value());
}

TEST(RoundOffFloor, ASolveStoppedEarlyIsAStallNotTheFloor) {
  bar::LayerOptions layer;
  layer.eps = 1e-3;
  layer.lambda_eps = 1e-3 * 4.5e2;  // Table 3's row 3
  layer.mu_eps = 1e-3 * 5.4e2;
  const Model model = bar::make_layer_model(small_bar(), layer);
  const LinearSystem system(model);
  const ContactProblem problem(system, bar::make_layer_interfaces(model));
  SolverOptions capped;
  capped.max_iterations = 3;
  const SolveReport r = solve_fast(problem, capped);
  ASSERT_FALSE(r.converged);
  EXPECT_GT(r.residual.value(), 1e3 * r.residual.floor());
  EXPECT_NE(r.stop_cause, StopCause::RoundOffFloor) << r.message;
  EXPECT_EQ(r.stop_cause, StopCause::IterationCap) << r.message;
}

TEST(StopCause, AFloatingLayerWithEveryContactOpenIsSingular) {
  // Reversed loads lift the bar: the layer under AD touches neither the bar nor the ground.
  bar::LayerOptions layer;
  layer.eps = 1e-3;
  layer.lambda_eps = layer.eps * 450;
  layer.mu_eps = layer.eps * 540;
  const Model model = bar::make_layer_model(small_bar(-1), layer);
  const LinearSystem system(model);
  const ContactProblem problem(system, bar::make_layer_interfaces(model));
  const SolveReport r = solve_fast(problem);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.stop_cause, StopCause::Singular);
  EXPECT_NE(r.message.find("held by none of its contacts"), std::string::npos) << r.message;
  // The residual alone would have passed: the answer exists, it is not unique.
  EXPECT_LE(r.residual.value(), 1e-10);
  EXPECT_TRUE(r.u.allFinite());

  // With the loads the right way round the same layer is held, and the solve converges.
  const Model held_model = bar::make_layer_model(small_bar(1), layer);
  const LinearSystem held_system(held_model);
  const ContactProblem held(held_system, bar::make_layer_interfaces(held_model));
  const SolveReport h = solve_fast(held);
  EXPECT_TRUE(h.converged) << h.message;
  EXPECT_EQ(h.stop_cause, StopCause::Converged);
}

// A capped layer solve stops within its cap and says so (SolverOptions::max_iterations bounds the
// floating-layer solver's linear solves across its stages), reporting a finite iterate; the same
// scene uncapped converges. Case (e) at ε = 1e-4 on a coarse mesh: its active set cycles on the
// eliminated layer, so the caps cut it inside different stages. With both quadratures of the
// layer: the selective one this test was written for, and the full one case (e) takes since
// issue 14 (cases/layer_quadrature.h).
TEST(StopCause, ACappedLayerSolveStopsWithinItsCapAndSaysSo) {
  dovetail::MeshOptions mesh;
  mesh.h_interface = 0.05;  // a coarse mesh: a fraction of a second per solve
  mesh.h_far = 0.2;
  const DovetailLimitBulk bulk(mesh);
  for (LayerQuadrature quadrature : {LayerQuadrature::Selective, LayerQuadrature::ByExponents})
  for (int cap : {50, 100, 200}) {
    SolverOptions options;
    options.max_iterations = cap;
    const DovetailScene s = solve_dovetail_layer(bulk, dovetail::exponents_of('e'), 1e-4, "e", SolverKind::Fast,
                                                 options, default_status_tolerance, quadrature);
    SCOPED_TRACE(std::string(quadrature == LayerQuadrature::Selective ? "selective" : "full") + ", cap " +
                 std::to_string(cap) + ": " + s.report.message);
    EXPECT_LE(s.report.iterations, cap);
    if (!s.report.converged) {
      EXPECT_EQ(s.report.stop_cause, StopCause::IterationCap);
    }
    EXPECT_TRUE(std::isfinite(s.report.residual.value()));
  }
  const DovetailScene free = solve_dovetail_layer(bulk, dovetail::exponents_of('e'), 1e-4, "e", SolverKind::Fast, {});
  EXPECT_TRUE(free.report.converged) << free.report.message;
}

TEST(StopCause, ASceneWithNaNIsNeverWritten) {
  const Model model = bar::make_model(small_bar());
  const LinearSystem system(model);
  const ContactProblem problem(system, {bar::make_interface(model, compliant)});
  SolveReport report = solve_fast(problem);
  report.u[3] = std::numeric_limits<double>::quiet_NaN();
  const SceneRecord record = record_scene("poisoned", model, problem, report, 1e-6);
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("thinlayer-nan-" + std::to_string(::getpid()) + ".h5");
  {
    H5Writer out(file.string());
    try {
      write_scene(out, record);
      FAIL() << "a NaN was written";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
    }
  }  // not committed: nothing is left behind
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(StopCause, EveryCauseHasAName) {
  for (StopCause c : {StopCause::Converged, StopCause::IterationCap, StopCause::Singular, StopCause::LossOfAccuracy,
                      StopCause::NonFinite, StopCause::RoundOffFloor, StopCause::LayerAdrift})
    EXPECT_STRNE(to_string(c), "unknown");
}

}  // namespace
}  // namespace thinlayer
