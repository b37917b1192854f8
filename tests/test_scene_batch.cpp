// SceneBatch (studies/parallel/scene_batch.h): every result in place and in order, whatever the ranks and
// threads; a scene that throws is named; the longest-first assignment; results survive the
// trip through bytes bit for bit. CTest runs this file as one process and, under mpirun, as
// two ranks (scene_batch_two_ranks), where the same assertions hold on every rank.
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "studies/parallel/process_group.h"
#include "studies/parallel/result_bytes.h"
#include "studies/parallel/scene_batch.h"

namespace thinlayer {
namespace {

// MPI starts before the tests (when mpirun started us) and stops after them.
class Processes : public ::testing::Environment {
 public:
  void SetUp() override {
    int argc = 0;
    char** argv = nullptr;
    group_ = new ProcessGroup(argc, argv);
  }
  void TearDown() override { delete group_; }

 private:
  ProcessGroup* group_ = nullptr;
};
const auto* const processes = ::testing::AddGlobalTestEnvironment(new Processes);

TEST(AssignLongestFirst, GreedyOnDecreasingCosts) {
  // 5 -> r0, 4 -> r1, 3 -> r1 (load 4 < 5), 3 -> r0 (5 < 7), 3 -> r1 (7 < 8).
  EXPECT_EQ(assign_longest_first({5, 4, 3, 3, 3}, 2), (std::vector<int>{0, 1, 1, 0, 1}));
  // Ties go to the lower rank and the earlier task: equal costs deal round-robin.
  EXPECT_EQ(assign_longest_first({1, 1, 1, 1, 1}, 3), (std::vector<int>{0, 1, 2, 0, 1}));
  // One expensive scene and many cheap ones: the cheap ones fill the other ranks.
  EXPECT_EQ(assign_longest_first({100, 1, 1, 1}, 2), (std::vector<int>{0, 1, 1, 1}));
  EXPECT_EQ(assign_longest_first({2, 3}, 1), (std::vector<int>{0, 0}));
}

TEST(SceneBatch, EveryResultInPlaceAndInOrder) {
  for (int threads : {1, 3}) {
    SceneBatch batch("test", threads);
    std::vector<long long> squares(40, -1);
    std::vector<std::string> names(40);
    std::atomic<int> solved_here{0};
    for (int i = 0; i < 40; ++i) {
      batch.add("square " + std::to_string(i), 1 + i % 7, squares[i], [i, &solved_here] {
        ++solved_here;
        return static_cast<long long>(i) * i;
      });
      batch.add("name " + std::to_string(i), 0.5, names[i], [i] { return "scene-" + std::to_string(i); });
    }
    batch.run();
    for (int i = 0; i < 40; ++i) {
      EXPECT_EQ(squares[i], static_cast<long long>(i) * i);
      EXPECT_EQ(names[i], "scene-" + std::to_string(i));
    }
    ASSERT_EQ(batch.size(), 80u);
    // Spread over K ranks, each solves only its share; one process solves them all.
    if (rank_count() == 1) {
      EXPECT_EQ(solved_here, 40);
    } else {
      EXPECT_LT(solved_here, 40);
    }
  }
}

TEST(SceneBatch, AThrowingSceneIsNamedOnEveryRank) {
  SceneBatch batch("test");
  std::vector<int> out(6);
  for (int i = 0; i < 6; ++i)
    batch.add("scene " + std::to_string(i), 1, out[i], [i] {
      if (i == 4) throw std::runtime_error("singular system: nothing holds it");
      return i;
    });
  try {
    batch.run();
    FAIL() << "no SceneFailure";
  } catch (const SceneFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("scene 'scene 4'"), std::string::npos) << what;
    EXPECT_NE(what.find("singular system: nothing holds it"), std::string::npos) << what;
    if (rank_count() > 1) {
      EXPECT_NE(what.find("on rank "), std::string::npos) << what;
    }
  }
  // The batch is usable again afterwards: the next run starts empty.
  int again = 0;
  batch.add("after", 1, again, [] { return 7; });
  batch.run();
  EXPECT_EQ(again, 7);
}

TEST(SceneBatch, RankZeroWorkingAloneSolvesEverythingItself) {
  // What on_root_alone does: the other ranks are not running the batch, so rank 0 must not
  // wait for them (under two ranks this test would hang without WorkingAlone).
  if (is_root()) {
    const WorkingAlone alone;
    SceneBatch batch("alone");
    std::vector<int> out(5, -1);
    int solved_here = 0;
    for (int i = 0; i < 5; ++i)
      batch.add("scene " + std::to_string(i), 1, out[i], [i, &solved_here] { return ++solved_here, i; });
    batch.run();
    EXPECT_EQ(solved_here, 5);
    EXPECT_EQ(out, (std::vector<int>{0, 1, 2, 3, 4}));
  }
  wait_for_each_other();
}

// `a` written as bytes and read back: every byte read, and reading more than was written an
// error, not garbage.
template <class T>
T round_trip(const T& a) {
  ByteWriter w;
  put(w, a);
  const std::string bytes = w.take();
  ByteReader r(bytes);
  T b;
  get(r, b);
  EXPECT_TRUE(r.done());
  int extra = 0;
  EXPECT_THROW(get(r, extra), std::runtime_error);
  return b;
}

TEST(ResultBytes, ASceneRecordComesBackBitForBit) {
  SceneRecord a;
  a.id = "bar-x";
  a.text = {{"case", "bar"}, {"mode", "layer"}};
  a.numbers = {{"eps", 1e-4}, {"nan", std::numeric_limits<double>::quiet_NaN()}, {"inf", -INFINITY}};
  a.integers = {{"nx", 32}};
  a.nodes.resize(3, 2);
  a.nodes << 0, 1, 2, 3, 4, 5.5;
  a.cells.resize(1, 3);
  a.cells << 0, 1, 2;
  a.u = a.nodes * 1e-3;
  // The self-description of results layout 2 (issue 15) travels too.
  a.body_names = {"bar", "layer"};
  a.cell_body = {1};
  a.cell_stress.resize(1, 3);
  a.cell_stress << -10, 5.25, 1e-300;
  a.residual_per_body = {3e-11, 7e-12};
  a.residual_per_interface = {1e-12};
  a.interface_names = {"S+"};
  InterfaceFields f;
  f.name = "S+";
  f.x = a.nodes;
  f.jump_N = Eigen::VectorXd::LinSpaced(3, -1, 1);
  f.status = {0, 1, 2};
  f.node_plus = {0, 1, 2};
  f.node_minus = {-1, -1, -1};
  a.interfaces = {f};
  a.reactions["D"] = Eigen::Vector2d(1.5, -2.25);
  a.combined_status = {2, 2, 0};
  const SceneRecord b = round_trip(a);
  EXPECT_EQ(b.id, a.id);
  EXPECT_EQ(b.text, a.text);
  EXPECT_EQ(b.numbers.at("eps"), 1e-4);
  EXPECT_TRUE(std::isnan(b.numbers.at("nan")));
  EXPECT_EQ(b.numbers.at("inf"), -INFINITY);
  EXPECT_EQ(b.integers, a.integers);
  EXPECT_EQ(b.nodes, a.nodes);
  EXPECT_EQ(b.cells, a.cells);
  EXPECT_EQ(b.u, a.u);
  EXPECT_EQ(b.body_names, a.body_names);
  EXPECT_EQ(b.cell_body, a.cell_body);
  EXPECT_EQ(b.cell_stress, a.cell_stress);
  EXPECT_EQ(b.residual_per_body, a.residual_per_body);
  EXPECT_EQ(b.residual_per_interface, a.residual_per_interface);
  EXPECT_EQ(b.interface_names, a.interface_names);
  ASSERT_EQ(b.interfaces.size(), 1u);
  EXPECT_EQ(b.interfaces[0].name, "S+");
  EXPECT_EQ(b.interfaces[0].jump_N, f.jump_N);
  EXPECT_EQ(b.interfaces[0].status, f.status);
  EXPECT_EQ(b.interfaces[0].node_plus, f.node_plus);
  EXPECT_EQ(b.interfaces[0].node_minus, f.node_minus);
  EXPECT_EQ(b.reactions.at("D"), a.reactions.at("D"));
  EXPECT_EQ(b.combined_status, a.combined_status);
}

TEST(ResultBytes, ASolveReportKeepsItsResidualBodyByBody) {
  SolveReport a;
  a.solver = "fast";
  a.u = Eigen::VectorXd::LinSpaced(4, 0, 1);
  a.residual.interface = 2e-11;
  a.residual.bulk = 4e-11;
  a.residual.per_interface = {2e-11, 1e-13};
  a.residual.per_body = {4e-11, 3e-12, 5e-13};
  a.stop_cause = StopCause::Converged;
  const SolveReport b = round_trip(a);
  EXPECT_EQ(b.u, a.u);
  EXPECT_EQ(b.residual.per_interface, a.residual.per_interface);
  EXPECT_EQ(b.residual.per_body, a.residual.per_body);
  EXPECT_EQ(b.stop_cause, a.stop_cause);
}

}  // namespace
}  // namespace thinlayer
