// The Siconos peer solvers (core/solvers/siconos_peers.h) against solve_fast on the bar with
// 32 contact nodes: the same forces, the same statuses, and what each peer's own stopping
// criterion is worth in the SPEC residual.
#include <gtest/gtest.h>

#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "cases/bar/bar.h"
#include "core/io/reference_tables.h"
#include "core/io/scene_record.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/siconos_peers.h"
#include "cases/bar/bar_scenes.h"

namespace thinlayer {
namespace {

const double inf = std::numeric_limits<double>::infinity();

double relative_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

InterfaceLaw table3_row1(double friction = bar::friction) {
  const Table3Row row = load_table3_paper().at(0);
  return InterfaceLaw::make(row.lambda_bar, row.mu_bar, friction);
}

struct SiconosPeers : ::testing::Test {
  static void SetUpTestSuite() { bulk = std::make_unique<BarBulk>(bar::MeshOptions{}); }  // 32 × 32 Q1
  static void TearDownTestSuite() { bulk.reset(); }
  static std::unique_ptr<BarBulk> bulk;

  static ContactProblem problem(const InterfaceLaw& law) {
    return ContactProblem(bulk->system(), {bar::make_interface(bulk->model(), law)});
  }
  static std::vector<int> statuses(const ContactProblem& p, const SolveReport& s) {
    return interface_fields(p, s, default_status_tolerance).at(0).status;
  }
  static SolveReport reference(const ContactProblem& p) {
    SolverOptions options;
    options.tolerance = 1e-12;
    return solve_fast(p, bulk->condensed(), options);
  }
};
std::unique_ptr<BarBulk> SiconosPeers::bulk;

struct NamedLaw {
  std::string name;
  InterfaceLaw law;
};

// Table 3 row 1, the same without friction, the rigid law (Signorini-Coulomb), and case (c)
// (no tangential interaction: an infinite tangential compliance, mu = 0 for the peer).
std::vector<NamedLaw> laws() {
  return {{"table 3 row 1", table3_row1()},
          {"table 3 row 1, f = 0", table3_row1(0.0)},
          {"rigid (Signorini-Coulomb)", InterfaceLaw::make(inf, inf, bar::friction)},
          {"case (c)", InterfaceLaw::make(450, 0, bar::friction)}};
}

// The peer's answer is the fast solver's: r and the jumps to 1e-6, every node's status and the
// counts of each status equal.
void expect_the_same_answer(const ContactProblem& p, const SolveReport& peer, const SolveReport& fast) {
  EXPECT_LT(relative_distance(peer.r, fast.r), 1e-6);
  EXPECT_LT(relative_distance(p.jumps(peer.u), p.jumps(fast.u)), 1e-6);
  EXPECT_EQ(SiconosPeers::statuses(p, peer), SiconosPeers::statuses(p, fast));
  EXPECT_EQ(interface_fields(p, peer, default_status_tolerance).at(0).counts(),
            interface_fields(p, fast, default_status_tolerance).at(0).counts());
}

TEST_F(SiconosPeers, MeshHas32ContactNodes) { EXPECT_EQ(problem(table3_row1()).num_nodes(), 32); }

// For each law: the peer's answer (handed our tolerance, 1e-10) is the fast solver's at 1e-12
// (expect_the_same_answer); then `check` judges the peer's own report.
template <class Check>
void against_the_fast_solver(PeerSolver solver, Check check) {
  for (const NamedLaw& l : laws()) {
    SCOPED_TRACE(l.name);
    const ContactProblem p = SiconosPeers::problem(l.law);
    const SolveReport fast = SiconosPeers::reference(p);
    ASSERT_TRUE(fast.converged) << fast.message;
    const SolveReport peer = solve_siconos(p, SiconosPeers::bulk->condensed(), solver);
    expect_the_same_answer(p, peer, fast);
    check(peer);
  }
}

TEST_F(SiconosPeers, LemkeReproducesTheFastSolver) {
  against_the_fast_solver(PeerSolver::Lemke, [](const SolveReport& lemke) {
    EXPECT_EQ(lemke.solver, "siconos-lemke");
    EXPECT_TRUE(lemke.converged) << lemke.message;  // a direct method: our residual ≤ 1e-10
    EXPECT_LE(lemke.residual.value(), 1e-10) << lemke.message;
    EXPECT_GT(lemke.iterations, 0);
    EXPECT_NE(lemke.message.find("fc2d_lexicolemke info 0"), std::string::npos) << lemke.message;
  });
}

TEST_F(SiconosPeers, NsgsReproducesTheFastSolver) {
  against_the_fast_solver(PeerSolver::NSGS, [](const SolveReport& nsgs) {
    EXPECT_EQ(nsgs.solver, "siconos-nsgs");
    EXPECT_NE(nsgs.message.find("fc2d_nsgs_dense info 0"), std::string::npos) << nsgs.message;  // its own verdict
    // Small, but not 1e-10: see NsgsStopsOnItsOwnCriterionBeforeOurs.
    EXPECT_LT(nsgs.residual.value(), 1e-7) << nsgs.message;
  });
}

// fc2d_nsgs_dense stops when ‖q + M ρ - u‖ / ‖q‖ (u: the velocities of the last sweep's local
// solves, so this measures how much the sweep still moves) falls below the tolerance it is
// given. On the bar that criterion is met about 150 times before our SPEC residual: handed our
// 1e-10 it stops near 1.4e-8 and the report says NOT converged; a 1000 times tighter tolerance
// for the peer gets ours below 1e-10. Lemke has no such gap (it is exact up to round-off).
TEST_F(SiconosPeers, NsgsStopsOnItsOwnCriterionBeforeOurs) {
  const ContactProblem p = problem(table3_row1());
  SolverOptions options;
  options.tolerance = 1e-10;
  const SolveReport same = solve_siconos(p, bulk->condensed(), PeerSolver::NSGS, options);
  EXPECT_FALSE(same.converged) << same.message;
  EXPECT_GT(same.residual.value(), 10 * options.tolerance) << same.message;
  EXPECT_NE(same.message.find("NOT converged: fc2d_nsgs_dense info 0"), std::string::npos) << same.message;
  EXPECT_EQ(same.stop_cause, StopCause::LossOfAccuracy);  // stopped on its own criterion, not its cap

  options.tolerance = 1e-13;
  const SolveReport tighter = solve_siconos(p, bulk->condensed(), PeerSolver::NSGS, options);
  EXPECT_LT(tighter.residual.value(), 1e-10) << tighter.message;
  EXPECT_GT(tighter.iterations, same.iterations);
}

TEST_F(SiconosPeers, SayWhenTheyHitTheIterationCap) {
  const ContactProblem p = problem(table3_row1());
  SolverOptions options;
  options.max_iterations = 3;
  const SolveReport nsgs = solve_siconos(p, bulk->condensed(), PeerSolver::NSGS, options);
  EXPECT_FALSE(nsgs.converged);
  EXPECT_EQ(nsgs.iterations, 3);
  EXPECT_NE(nsgs.message.find("NOT converged: fc2d_nsgs_dense info 1"), std::string::npos) << nsgs.message;
  // Lemke stopped after 3 pivots: Siconos 4.4's fc2d_driver still returns info 0 there (only
  // its own error, ~5e-2, shows it); our residual is what says NOT converged.
  const SolveReport lemke = solve_siconos(p, bulk->condensed(), PeerSolver::Lemke, options);
  EXPECT_FALSE(lemke.converged);
  EXPECT_EQ(lemke.iterations, 3);
  EXPECT_GT(lemke.residual.value(), 1e-3);
  EXPECT_NE(lemke.message.find("NOT converged: fc2d_lexicolemke"), std::string::npos) << lemke.message;
  EXPECT_EQ(nsgs.stop_cause, StopCause::IterationCap);
  EXPECT_EQ(lemke.stop_cause, StopCause::IterationCap);
}

TEST_F(SiconosPeers, FreeLawIsSolvedWithoutCallingThePeer) {
  // Case (a): no node has a normal interaction, so there is no contact to hand over: r = 0.
  const ContactProblem p = problem(InterfaceLaw::make(0, 0, bar::friction));
  for (PeerSolver solver : {PeerSolver::NSGS, PeerSolver::Lemke}) {
    const SolveReport s = solve_siconos(p, bulk->condensed(), solver);
    EXPECT_TRUE(s.converged) << s.message;
    EXPECT_EQ(s.r.norm(), 0.0);
  }
}

// Twice finer (64 contact nodes), Table 3 row 1 with f = 1: Gauss–Seidel does not converge at
// all. fc2d_nsgs_dense wanders with its own error near 2e-2 and r some 55 % away from
// solve_fast's, however many sweeps it is given (10 to 100000 tried); a plain NSGS written
// independently on our side of the map, with consistent local branches, follows the same path
// sweep for sweep, so this is the method on this problem, not the sign map. With f = 0.5 or 0
// it converges. Lemke solves it.
TEST(SiconosPeersFinerBar, NsgsDoesNotConvergeAt64NodesWithFrictionOne) {
  BarBulk bulk(bar::MeshOptions{64, 64});
  const ContactProblem p(bulk.system(), {bar::make_interface(bulk.model(), table3_row1())});
  ASSERT_EQ(p.num_nodes(), 64);
  SolverOptions reference;
  reference.tolerance = 1e-12;
  const SolveReport fast = solve_fast(p, bulk.condensed(), reference);
  ASSERT_TRUE(fast.converged) << fast.message;

  SolverOptions options;
  options.max_iterations = 20000;
  const SolveReport nsgs = solve_siconos(p, bulk.condensed(), PeerSolver::NSGS, options);
  EXPECT_FALSE(nsgs.converged);
  EXPECT_EQ(nsgs.iterations, 20000);
  EXPECT_NE(nsgs.message.find("NOT converged: fc2d_nsgs_dense info 1"), std::string::npos) << nsgs.message;
  EXPECT_GT(relative_distance(nsgs.r, fast.r), 0.1);
  EXPECT_GT(nsgs.residual.value(), 0.1);

  const SolveReport lemke = solve_siconos(p, bulk.condensed(), PeerSolver::Lemke);
  EXPECT_TRUE(lemke.converged) << lemke.message;
  EXPECT_LT(relative_distance(lemke.r, fast.r), 1e-6);
}

TEST(SiconosPeersLayerMode, FloatingBodyIsRejected) {
  const bar::MeshOptions mesh{8, 8};
  bar::LayerOptions layer;
  layer.eps = 1e-2;
  layer.lambda_eps = layer.eps * 450;
  layer.mu_eps = layer.eps * 540;
  const Model model = bar::make_layer_model(mesh, layer);
  const LinearSystem system(model);
  const ContactProblem p(system, bar::make_layer_interfaces(model));
  const CondensedInterface condensed(p);
  ASSERT_GT(condensed.num_floating_unknowns(), 0);
  for (PeerSolver solver : {PeerSolver::NSGS, PeerSolver::Lemke})
    EXPECT_THROW(solve_siconos(p, condensed, solver), std::invalid_argument);
}

}  // namespace
}  // namespace thinlayer
