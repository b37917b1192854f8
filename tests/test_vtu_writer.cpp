// write_vtu and `thinlayer solve --vtu`: the file reads back (points, cells, displacement,
// interface fields, scene attributes), and a failed write leaves nothing behind.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "core/io/h5_reader.h"
#include "tests/text_file.h"
#include "core/io/vtu_writer.h"

namespace thinlayer {
namespace {

namespace fs = std::filesystem;

// --- A minimal reader for the few things the tests look at --------------------------------

// The value of attribute `name` in the first `<tag ...>` of the file.
std::string tag_attribute(const std::string& xml, const std::string& tag, const std::string& name) {
  const std::size_t start = xml.find("<" + tag + " ");
  if (start == std::string::npos) throw std::runtime_error("no <" + tag + ">");
  const std::size_t end = xml.find('>', start);
  const std::size_t at = xml.find(" " + name + "=\"", start);
  if (at == std::string::npos || at > end) throw std::runtime_error("no " + name + " in <" + tag + ">");
  const std::size_t value = at + name.size() + 3;
  return xml.substr(value, xml.find('"', value) - value);
}

// The numbers of the DataArray whose opening tag holds `key` (e.g. Name="displacement").
std::vector<double> array_values(const std::string& xml, const std::string& key, std::string* opening = nullptr) {
  const std::size_t at = xml.find(key);
  if (at == std::string::npos) throw std::runtime_error("no DataArray with " + key);
  const std::size_t start = xml.rfind("<DataArray", at);
  const std::size_t body = xml.find('>', at) + 1;
  const std::size_t end = xml.find("</DataArray>", body);
  if (opening) *opening = xml.substr(start, body - start);
  std::istringstream in(xml.substr(body, end - body));
  std::vector<double> values;
  for (double v; in >> v;) values.push_back(v);
  return values;
}

std::vector<double> named(const std::string& xml, const std::string& name, std::string* opening = nullptr) {
  return array_values(xml, "Name=\"" + name + "\"", opening);
}

std::string vtk_string(const std::vector<double>& codes) {
  std::string s;
  for (double c : codes)
    if (c != 0) s += static_cast<char>(c);
  return s;
}

// --- The scene: two unit quads side by side, an interface along their bottom ---------------
//   3 --- 4 --- 5
//   |  0  |  1  |
//   0 --- 1 --- 2      (mm)
SceneRecord two_quads() {
  SceneRecord s;
  s.id = "two-quads";
  s.nodes.resize(6, 2);
  s.nodes << 0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1;
  s.cells.resize(2, 4);
  s.cells << 0, 1, 4, 3, 1, 2, 5, 4;
  s.u.resize(6, 2);
  for (int n = 0; n < 6; ++n) {
    s.u(n, 0) = 0.1 * n + 1.0 / 3.0;  // not short in decimal: checks the round trip
    s.u(n, 1) = -1e-7 * n;
  }
  InterfaceFields f;
  f.name = "S";
  f.x.resize(3, 2);
  f.x << 0, 0, 1, 0, 2, 0;
  f.normal.resize(3, 2);
  f.normal << 0, 1, 0, 1, 0, 1;
  f.length = Eigen::Vector3d(0.5, 1, 0.5);
  f.jump_N = Eigen::Vector3d(-0.0, 1e-3, 2e-3);
  f.jump_T = Eigen::Vector3d(1, 2, 3);
  f.sigma_N = Eigen::Vector3d(0, -5.5, -7.25);
  f.sigma_T = Eigen::Vector3d(0, 5.5, 1);
  f.status = {0, 1, 2};
  s.interfaces.push_back(f);
  s.text["case"] = "bar";
  s.text["mode"] = "limit";
  s.numbers["eps"] = 0;
  s.numbers["friction"] = 0.5;
  s.numbers["lambda_bar"] = std::numeric_limits<double>::infinity();  // Signorini: legitimate
  s.integers["iterations"] = 7;
  s.reactions["D"] = Eigen::Vector2d(1.5, -2);
  return s;
}

class VtuWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("thinlayer_vtu_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  bool dir_empty() const { return fs::is_empty(dir_); }
  fs::path dir_;
};

TEST_F(VtuWriter, TwoQuadsReadBack) {
  const SceneRecord scene = two_quads();
  write_vtu(file("s.vtu"), scene);
  const std::string xml = read_text_file(file("s.vtu"));
  EXPECT_EQ(xml.rfind("<?xml", 0), 0u);
  EXPECT_EQ(tag_attribute(xml, "VTKFile", "type"), "UnstructuredGrid");
  EXPECT_EQ(tag_attribute(xml, "Piece", "NumberOfPoints"), "6");
  EXPECT_EQ(tag_attribute(xml, "Piece", "NumberOfCells"), "2");

  const std::size_t points = xml.find("<Points>");
  ASSERT_NE(points, std::string::npos);
  const auto xyz = array_values(xml.substr(points), "NumberOfComponents=\"3\"");
  ASSERT_EQ(xyz.size(), 18u);
  for (int n = 0; n < 6; ++n) {
    EXPECT_EQ(xyz[3 * n], scene.nodes(n, 0));
    EXPECT_EQ(xyz[3 * n + 1], scene.nodes(n, 1));
    EXPECT_EQ(xyz[3 * n + 2], 0.0);
  }
  EXPECT_EQ(named(xml, "connectivity"), (std::vector<double>{0, 1, 4, 3, 1, 2, 5, 4}));
  EXPECT_EQ(named(xml, "offsets"), (std::vector<double>{4, 8}));
  EXPECT_EQ(named(xml, "types"), (std::vector<double>{9, 9}));  // VTK_QUAD

  std::string opening;
  const auto u = named(xml, "displacement", &opening);
  EXPECT_NE(opening.find("NumberOfComponents=\"3\""), std::string::npos) << opening;
  ASSERT_EQ(u.size(), 18u);
  for (int n = 0; n < 6; ++n) {
    EXPECT_EQ(u[3 * n], scene.u(n, 0)) << n;  // exact: shortest round-trip formatting
    EXPECT_EQ(u[3 * n + 1], scene.u(n, 1)) << n;
    EXPECT_EQ(u[3 * n + 2], 0.0);
  }
}

TEST_F(VtuWriter, InterfaceFieldsSitOnTheirNodes) {
  write_vtu(file("s.vtu"), two_quads());
  const std::string xml = read_text_file(file("s.vtu"));
  EXPECT_EQ(named(xml, "on_interface_S"), (std::vector<double>{1, 1, 1, 0, 0, 0}));
  EXPECT_EQ(named(xml, "S_sigma_N"), (std::vector<double>{0, -5.5, -7.25, 0, 0, 0}));
  EXPECT_EQ(named(xml, "S_sigma_T"), (std::vector<double>{0, 5.5, 1, 0, 0, 0}));
  EXPECT_EQ(named(xml, "S_jump_N"), (std::vector<double>{0, 1e-3, 2e-3, 0, 0, 0}));
  EXPECT_EQ(named(xml, "S_jump_T"), (std::vector<double>{1, 2, 3, 0, 0, 0}));
  EXPECT_EQ(named(xml, "S_length"), (std::vector<double>{0.5, 1, 0.5, 0, 0, 0}));
  EXPECT_EQ(named(xml, "S_status"), (std::vector<double>{0, 1, 2, -1, -1, -1}));
  EXPECT_EQ(named(xml, "S_normal"), (std::vector<double>{0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0}));
}

TEST_F(VtuWriter, SceneAttributesAreFieldData) {
  write_vtu(file("s.vtu"), two_quads());
  const std::string xml = read_text_file(file("s.vtu"));
  std::string opening;
  EXPECT_EQ(vtk_string(named(xml, "scene_id", &opening)), "two-quads");
  EXPECT_NE(opening.find("type=\"String\""), std::string::npos) << opening;
  EXPECT_EQ(vtk_string(named(xml, "case")), "bar");
  EXPECT_EQ(named(xml, "friction", &opening), (std::vector<double>{0.5}));
  EXPECT_NE(opening.find("type=\"Float64\""), std::string::npos) << opening;
  EXPECT_NE(opening.find("NumberOfTuples=\"1\""), std::string::npos) << opening;
  EXPECT_EQ(vtk_string(named(xml, "lambda_bar", &opening)), "inf");  // ASCII VTK has no Float64 inf
  EXPECT_NE(opening.find("type=\"String\""), std::string::npos) << opening;
  EXPECT_EQ(named(xml, "iterations", &opening), (std::vector<double>{7}));
  EXPECT_NE(opening.find("type=\"Int64\""), std::string::npos) << opening;
  EXPECT_EQ(named(xml, "reaction_D"), (std::vector<double>{1.5, -2}));
}

TEST_F(VtuWriter, TrianglesAndAPaddedMixedTable) {
  SceneRecord scene = two_quads();
  scene.cells << 0, 1, 4, 3, 1, 2, 5, -1;  // a quad, then a triangle padded to 4 columns
  write_vtu(file("mixed.vtu"), scene);
  std::string xml = read_text_file(file("mixed.vtu"));
  EXPECT_EQ(named(xml, "connectivity"), (std::vector<double>{0, 1, 4, 3, 1, 2, 5}));
  EXPECT_EQ(named(xml, "offsets"), (std::vector<double>{4, 7}));
  EXPECT_EQ(named(xml, "types"), (std::vector<double>{9, 5}));  // VTK_QUAD, VTK_TRIANGLE

  scene.cells.resize(4, 3);
  scene.cells << 0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4;
  write_vtu(file("p1.vtu"), scene);
  xml = read_text_file(file("p1.vtu"));
  EXPECT_EQ(tag_attribute(xml, "Piece", "NumberOfCells"), "4");
  EXPECT_EQ(named(xml, "offsets"), (std::vector<double>{3, 6, 9, 12}));
  EXPECT_EQ(named(xml, "types"), (std::vector<double>{5, 5, 5, 5}));
}

TEST_F(VtuWriter, UnwritableDirectoryThrowsNamingThePathAndLeavesNothing) {
  const std::string target = file("missing-dir/s.vtu");
  try {
    write_vtu(target, two_quads());
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(target), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_vtu_target(target), std::runtime_error);
  EXPECT_THROW(write_vtu(dir_.string(), two_quads()), std::runtime_error);  // a directory
  EXPECT_TRUE(dir_empty());
  check_vtu_target(file("s.vtu"));  // a writable target: no error, and nothing left behind
  EXPECT_TRUE(dir_empty());
}

TEST_F(VtuWriter, NonFiniteValuesThrowAndLeaveNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto u_nan = [&](SceneRecord& s) { s.u(4, 1) = nan; };
  auto u_inf = [&](SceneRecord& s) { s.u(0, 0) = -inf; };
  auto node_nan = [&](SceneRecord& s) { s.nodes(5, 0) = nan; };
  auto sigma_nan = [&](SceneRecord& s) { s.interfaces[0].sigma_N[1] = nan; };
  auto number_nan = [&](SceneRecord& s) { s.numbers["residual"] = nan; };
  auto reaction_inf = [&](SceneRecord& s) { s.reactions["D"].x() = inf; };
  for (const auto& spoil : std::vector<std::function<void(SceneRecord&)>>{u_nan, u_inf, node_nan, sigma_nan, number_nan,
                                                                          reaction_inf}) {
    SceneRecord scene = two_quads();
    spoil(scene);
    EXPECT_THROW(write_vtu(file("s.vtu"), scene), std::runtime_error);
    EXPECT_TRUE(dir_empty());
  }
}

TEST_F(VtuWriter, FailedWriteKeepsThePreviousFile) {
  {
    std::ofstream(file("s.vtu")) << "previous";
  }
  SceneRecord scene = two_quads();
  scene.u(2, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(write_vtu(file("s.vtu"), scene), std::runtime_error);
  EXPECT_EQ(read_text_file(file("s.vtu")), "previous");
  write_vtu(file("s.vtu"), two_quads());  // a good write replaces it
  EXPECT_EQ(tag_attribute(read_text_file(file("s.vtu")), "Piece", "NumberOfPoints"), "6");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);
}

TEST_F(VtuWriter, InconsistentScenesThrow) {
  auto bad_node = [](SceneRecord& s) { s.cells(1, 2) = 6; };
  auto two_node_cell = [](SceneRecord& s) { s.cells.row(1) << 1, 2, -1, -1; };
  auto short_u = [](SceneRecord& s) { s.u.conservativeResize(5, 2); };
  auto short_field = [](SceneRecord& s) { s.interfaces[0].status.pop_back(); };
  auto off_mesh = [](SceneRecord& s) { s.interfaces[0].x(1, 1) = 0.5; };
  for (const auto& spoil : std::vector<std::function<void(SceneRecord&)>>{bad_node, two_node_cell, short_u, short_field,
                                                                          off_mesh}) {
    SceneRecord scene = two_quads();
    spoil(scene);
    EXPECT_THROW(write_vtu(file("s.vtu"), scene), std::runtime_error);
    EXPECT_TRUE(dir_empty());
  }
}

// --- thinlayer solve --vtu -------------------------------------------------------------------

struct CliRun {
  int status = 0;
  std::string out, err;
};

// Runs in `scratch`, where its standard output and error are kept until read.
CliRun run_cli(const std::string& arguments, const fs::path& scratch) {
  const fs::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const std::string command = "cd " + scratch.string() + " && " + std::string(THINLAYER_CLI) + " " + arguments + " >" +
                              out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  CliRun r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text_file(out), read_text_file(err)};
  fs::remove(out);
  fs::remove(err);
  return r;
}

int count_equal(const std::vector<double>& v, double x) { return static_cast<int>(std::count(v.begin(), v.end(), x)); }

TEST_F(VtuWriter, CliWritesTheBarScene) {
  const fs::path vtu = dir_ / "row4.vtu";
  const CliRun r = run_cli("solve --case bar --row 4 --vtu " + vtu.string(), dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + vtu.string()), std::string::npos) << r.out;
  const std::string xml = read_text_file(vtu);
  EXPECT_EQ(tag_attribute(xml, "Piece", "NumberOfPoints"), "1089");  // 33 x 33 nodes
  EXPECT_EQ(tag_attribute(xml, "Piece", "NumberOfCells"), "1024");   // 32 x 32 Q1
  EXPECT_EQ(named(xml, "types"), std::vector<double>(1024, 9));
  EXPECT_EQ(named(xml, "displacement").size(), 3u * 1089);
  EXPECT_EQ(count_equal(named(xml, "on_interface_S"), 1), 32);  // AD without D, on the bar only
  EXPECT_EQ(count_equal(named(xml, "S_status"), 2), 32);        // Table 3 row 4: 32 stick
  EXPECT_EQ(vtk_string(named(xml, "law_case")), "table3-row-4");
  EXPECT_EQ(named(xml, "converged"), (std::vector<double>{1}));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1);  // no temporary left
}

TEST_F(VtuWriter, CliPutsEachLayerFaceOnTheNodesOfBothItsBodies) {
  const fs::path vtu = dir_ / "layer.vtu", h5 = dir_ / "layer.h5";
  const CliRun r = run_cli("solve --case dovetail --mode layer --law-case d --eps 1e-3 --h-interface 0.05 --h-far 0.2 "
                           "--out " + h5.string() + " --vtu " + vtu.string(), dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string xml = read_text_file(vtu);
  const H5Reader scene(h5.string());
  const std::string g = "/scenes/" + scene.children("/scenes").at(0);
  for (const std::string face : {"S+", "S-"}) {
    std::vector<std::size_t> shape;
    scene.read_doubles(g + "/interface/" + face + "/x", &shape);
    const int points = static_cast<int>(shape.at(0));
    EXPECT_GT(points, 0) << face;
    // Each point of a face joins two meshed bodies (tenon/layer, layer/base): two nodes.
    EXPECT_EQ(count_equal(named(xml, "on_interface_" + face), 1), 2 * points) << face;
    const auto status = named(xml, face + "_status");
    EXPECT_EQ(count_equal(status, 0) + count_equal(status, 1) + count_equal(status, 2), 2 * points) << face;
  }
  const auto combined = named(xml, "combined_status");
  EXPECT_EQ(combined.size(), std::stoul(tag_attribute(xml, "Piece", "NumberOfPoints")));
  EXPECT_GT(count_equal(combined, -1), 0);
}

TEST_F(VtuWriter, CliBadVtuTargetIsAnErrorBeforeAnyWork) {
  const std::string target = (dir_ / "missing-dir" / "s.vtu").string();
  CliRun r = run_cli("solve --case bar --row 4 --vtu " + target, dir_);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find(target), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("residual"), std::string::npos) << "solved before failing:\n" << r.out;
  EXPECT_TRUE(dir_empty());

  const std::string same = (dir_ / "s").string();
  r = run_cli("solve --case bar --row 4 --out " + same + " --vtu " + same, dir_);
  EXPECT_EQ(r.status, 2) << r.err;
  r = run_cli("solve --case bar --row 4 --out s --vtu ./s", dir_);  // relative to the current directory
  EXPECT_EQ(r.status, 2) << r.err;
  r = run_cli("solve --case bar --row 9 --vtu " + (dir_ / "s.vtu").string(), dir_);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(dir_empty());
}

}  // namespace
}  // namespace thinlayer
