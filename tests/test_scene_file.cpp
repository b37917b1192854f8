// Scene files (SPEC §5): the JSON schema's positions, and a closed-form scene. The closed form:
// a rectangle cut by a straight bondline at 21.8° to the x axis, both halves in one uniform
// stress state (u = G x + c on each side, the same G), so the interface carries the constant
// traction σn and the limit law (case d, sticking) makes the displacement jump exactly
// [u]_N = −σ_N/K_N, [u]_T = −σ_T/K_T. Everything expected here is computed by hand below from
// G, λ, μ and the bondline's angle, not by the code under test.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cases/scene/json_positions.h"
#include "cases/scene/scene_spec.h"
#include "cases/scene/scene_file_scenes.h"
#include "core/mesh/gmsh_session.h"
#include "tests/scene_folder.h"
#include "tests/uniform_bondline.h"
#include "tests/error_message.h"

namespace fs = std::filesystem;
using namespace thinlayer;

namespace {

// The InputError's message of parsing `text`, or of reading it as a scene ("(no error)" if none).
std::string expect_input_error(const std::string& text) {
  return message_of<InputError>([&] { parse_positioned_json(text, "s.json"); });
}

std::string spec_error(const std::string& text) {
  const std::string m = message_of<InputError>([&] { scene_spec_from_json(parse_positioned_json(text, "s.json"), "."); });
  return m.empty() ? "(no error)" : m;
}

using Folder = SceneFolder;
std::string num(double x) { return full_digits(x); }

// The closed form's data. Plane strain, mm and daN.
struct ClosedForm : UniformBondline {
  double W = 10, H = 10, y0 = 3, y1 = 7;  // bondline from (0, y0) to (W, y1): direction (W, y1 − y0)
  std::string faces;                      // "" (contact, the paper's), or a "faces" member of the interface
  Eigen::Vector2d top_u() const { return Eigen::Vector2d(a * H, e * H) + Delta(); }

  std::string geo() const {
    return "Point(1) = {0, 0, 0, 1};\nPoint(2) = {" + num(W) + ", 0, 0, 1};\nPoint(3) = {" + num(W) + ", " + num(y1) +
           ", 0, 1};\nPoint(4) = {0, " + num(y0) + ", 0, 1};\nPoint(5) = {" + num(W) + ", " + num(H) +
           ", 0, 1};\nPoint(6) = {0, " + num(H) + ", 0, 1};\n"
           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {4, 1};\n"
           "Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};\n"
           "Curve Loop(1) = {1, 2, -3, 4}; Plane Surface(1) = {1};\n"
           "Curve Loop(2) = {3, 5, 6, 7}; Plane Surface(2) = {2};\n"
           "Physical Surface(\"lower\") = {1};\nPhysical Surface(\"upper\") = {2};\n"
           "Physical Curve(\"bond\") = {3};\nPhysical Curve(\"bottom\") = {1};\nPhysical Curve(\"top\") = {6};\n"
           "Physical Curve(\"left\") = {4, 7};\nPhysical Curve(\"right\") = {2, 5};\n";
  }
  // The sides carry σ n_out: (−σ_xx, −σ_xy) on x = 0, (σ_xx, σ_xy) on x = W.
  std::string json(bool plus_supported = true) const {
    const Eigen::Matrix2d S = sigma();
    std::string supports = "[{\"group\": \"bottom\", \"u\": [0, 0]}";
    std::string loads = "[{\"group\": \"left\", \"traction\": [" + num(-S(0, 0)) + ", " + num(-S(0, 1)) + "]}, " +
                        "{\"group\": \"right\", \"traction\": [" + num(S(0, 0)) + ", " + num(S(0, 1)) + "]}";
    if (plus_supported)
      supports += ", {\"group\": \"top\", \"u\": [" + num(top_u().x()) + ", " + num(top_u().y()) + "]}";
    else  // held by its contact alone: the top carries σ (0, 1)
      loads += ", {\"group\": \"top\", \"traction\": [" + num(S(0, 1)) + ", " + num(S(1, 1)) + "]}";
    return "{\"name\": \"closed-form\", \"geometry\": \"cf.geo\", \"mesh_size\": {\"interface\": 1, \"far\": 2},\n"
           " \"bodies\": {\"lower\": {\"group\": \"lower\", \"lambda\": " + num(lambda) + ", \"mu\": " + num(mu) + "},\n"
           "            \"upper\": {\"group\": \"upper\", \"lambda\": " + num(lambda) + ", \"mu\": " + num(mu) + "}},\n"
           " \"interface\": {\"group\": \"bond\", \"plus\": \"upper\", \"minus\": \"lower\", \"friction\": 1,\n" +
           (faces.empty() ? "" : "   \"faces\": " + faces + ",\n") +
           "   \"layer\": {\"gamma\": 1, \"delta\": 1, \"lambda_g\": " + num(lambda_g) + ", \"mu_g\": " + num(mu_g) + "}},\n"
           " \"supports\": " + supports + "],\n \"loads\": " + loads + "]}\n";
  }
};

// Largest deviation of the jumps across the whole interface (from the adherents' node pairs,
// so across the layer in layer mode) from the closed form, relative to |[u]|.
double jump_error(const SceneFileBulk& bulk, const SceneRecord& r, const ClosedForm& cf) {
  const int lower_nodes = bulk.meshes().bodies[0].num_nodes();
  const SceneInterfaceNodes& S = bulk.interface_nodes().at(0);
  double worst = 0;
  for (size_t k = 0; k < S.plus.size(); ++k) {
    const Eigen::Vector2d d = r.u.row(lower_nodes + S.plus[k]).transpose() - r.u.row(S.minus[k]).transpose();  // u⁺ − u⁻
    worst = std::max(worst, (d - cf.Delta()).norm() / cf.Delta().norm());
  }
  return worst;
}

}  // namespace

TEST(SceneJson, SyntaxErrorNamesLineAndColumn) {
  const std::string m = expect_input_error("{\n  \"name\": \"x\",\n  \"bodies\": {,}\n}\n");
  EXPECT_EQ(m.rfind("s.json:3:14: syntax error", 0), 0u) << m;
}

TEST(SceneJson, DuplicateKeyRefused) {
  const std::string m = expect_input_error("{\"a\": 1,\n \"a\": 2}");
  EXPECT_EQ(m, "s.json:2:2: key 'a' given twice");
}

TEST(SceneJson, PositionsOfKeysAndArrayElements) {
  const PositionedJson j = parse_positioned_json("{\"a\": [1,\n  {\"b\": 2}], \"c\" : null}", "x");
  EXPECT_EQ(j.at("/a").line, 1);
  EXPECT_EQ(j.at("/a").column, 2);
  EXPECT_EQ(j.at("/a/1").line, 2);
  EXPECT_EQ(j.at("/a/1").column, 3);
  EXPECT_EQ(j.at("/a/1/b").column, 4);
  EXPECT_EQ(j.at("/c").line, 2);
  EXPECT_EQ(j.at("/c").column, 14);
}

// A key of the positions' tree is stored once; escaped keys (RFC 6901) and a missing member
// answer with the nearest parent's position.
TEST(SceneJson, PositionsOfEscapedKeysAndOfWhatIsNotThere) {
  const PositionedJson j = parse_positioned_json("{\"a/b\": {\"~c\": [0,\n 5]}}", "x");
  EXPECT_EQ(j.at("/a~1b").column, 2);
  EXPECT_EQ(j.at("/a~1b/~0c").column, 10);
  EXPECT_EQ(j.at("/a~1b/~0c/1").line, 2);
  EXPECT_EQ(j.at("/a~1b/~0c/1").column, 2);
  EXPECT_EQ(j.at("/a~1b/missing").column, 2);  // its parent's
  EXPECT_EQ(j.at("").column, 1);
}

TEST(SceneJson, AKeyLongerThanTheBoundIsRefusedAtIt) {
  const std::string long_key(max_json_key_bytes + 1, 'k');
  const std::string m = expect_input_error("{\"a\": 1,\n \"" + long_key + "\": 2}");
  EXPECT_EQ(m, "s.json:2:2: a key of 65 bytes (a key, a body's name among them, is at most 64)");
  EXPECT_EQ(expect_input_error("{\"" + std::string(max_json_key_bytes, 'k') + "\": 2}"), "");
}

TEST(SceneSpec, ANameLongerThanTheBoundIsRefusedAtIt) {
  const std::string m = spec_error("{\"name\": \"" + std::string(max_scene_name_bytes + 1, 'n') + "\"}");
  EXPECT_EQ(m, "s.json:1:2: 'name' in the scene is 65 bytes long; a name is at most 64");
}

TEST(SceneSpec, UnknownKeyNamedWithItsPosition) {
  const std::string m = spec_error("{\"name\": \"x\",\n \"frction\": 1}");
  EXPECT_EQ(m.rfind("s.json:2:2: unknown key 'frction' in the scene", 0), 0u) << m;
}

TEST(SceneSpec, NameThatWouldNestGroupsRefused) {
  const std::string m = spec_error("{\"name\": \"a/b\"}");
  EXPECT_EQ(m.rfind("s.json:1:2: 'name' may hold letters", 0), 0u) << m;
}

TEST(SceneSpec, WrongTypeNamedWithItsPosition) {
  const std::string m = spec_error("{\"name\": 3}");
  EXPECT_EQ(m, "s.json:1:2: 'name' in the scene must be a string, not a number");
}

TEST(SceneSpec, MissingKeyNamedAtItsObject) {
  Folder f;
  f.write("g.geo", "Point(1) = {0,0,0,1};");
  const std::string text =
      "{\"name\": \"x\", \"geometry\": \"g.geo\",\n \"bodies\": {\"a\": {\"mu\": 1, \"lambda\": 1}}}";
  try {
    scene_spec_from_json(parse_positioned_json(text, "s.json"), f.path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "s.json:2:13: body 'a' has no 'group'");
  }
}

TEST(SceneClosedForm, LimitModeJumpsAreSigmaOverKToRoundOff) {
  const ClosedForm cf;
  ASSERT_LT(cf.sigma_N(), 0);                                // in contact
  ASSERT_LT(std::abs(cf.sigma_T()), std::abs(cf.sigma_N()));  // sticking (f = 1)
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json())));
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  const double error = jump_error(bulk, s.record, cf);
  std::printf("closed form, limit mode: max relative jump error %.3e (|[u]| = %.4e mm)\n", error, cf.Delta().norm());
  EXPECT_LT(error, 1e-9);
  const InterfaceFields& S = s.record.interfaces.at(0);
  for (Eigen::Index k = 0; k < S.sigma_N.size(); ++k) {
    EXPECT_NEAR(S.sigma_N[k], cf.sigma_N(), 1e-9 * std::abs(cf.sigma_N()));
    EXPECT_NEAR(S.sigma_T[k], cf.sigma_T(), 1e-9 * std::abs(cf.sigma_N()));
    EXPECT_NEAR(S.jump_N[k], cf.jump_N(), 1e-9 * cf.Delta().norm());
    EXPECT_NEAR(S.jump_T[k], cf.jump_T(), 1e-9 * cf.Delta().norm());
    EXPECT_EQ(S.status[k], 2);  // stick
  }
}

TEST(SceneClosedForm, BodyHeldByContactAloneLimitMode) {
  const ClosedForm cf;
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json(/*plus_supported=*/false))));
  ASSERT_TRUE(bulk.model().bodies[1].floating);
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  const double error = jump_error(bulk, s.record, cf);
  std::printf("closed form, upper body held by contact alone: max relative jump error %.3e\n", error);
  EXPECT_LT(error, 1e-8);
}

TEST(SceneClosedForm, LayerModeConvergesToTheJumps) {
  const ClosedForm cf;
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json())));
  double previous = INFINITY;
  for (double eps : {1e-1, 1e-2, 1e-3, 1e-4}) {
    const SceneFileScene s = solve_scene_file_layer(bulk, eps, SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << "eps " << eps << ": " << s.report.message;
    const double error = jump_error(bulk, s.record, cf);
    std::printf("closed form, layer mode at eps %g: max relative jump error %.3e\n", eps, error);
    // First order in ε (studies/convergence_rates.md, case d): at least a factor 5 per decade.
    EXPECT_LT(error, previous / 5) << "eps " << eps;
    previous = error;
  }
}

TEST(SceneClosedForm, TooThickALayerIsRefused) {
  const ClosedForm cf;
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json())));
  ASSERT_GT(bulk.thickest_layer(), 0);
  EXPECT_THROW(solve_scene_file_layer(bulk, 1.01 * bulk.thickest_layer(), SolverKind::Fast, SolverOptions{}),
               std::invalid_argument);
}

// A .msh 4.1 is used as is: the closed form meshed once by gmsh (its own sizes), written, and
// read back through "mesh" gives the exact jumps too.
TEST(SceneClosedForm, MeshFileUsedAsIs) {
  const ClosedForm cf;
  Folder f;
  f.write("cf.geo", cf.geo());
  {
    GmshModelScope scope("write-msh");
    with_gmsh_errors([&] {
      gmsh::open((f.path / "cf.geo").string());
      gmsh::option::setNumber("Mesh.RecombineAll", 1);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 2);
      gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
      gmsh::model::mesh::generate(2);
      gmsh::write((f.path / "cf.msh").string());
      gmsh::option::setNumber("Mesh.RecombineAll", 0);
      gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);
    });
  }
  std::string json = cf.json();
  json.replace(json.find("\"geometry\": \"cf.geo\", \"mesh_size\": {\"interface\": 1, \"far\": 2}"),
               std::string("\"geometry\": \"cf.geo\", \"mesh_size\": {\"interface\": 1, \"far\": 2}").size(),
               "\"mesh\": \"cf.msh\"");
  SceneFileBulk bulk(read_scene_spec(f.write("msh.json", json)));
  EXPECT_GT(bulk.meshes().bodies[0].num_nodes(), 4);
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  EXPECT_LT(jump_error(bulk, s.record, cf), 1e-9);
}

// The upper body held by contact alone, in layer mode: two floating bodies (the upper one and
// the layer) stacked on the supported lower one.
TEST(SceneClosedForm, BodyHeldByContactAloneLayerMode) {
  const ClosedForm cf;
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json(/*plus_supported=*/false))));
  double previous = INFINITY;
  for (double eps : {1e-1, 1e-2, 1e-3}) {
    const SceneFileScene s = solve_scene_file_layer(bulk, eps, SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << "eps " << eps << ": " << s.report.message;
    const double error = jump_error(bulk, s.record, cf);
    std::printf("closed form, upper body held by contact alone, layer mode at eps %g: max relative jump error %.3e\n",
                eps, error);
    EXPECT_LT(error, previous / 5) << "eps " << eps;
    previous = error;
  }
}

TEST(SceneJson, OverflowAndUnderflowNamed) {
  // nlohmann refuses an overflow itself, where the number ends.
  EXPECT_EQ(expect_input_error("{\"a\": [1,\n 1e999]}"), "s.json:2:6: number overflow parsing '1e999'");
  EXPECT_EQ(expect_input_error("{\"a\": 1e-400}"), "s.json:1:7: the number 1e-400 underflows a double");
  EXPECT_EQ(expect_input_error("{\"a\": 0.0e-400}"), "");  // a plain zero
}

// Bonded faces (SPEC §1.6): the same bondline at 21.8° under a uniform stress with tension across
// it (e > 0: σ_N = 12.3 daN/mm² > 0) and shear along it (σ_T = −4.2 daN/mm²). Both faces bonded,
// the limit law is the bilateral spring σ = −K [u] (K_N = λ̄ + 2μ̄, K_T = μ̄) for either sign of
// [u]_N, so the uniform state is exact: [u]_N = −σ_N/K_N < 0 (opening), [u]_T = −σ_T/K_T. The
// expected values are the closed form's, computed above from G, λ, μ and the angle.
ClosedForm bonded_tension() {
  ClosedForm cf;
  cf.e = 1e-3;
  cf.faces = "{\"plus\": \"bonded\", \"minus\": \"bonded\"}";
  return cf;
}

TEST(SceneBonded, LimitModeBilateralSpringCarriesTensionToRoundOff) {
  const ClosedForm cf = bonded_tension();
  ASSERT_GT(cf.sigma_N(), 0);  // tension across the bondline
  ASSERT_GT(std::abs(cf.sigma_T()), 0.1 * cf.sigma_N());
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json())));
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  EXPECT_TRUE(s.bondlines.at(0).law.bilateral);
  const double error = jump_error(bulk, s.record, cf);
  std::printf("bonded closed form, limit mode: max relative jump error %.3e (|[u]| = %.4e mm)\n", error, cf.Delta().norm());
  EXPECT_LT(error, 1e-9);
  const InterfaceFields& S = s.record.interfaces.at(0);
  for (Eigen::Index k = 0; k < S.sigma_N.size(); ++k) {
    EXPECT_NEAR(S.sigma_N[k], cf.sigma_N(), 1e-9 * cf.sigma_N());
    EXPECT_NEAR(S.sigma_T[k], cf.sigma_T(), 1e-9 * cf.sigma_N());
    EXPECT_NEAR(S.jump_N[k], cf.jump_N(), 1e-9 * cf.Delta().norm());
    EXPECT_NEAR(S.jump_T[k], cf.jump_T(), 1e-9 * cf.Delta().norm());
    EXPECT_LT(S.jump_N[k], 0);   // opening, and yet carrying the tension
    EXPECT_EQ(S.status[k], 2);   // a loaded bonded node is "stick", never "gap"
  }
  EXPECT_TRUE(s.carries_load);
}

// The meshed layer with both faces tied converges to the bilateral law at first order in ε
// (studies/convergence_rates.md, case d: O(ε) remainder): within 1 % of |[u]| at ε = 1e-2 and a
// factor ≥ 5 per decade below.
TEST(SceneBonded, LayerModeBondedLayerConvergesToTheBilateralJumps) {
  const ClosedForm cf = bonded_tension();
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json())));
  double previous = INFINITY;
  for (double eps : {1e-2, 1e-3, 1e-4}) {
    const SceneFileScene s = solve_scene_file_layer(bulk, eps, SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << "eps " << eps << ": " << s.report.message;
    const double error = jump_error(bulk, s.record, cf);
    std::printf("bonded closed form, layer mode at eps %g: max relative jump error %.3e\n", eps, error);
    EXPECT_LT(error, 1e-2) << "eps " << eps;
    EXPECT_LT(error, previous / 5) << "eps " << eps;
    previous = error;
    EXPECT_EQ(s.counts.combined.gap, 0);  // tension carried through both tied faces
  }
}

// The same tension with the paper's faces (contact on both): the bondline opens everywhere and
// carries nothing, which the scene says (carries_load false).
TEST(SceneBonded, ContactFacesOpenUnderTheSameTension) {
  ClosedForm cf = bonded_tension();
  cf.faces = "";
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json())));
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  EXPECT_EQ(s.limit.gap, static_cast<int>(s.record.interfaces.at(0).status.size()));
  EXPECT_FALSE(s.carries_load);
  for (Eigen::Index k = 0; k < s.record.interfaces.at(0).sigma_N.size(); ++k) {
    EXPECT_EQ(s.record.interfaces.at(0).sigma_N[k], 0.0);
    EXPECT_LT(s.record.interfaces.at(0).jump_N[k], 0.0);  // open
  }
}

// One face bonded, one in contact (SPEC §1.6): under tension the contact face opens and the layer
// hangs on its bonded face (held, not floating free: the solve converges).
TEST(SceneBonded, OneFaceBondedTheContactFaceOpens) {
  ClosedForm cf = bonded_tension();
  cf.faces = "{\"plus\": \"bonded\", \"minus\": \"contact\"}";
  Folder f;
  SceneFileBulk bulk(read_scene_spec(f.write_scene("cf", cf.geo(), cf.json())));
  const SceneFileScene s = solve_scene_file_layer(bulk, 1e-3, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  EXPECT_EQ(s.counts.minus_face.gap, static_cast<int>(s.record.interfaces.at(1).status.size()));  // S-: contact, open
  EXPECT_FALSE(s.carries_load);
  const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  EXPECT_FALSE(limit.bondlines.at(0).law.bilateral);  // one contact face: the Table 1 law
  EXPECT_FALSE(limit.carries_load);
}
