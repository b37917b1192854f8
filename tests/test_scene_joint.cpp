// An engineer's joint in a scene file (SPEC §5): several bondlines in one scene (a closed form),
// loads given as pressure and force resultants against hand-integrated tractions, mm-N against
// mm-daN, bodies by E and ν against λ and μ, a 0.2 mm glue line between 1.5 mm adherends, and a
// layer refused only where the geometry cannot hold it. Expected values are computed by hand here.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cases/scene/scene_file_scenes.h"
#include "core/io/h5_reader.h"
#include "tests/scene_folder.h"
#include "tests/uniform_bondline.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

const std::string num(double x) { return full_digits(x); }

// Three bodies stacked across two parallel bondlines at atan(0.2) = 11.3° to the x axis, in one
// uniform stress state (u = G x + c in each body, the same G): both bondlines carry the constant
// traction σn, and with both faces bonded the bilateral law makes each jump exactly
// [u]_N = −σ_N/K_N, [u]_T = −σ_T/K_T — here in tension across the bondlines (e > 0).
struct TwoBondlines : UniformBondline {
  TwoBondlines() {
    dx = 10, dy = 2;
    e = 1e-3;
  }
  Eigen::Vector2d top_u() const { return Eigen::Vector2d(a * 12, e * 12) + 2 * Delta(); }

  std::string geo() const {
    return "Point(1) = {0, 0, 0, 1}; Point(2) = {10, 0, 0, 1}; Point(3) = {10, 5, 0, 1}; Point(4) = {0, 3, 0, 1};\n"
           "Point(5) = {10, 9, 0, 1}; Point(6) = {0, 7, 0, 1}; Point(7) = {10, 12, 0, 1}; Point(8) = {0, 12, 0, 1};\n"
           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {4, 1};\n"
           "Line(5) = {3, 5}; Line(6) = {6, 5}; Line(7) = {6, 4};\n"
           "Line(8) = {5, 7}; Line(9) = {7, 8}; Line(10) = {8, 6};\n"
           "Curve Loop(1) = {1, 2, -3, 4}; Plane Surface(1) = {1};\n"
           "Curve Loop(2) = {3, 5, -6, 7}; Plane Surface(2) = {2};\n"
           "Curve Loop(3) = {6, 8, 9, 10}; Plane Surface(3) = {3};\n"
           "Physical Surface(\"lower\") = {1}; Physical Surface(\"middle\") = {2}; Physical Surface(\"upper\") = {3};\n"
           "Physical Curve(\"bond1\") = {3}; Physical Curve(\"bond2\") = {6};\n"
           "Physical Curve(\"bottom\") = {1}; Physical Curve(\"top\") = {9};\n"
           "Physical Curve(\"left\") = {4, 7, 10}; Physical Curve(\"right\") = {2, 5, 8};\n";
  }
  std::string json() const {
    const Eigen::Matrix2d S = sigma();
    auto bond = [&](const char* group, const char* plus, const char* minus) {
      return std::string("{\"group\": \"") + group + "\", \"plus\": \"" + plus + "\", \"minus\": \"" + minus +
             "\", \"faces\": {\"plus\": \"bonded\", \"minus\": \"bonded\"}, \"layer\": {\"gamma\": 1, \"delta\": 1, "
             "\"lambda_g\": " + num(lambda_g) + ", \"mu_g\": " + num(mu_g) + "}}";
    };
    auto body = [&](const char* name) {
      return std::string("\"") + name + "\": {\"group\": \"" + name + "\", \"lambda\": " + num(lambda) +
             ", \"mu\": " + num(mu) + "}";
    };
    return "{\"name\": \"two-bondlines\", \"geometry\": \"t.geo\", \"mesh_size\": {\"interface\": 1, \"far\": 2},\n"
           " \"bodies\": {" + body("lower") + ", " + body("middle") + ", " + body("upper") + "},\n"
           " \"interfaces\": [" + bond("bond1", "middle", "lower") + ",\n  " + bond("bond2", "upper", "middle") + "],\n"
           " \"supports\": [{\"group\": \"bottom\", \"u\": [0, 0]}, {\"group\": \"top\", \"u\": [" + num(top_u().x()) +
           ", " + num(top_u().y()) + "]}],\n"
           " \"loads\": [{\"group\": \"left\", \"traction\": [" + num(-S(0, 0)) + ", " + num(-S(0, 1)) + "]},\n"
           "           {\"group\": \"right\", \"traction\": [" + num(S(0, 0)) + ", " + num(S(0, 1)) + "]}]}\n";
  }
};

// The largest deviation of each bondline's jump (from the adherents' node pairs: across the layer
// in layer mode) from the closed form's Δ, relative to |Δ|.
double jump_error(const SceneFileBulk& bulk, const SceneRecord& r, const Eigen::Vector2d& Delta) {
  double worst = 0;
  for (const Interface& S : bulk.limit_interfaces(0, false))
    for (const InterfaceNode& node : S.nodes) {
      int plus_row = node.plus_node, minus_row = node.minus_node;
      for (int b = 0; b < node.plus_body; ++b) plus_row += bulk.meshes().bodies[b].num_nodes();
      for (int b = 0; b < node.minus_body; ++b) minus_row += bulk.meshes().bodies[b].num_nodes();
      const Eigen::Vector2d d = r.u.row(plus_row).transpose() - r.u.row(minus_row).transpose();
      worst = std::max(worst, (d - Delta).norm() / Delta.norm());
    }
  return worst;
}

}  // namespace

TEST(SceneJoint, SeveralBondlinesLimitModeExact) {
  const TwoBondlines cf;
  ASSERT_GT(cf.sigma_N(), 0);
  SceneFolder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("t", cf.geo(), cf.json())));
  ASSERT_EQ(bulk.spec().interfaces.size(), 2u);
  EXPECT_TRUE(bulk.model().bodies[1].floating);  // the middle body: held by its two bondlines alone
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  ASSERT_EQ(s.record.interfaces.size(), 2u);
  EXPECT_EQ(s.record.interfaces[0].name, "bond1/S");  // interface/<group>/S in the file
  EXPECT_EQ(s.record.interfaces[1].name, "bond2/S");
  const double error = jump_error(bulk, s.record, cf.Delta());
  std::printf("two bondlines, limit mode: max relative jump error %.3e\n", error);
  EXPECT_LT(error, 1e-8);
  for (const InterfaceFields& S : s.record.interfaces)
    for (Eigen::Index k = 0; k < S.sigma_N.size(); ++k) {
      EXPECT_NEAR(S.sigma_N[k], cf.sigma_N(), 1e-8 * cf.sigma_N());
      EXPECT_NEAR(S.sigma_T[k], cf.sigma_T(), 1e-8 * cf.sigma_N());
    }
}

// Layer mode: the middle body is the plus body of bond1 and the minus body of bond2, so it makes
// room for the first layer while its face on the second stays (it is squeezed by ε); the upper
// body moves by ε. Both layers converge to the bilateral jumps at first order in ε.
TEST(SceneJoint, SeveralBondlinesLayerModeConverges) {
  const TwoBondlines cf;
  SceneFolder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("t", cf.geo(), cf.json())));
  double previous = INFINITY;
  for (double eps : {1e-2, 1e-3}) {
    const SceneFileScene s = solve_scene_file_layer(bulk, eps, SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << "eps " << eps << ": " << s.report.message;
    ASSERT_EQ(s.record.interfaces.size(), 4u);
    EXPECT_EQ(s.record.interfaces[0].name, "bond1/S+");
    EXPECT_EQ(s.record.interfaces[3].name, "bond2/S-");
    const double error = jump_error(bulk, s.record, cf.Delta());
    std::printf("two bondlines, layer mode at eps %g: max relative jump error %.3e\n", eps, error);
    EXPECT_LT(error, 2e-2);
    EXPECT_LT(error, previous / 5);
    previous = error;
  }
}

namespace {

// Two aluminium blocks bonded along y = 2 (a law only); the upper one's top edge inclined from
// (0, 4) to (10, 6). Loads: a pressure p on that edge, a force resultant on the lower block's
// right side, a force on the upper block's corner point (10, 6). Per mm of thickness.
std::string blocks_geo() {
  return "Point(1) = {0, 0, 0, 1}; Point(2) = {10, 0, 0, 1}; Point(3) = {10, 2, 0, 1}; Point(4) = {0, 2, 0, 1};\n"
         "Point(5) = {10, 6, 0, 1}; Point(6) = {0, 4, 0, 1};\n"
         "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {4, 1};\n"
         "Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};\n"
         "Curve Loop(1) = {1, 2, -3, 4}; Plane Surface(1) = {1};\n"
         "Curve Loop(2) = {3, 5, 6, 7}; Plane Surface(2) = {2};\n"
         "Physical Surface(\"lower\") = {1}; Physical Surface(\"upper\") = {2};\n"
         "Physical Curve(\"bond\") = {3}; Physical Curve(\"bottom\") = {1}; Physical Curve(\"slope\") = {6};\n"
         "Physical Curve(\"side\") = {2}; Physical Point(\"tip\") = {5};\n";
}

// `scale` multiplies every modulus and load (10: the same joint in N and MPa).
std::string blocks_json(const std::string& units, double scale, bool young = true) {
  const double E = 7000 * scale, nu = 0.33;  // daN/mm² (70 GPa)
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));  // by hand
  auto body = [&](const char* name) {
    return std::string("\"") + name + "\": {\"group\": \"" + name + "\", " +
           (young ? "\"E\": " + num(E) + ", \"nu\": " + num(nu) : "\"lambda\": " + num(lambda) + ", \"mu\": " + num(mu)) + "}";
  };
  return "{\"name\": \"blocks\", \"geometry\": \"b.geo\", \"mesh_size\": {\"interface\": 1, \"far\": 2}, \"units\": \"" +
         units + "\",\n \"bodies\": {" + body("lower") + ", " + body("upper") + "},\n"
         " \"interface\": {\"group\": \"bond\", \"plus\": \"upper\", \"minus\": \"lower\", \"faces\": {\"plus\": \"bonded\", "
         "\"minus\": \"bonded\"}, \"law\": {\"lambda_bar\": " + num(3000 * scale) + ", \"mu_bar\": " + num(1000 * scale) + "}},\n"
         " \"supports\": [{\"group\": \"bottom\", \"u\": [0, 0]}],\n"
         " \"loads\": [{\"group\": \"slope\", \"pressure\": " + num(2 * scale) + "},\n"
         "           {\"group\": \"side\", \"force\": [" + num(3 * scale) + ", " + num(-1 * scale) + "]},\n"
         "           {\"group\": \"tip\", \"force\": [" + num(0.5 * scale) + ", " + num(0.25 * scale) + "]}]}\n";
}

SceneFileScene solve_blocks(const SceneFolder& f, const std::string& json) {
  SceneFileBulk bulk(read_scene_spec(f.write("b.json", json)));
  return solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
}

}  // namespace

// The resultants by hand: the pressure p = 2 pushes into the upper block across its top edge of
// direction (−10, −2) (the body on its left), outward normal (−2, 10)/√104, length √104:
// −p n L = (4, −20). The force on the side: (3, −1), spread along it but summing to itself. The
// point force: (0.5, 0.25). The reactions of the clamped bottom balance their sum, (−7.5, 20.75).
TEST(SceneJoint, PressureAndForceResultantsAgainstHandIntegration) {
  SceneFolder f;
  f.write("b.geo", blocks_geo());
  const SceneFileScene s = solve_blocks(f, blocks_json("mm-daN", 1));
  ASSERT_TRUE(s.report.converged) << s.report.message;
  ASSERT_EQ(s.loads.size(), 3u);
  EXPECT_NEAR(s.loads.at("slope").x(), 4.0, 1e-12);
  EXPECT_NEAR(s.loads.at("slope").y(), -20.0, 1e-12);
  EXPECT_NEAR(s.loads.at("side").x(), 3.0, 1e-12);
  EXPECT_NEAR(s.loads.at("side").y(), -1.0, 1e-12);
  EXPECT_NEAR(s.loads.at("tip").x(), 0.5, 1e-15);
  EXPECT_NEAR(s.loads.at("tip").y(), 0.25, 1e-15);
  const Eigen::Vector2d R = s.record.reactions.at("bottom");
  EXPECT_NEAR(R.x(), -7.5, 1e-9);
  EXPECT_NEAR(R.y(), 20.75, 1e-9);
}

// The same joint in N and MPa (every modulus and load × 10): the same displacements, stresses
// and reactions × 10, and the file says so (units "MPa", "N/mm"); bodies by λ, μ computed by hand
// from E, ν give the same answer as by E, ν.
TEST(SceneJoint, NewtonsAgainstDecanewtonsAndYoungAgainstLame) {
  SceneFolder f;
  f.write("b.geo", blocks_geo());
  const SceneFileScene daN = solve_blocks(f, blocks_json("mm-daN", 1));
  const SceneFileScene N = solve_blocks(f, blocks_json("mm-N", 10));
  const SceneFileScene lame = solve_blocks(f, blocks_json("mm-daN", 1, /*young=*/false));
  ASSERT_TRUE(daN.report.converged && N.report.converged && lame.report.converged);
  const double U = daN.record.u.cwiseAbs().maxCoeff();
  EXPECT_LT((N.record.u - daN.record.u).cwiseAbs().maxCoeff(), 1e-10 * U);
  EXPECT_LT((lame.record.u - daN.record.u).cwiseAbs().maxCoeff(), 1e-10 * U);
  const InterfaceFields &a = daN.record.interfaces.at(0), &b = N.record.interfaces.at(0);
  const double sigma = a.sigma_N.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < a.sigma_N.size(); ++k) {
    EXPECT_NEAR(b.sigma_N[k], 10 * a.sigma_N[k], 1e-9 * 10 * sigma);
    EXPECT_NEAR(b.sigma_T[k], 10 * a.sigma_T[k], 1e-9 * 10 * sigma);
  }
  EXPECT_NEAR(N.record.reactions.at("bottom").y(), 10 * daN.record.reactions.at("bottom").y(), 1e-9);
  // The written units.
  {
    H5Writer out((f.path / "n.h5").string());
    write_scene(out, N.record);
    out.commit();
  }
  const H5Reader in((f.path / "n.h5").string());
  const std::string g = "/scenes/" + N.record.id;
  EXPECT_EQ(in.attr_string(g + "/interface/S/sigma_N", "units"), "MPa");
  EXPECT_EQ(in.attr_string(g + "/reactions/bottom", "units"), "N/mm (per mm of thickness)");
  EXPECT_EQ(in.attr_string(g, "lambda_bar_units"), "N/mm^3");
  EXPECT_EQ(in.attr_string(g, "units"), "mm-N");
}

// The joint: a 0.2 mm glue line between 1.5 mm adherends, the bondline's elements 1 mm
// long (the first row of cells is ~1 mm deep: moving only it allowed 0.17 mm at most). The outer
// strip moves away by the glue's thickness and the layer is exactly 0.2 mm thick.
TEST(SceneJoint, TwoTenthsOfAMillimetreOfGlueBetween1_5mmAdherends) {
  SceneFolder f;
  std::string geo = read_text_file(std::string(THINLAYER_CASES_DIR) + "/double_lap/double_lap.geo");
  f.write("double_lap.geo", geo);
  std::string json = read_text_file(std::string(THINLAYER_CASES_DIR) + "/double_lap/double_lap.json");
  json.replace(json.find("\"interface\": 0.25"), 17, "\"interface\": 1.0");
  SceneFileBulk bulk(read_scene_spec(f.write("d.json", json)));
  ASSERT_GE(bulk.thickest_layer(), 0.2) << bulk.thickest_reason();
  const SceneFileScene s = solve_scene_file_layer(bulk, 0, SolverKind::Fast, SolverOptions{});  // the glue's own 0.2 mm
  ASSERT_TRUE(s.report.converged) << s.report.message;
  ASSERT_EQ(s.bondlines.at(0).thickness, 0.2);
  const InterfaceFields &plus = s.record.interfaces.at(0), &minus = s.record.interfaces.at(1);  // bond_top S+, S-
  for (Eigen::Index k = 0; k < plus.x.rows(); ++k)
    EXPECT_NEAR((plus.x.row(k) - minus.x.row(k)).norm(), 0.2, 1e-12) << "node " << k;
  std::printf("0.2 mm glue between 1.5 mm strips at h = 1 mm: residual %.2e; thickest allowed %g mm (%s)\n",
              s.report.residual.value(), bulk.thickest_layer(), bulk.thickest_reason().c_str());
}

// Refused only where the geometry cannot hold it: the double lap with its inner strip (3 mm) as
// the plus body of both bondlines is squeezed from both sides (at 2ε = 3 mm nothing is left of it),
// and where each bondline ends the strip's free face must step by ε: the cells there invert first.
// The thickest allowed is half the ε at which the first cell inverts, below the 0.75 mm of a
// uniform squeeze, above the glue's own 0.2 mm; the message names the body and where.
TEST(SceneJoint, TooThinAPlusBodyIsRefusedSayingWhy) {
  SceneFolder f;
  f.write("double_lap.geo", read_text_file(std::string(THINLAYER_CASES_DIR) + "/double_lap/double_lap.geo"));
  std::string json = read_text_file(std::string(THINLAYER_CASES_DIR) + "/double_lap/double_lap.json");
  for (const char* outer : {"\"plus\": \"outer_top\", \"minus\": \"inner\"", "\"plus\": \"outer_bottom\", \"minus\": \"inner\""}) {
    const std::string from = outer;
    const std::string to = "\"plus\": \"inner\", \"minus\": \"" + std::string(from.find("top") != std::string::npos ? "outer_top" : "outer_bottom") + "\"";
    json.replace(json.find(from), from.size(), to);
  }
  SceneFileBulk bulk(read_scene_spec(f.write("d.json", json)));
  const double thickest = bulk.thickest_layer();
  std::printf("inner strip as the plus body: thickest %g mm (%s)\n", thickest, bulk.thickest_reason().c_str());
  EXPECT_LT(thickest, 0.75);
  EXPECT_GT(thickest, 0.2);
  EXPECT_NE(bulk.thickest_reason().find("invert a cell of body 'inner'"), std::string::npos) << bulk.thickest_reason();
  try {
    check_layer_mode(bulk, 1.05 * thickest);
    FAIL() << "a layer thicker than the thickest accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("too thick for this joint"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(check_layer_mode(bulk, 0.95 * thickest));
  const SceneFileScene s = solve_scene_file_layer(bulk, 0.2, SolverKind::Fast, SolverOptions{});
  EXPECT_TRUE(s.report.converged) << s.report.message;
}
