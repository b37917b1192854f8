// The .geo scan (cases/scene/geo_scan.h): every statement of gmsh's language that runs,
// writes, stops or meshes is refused with its file and line; geometry passes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cases/scene/geo_scan.h"
#include "cases/scene/json_positions.h"

namespace {

namespace fs = std::filesystem;

struct GeoScan : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("thinlayer-geo-scan-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir / "scene"); }
  void TearDown() override { fs::remove_all(dir); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  }
  // "" if the scan passes, else its message.
  std::string scan(const std::string& text) {
    const fs::path geo = write("scene/t.geo", text);
    try {
      thinlayer::scan_geo(geo.string(), (dir / "scene").string());
    } catch (const thinlayer::InputError& e) {
      return e.what();
    }
    return "";
  }
};

const char* const geometry =
    "SetFactory(\"Built-in\");\nh = 0.5; // the size\nPoint(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h};\n"
    "Line(1) = {1, 2};\nFor i In {1:3}\n  x~{i} = i;\nEndFor\nMesh.Algorithm = 6; Mesh.MeshSizeMax = 1;\n"
    "Geometry.Tolerance = 1e-9;\nTransfinite Curve{1} = 10;\nPhysical Curve(\"System\") = {1};\n"
    "Printf(\"length %g\", h);\n/* Save \"x.msh\"; System \"rm -rf /\"; */\nMacro M\n  y = 2;\nReturn\nCall M;\n";

TEST_F(GeoScan, GeometryVariablesLoopsMacrosAndMeshOptionsPass) { EXPECT_EQ(scan(geometry), ""); }

TEST_F(GeoScan, EveryStatementThatRunsWritesStopsOrMeshesIsRefusedWithItsLine) {
  const std::pair<const char*, const char*> refused[] = {
      {"System \"touch pwned\";", "'System' runs a command"},
      {"SystemCall \"touch pwned\";", "'SystemCall' runs a command"},
      {"NonBlockingSystemCall \"touch pwned\";", "runs a command"},
      {"OnelabRun(\"x\", \"y\");", "'OnelabRun' runs a command"},
      {"Plugin(CutPlane).Run;", "'Plugin' runs a gmsh plugin"},
      {"Sleep 100;", "'Sleep' stalls the run"},
      {"Save \"/tmp/any.msh\";", "'Save' writes a file"},
      {"Print \"x.png\";", "'Print' writes a file"},
      {"CreateDir \"d\";", "'CreateDir' writes a file"},
      {"Printf(\"x\") > \"/any/path\";", "'Printf(...) >' writes a file"},
      {"Printf(\"x %g\", 1) >> \"/any/path\";", "'Printf(...) >' writes a file"},
      {"Exit;", "'Exit' ends the process"},
      {"Abort;", "'Abort' stops reading"},
      {"Mesh 2;", "'Mesh' meshes inside the script"},
      {"RefineMesh;", "'RefineMesh' meshes inside the script"},
      {"SetOrder 2;", "'SetOrder' meshes inside the script"},
      {"General.Terminal = 1;", "'General' sets gmsh's process-wide options"},
      {"Solver.Executable0 = \"sh\";", "'Solver' sets gmsh's process-wide options"},
      {"SetString(\"Solver.Executable0\", \"sh\");", "'SetString' sets ONELAB parameters"},
      {"S2N[\"System\"] \"touch pwned\";", "'S2N' builds a name at run time"},
      {"Include StrCat(\"a\", \".geo\");", "'Include' takes a file name in quotes"},
      {"Include \"../outside.geo\";", "a file outside the scene's folder"},
      {"Include \"/etc/passwd\";", "a file outside the scene's folder"},
      {"Merge \"../outside.step\";", "a file outside the scene's folder"},
      {"a() = ListFromFile(\"/etc/hostname\");", "a file outside the scene's folder"},
      {"If (0) Exit; EndIf", "'Exit'"},  // a branch never taken: still refused
  };
  for (const auto& [statement, why] : refused) {
    SCOPED_TRACE(statement);
    const std::string message = scan(std::string(geometry) + statement + "\n");
    EXPECT_NE(message.find((dir / "scene/t.geo").string() + ":18: "), std::string::npos) << message;
    EXPECT_NE(message.find(why), std::string::npos) << message;
  }
}

TEST_F(GeoScan, IncludedScriptsAreScannedInTurn) {
  write("scene/part.geo", "Point(1) = {0, 0, 0};\n\nSystem \"touch pwned\";\n");
  write("scene/data.msh", "System \"not a script: a mesh\"\n");
  EXPECT_EQ(scan("Merge \"data.msh\";\n"), "");
  const std::string message = scan("Include \"part.geo\";\n");
  EXPECT_NE(message.find("part.geo:3: 'System' runs a command"), std::string::npos) << message;
  write("scene/loop.geo", "Include \"loop.geo\";\n");  // includes itself: scanned once
  EXPECT_EQ(scan("Include \"loop.geo\";\n"), "");
  // A symbolic link inside the folder to a file outside it is outside.
  write("elsewhere.geo", "Point(1) = {0, 0, 0};\n");
  fs::create_symlink(dir / "elsewhere.geo", dir / "scene/link.geo");
  EXPECT_NE(scan("Include \"link.geo\";\n").find("outside the scene's folder"), std::string::npos);
}

TEST_F(GeoScan, AnUnterminatedStringOrCommentIsRefused) {
  EXPECT_NE(scan("x = 1;\ny = \"open\n").find("t.geo:2: a string that never ends"), std::string::npos);
  EXPECT_NE(scan("/* open\n").find("t.geo:1: a comment that never ends"), std::string::npos);
}

}  // namespace
