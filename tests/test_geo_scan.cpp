// The .geo scan (cases/scene/geo_scan.h) and the scene's sources (cases/scene/scene_sources.h):
// every statement of gmsh's language that runs, writes, stops or meshes is refused with its file
// and line; thinlayer reads every file gmsh would and refuses what it cannot check.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "cases/scene/geo_scan.h"
#include "cases/scene/json_positions.h"
#include "cases/scene/scene_sources.h"
#include "tests/error_message.h"

namespace {

namespace fs = std::filesystem;
using thinlayer::GeoReference;
using thinlayer::InputError;
using thinlayer::SceneSources;

// "" if the scan passes, else its message.
std::string scan(const std::string& text) {
  return message_of<InputError>([&] { thinlayer::scan_geo_text(text, "t.geo"); });
}

const char* const geometry =
    "SetFactory(\"Built-in\");\nh = 0.5; // the size\nPoint(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h};\n"
    "Line(1) = {1, 2};\nFor i In {1:3}\n  x~{i} = i;\nEndFor\nMesh.Algorithm = 6; Mesh.MeshSizeMax = 1;\n"
    "Geometry.Tolerance = 1e-9;\nTransfinite Curve{1} = 10;\nPhysical Curve(\"System\") = {1};\n"
    "Printf(\"length %g\", h);\n/* Save \"x.msh\"; System \"rm -rf /\"; */\nMacro M\n  y = 2;\nReturn\nCall M;\n";

TEST(GeoScan, GeometryVariablesLoopsMacrosAndMeshOptionsPass) { EXPECT_EQ(scan(geometry), ""); }

TEST(GeoScan, EveryStatementThatRunsWritesStopsOrMeshesIsRefusedWithItsLine) {
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
      {"If (0) Exit; EndIf", "'Exit'"},  // a branch never taken: still refused
      // gmsh's lexer reads "1e5" as a number and "System" as the keyword after it.
      {"x = 1e5System \"touch pwned\";", "'System' runs a command"},
      {"x = 2.5e-3Exit;", "'Exit' ends the process"},
  };
  for (const auto& [statement, why] : refused) {
    SCOPED_TRACE(statement);
    const std::string message = scan(std::string(geometry) + statement + "\n");
    EXPECT_EQ(message.rfind("t.geo:18: ", 0), 0u) << message;
    EXPECT_NE(message.find(why), std::string::npos) << message;
  }
}

// What a scene would learn of the machine it runs on (the user's environment, the file system,
// the machine's paths, clock and memory): refused, wherever it stands.
TEST(GeoScan, WhatReadsTheMachineIsRefusedWithItsLine) {
  const std::pair<const char*, const char*> refused[] = {
      {"Error(StrCat(\"x=\", GetEnv(\"TOKEN\")));", "'GetEnv' reads the user's environment"},
      {"x = GetEnv(\"HOME\") == \"\";", "'GetEnv' reads the user's environment"},
      {"If (FileExists(\"/etc/hostname\")) x = 1; EndIf", "'FileExists' probes the file system"},
      {"s = AbsolutePath(\"x\");", "'AbsolutePath' works on where files lie"},
      {"s = CurrentDir;", "'CurrentDir' works on where files lie"},
      {"s = CurrentDirectory;", "'CurrentDirectory' works on where files lie"},
      {"s = CurrentFileName;", "'CurrentFileName' works on where files lie"},
      {"s = DirName(\"/etc/passwd\");", "'DirName' works on where files lie"},
      {"s = FixRelativePath(\"x\");", "'FixRelativePath' works on where files lie"},
      {"s = GmshExecutableName;", "'GmshExecutableName' works on where files lie"},
      {"x = GetValue(\"x?\", 1);", "'GetValue' asks the terminal"},
      {"s = GetStringValue(\"x?\", \"a\");", "'GetStringValue' asks the terminal"},
      {"x = GetNumber(\"p\");", "'GetNumber' reads ONELAB parameters"},
      {"s = GetString(\"p\");", "'GetString' reads ONELAB parameters"},
      {"s = OnelabAction;", "'OnelabAction' reads ONELAB parameters"},
      {"s = Today;", "'Today' reads the machine's clock or memory"},
      {"x = Cpu;", "'Cpu' reads the machine's clock or memory"},
      {"x = Memory;", "'Memory' reads the machine's clock or memory"},
      {"x = TotalMemory;", "'TotalMemory' reads the machine's clock or memory"},
      {"If (0) x = TotalMemory; EndIf", "'TotalMemory'"},  // a branch never taken: still refused
  };
  for (const auto& [statement, why] : refused) {
    SCOPED_TRACE(statement);
    const std::string message = scan(std::string(geometry) + statement + "\n");
    EXPECT_EQ(message.rfind("t.geo:18: ", 0), 0u) << message;
    EXPECT_NE(message.find(why), std::string::npos) << message;
  }
  // In a string or a comment a word is only text.
  EXPECT_EQ(scan("Printf(\"GetEnv FileExists\");\n// GetEnv(\"TOKEN\")\n"), "");
}

// What gmsh's lexer reads otherwise than a text editor shows: refused.
TEST(GeoScan, ANulByteOrAStringGmshWouldCutIsRefused) {
  EXPECT_NE(scan(std::string("x = 1;\n// a comment\0 System \"touch pwned\";\n", 40)).find("t.geo:2: a NUL byte"),
            std::string::npos);
  EXPECT_EQ(scan("s = \"" + std::string(thinlayer::geo_string_max, 'a') + "\";\n"), "");
  EXPECT_NE(scan("s = \"" + std::string(thinlayer::geo_string_max + 1, 'a') + "\";\n")
                .find("t.geo:1: a string of 1024 bytes: gmsh reads at most 1023"),
            std::string::npos);
}

TEST(GeoScan, AnUnterminatedStringOrCommentIsRefused) {
  EXPECT_NE(scan("x = 1;\ny = \"open\n").find("t.geo:2: a string that never ends"), std::string::npos);
  EXPECT_NE(scan("/* open\n").find("t.geo:1: a comment that never ends"), std::string::npos);
}

TEST(GeoScan, TheFilesAScriptNamesAreReturned) {
  const auto references = thinlayer::scan_geo_text(
      "Include \"a.geo\";\nMerge \"m.msh\";\nv() = ListFromFile(\"l.txt\");\nShapeFromFile(\"s.brep\");\n", "t.geo");
  ASSERT_EQ(references.size(), 4u);
  EXPECT_EQ(references[0].kind, GeoReference::Include);
  EXPECT_EQ(references[0].name, "a.geo");
  EXPECT_EQ(references[1].kind, GeoReference::Merge);
  EXPECT_EQ(references[1].line, 2);
  EXPECT_EQ(references[2].kind, GeoReference::List);
  EXPECT_EQ(references[3].kind, GeoReference::Shape);
  EXPECT_EQ(references[3].name, "s.brep");
}

// A scene's folder of files, read as read_scene_sources reads them.
struct SceneSourcesTest : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("thinlayer-sources-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir / "scene"); }
  void TearDown() override { fs::remove_all(dir); }

  void write(const std::string& name, const std::string& text) {
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name, std::ios::binary) << text;
  }
  SceneSources read(const std::string& entry_text, bool mesh = false) {
    write(mesh ? "scene/t.msh" : "scene/t.geo", entry_text);
    return thinlayer::read_scene_sources((dir / "scene").string(), mesh ? "t.msh" : "t.geo", mesh, "s.json:3:5");
  }
  // "" if the sources are accepted, else the message.
  std::string refusal(const std::string& entry_text, bool mesh = false) {
    return message_of<InputError>([&] { read(entry_text, mesh); });
  }
};

TEST_F(SceneSourcesTest, ExactlyTheFilesTheGeometryReadsNoOptFile) {
  write("scene/t.geo.opt", "General.Terminal = 1;\n");  // gmsh merges it unasked; it is not staged
  write("scene/part.geo", "y = 2;\n");
  write("scene/sub/inner.geo", "z = 3;\nInclude \"../part.geo\";\n");
  const SceneSources s = read("Include \"part.geo\";\nInclude \"sub/inner.geo\";\nInclude \"sub/../part.geo\";\n");
  EXPECT_EQ(s.entry, "t.geo");
  std::vector<std::string> staged;
  for (const auto& f : s.files) staged.push_back(f.staged);
  EXPECT_EQ(staged, (std::vector<std::string>{"t.geo", "part.geo", "sub/inner.geo"}));
  EXPECT_EQ(s.folders, std::vector<std::string>{"sub"});
  EXPECT_EQ(s.files[1].bytes, "y = 2;\n");
  EXPECT_EQ(s.files[1].path, (dir / "scene/part.geo").string());
}

// Staged means scanned: a list (ListFromFile) is numbers for gmsh, scanned all the same.
TEST_F(SceneSourcesTest, AListIsScannedLikeAScript) {
  write("scene/nums.txt", "1 2 3.5e-1\n4\n");
  EXPECT_EQ(refusal("v() = ListFromFile(\"nums.txt\");\n"), "");
  write("scene/list.txt", "1 2\nSleep 6;\n");
  const std::string m = refusal("If (0) v() = ListFromFile(\"list.txt\"); EndIf\n");
  EXPECT_NE(m.find("list.txt:2: 'Sleep' stalls the run"), std::string::npos) << m;
  write("scene/nul.txt", std::string("1 2\0 3\n", 7));
  EXPECT_NE(refusal("v() = ListFromFile(\"nul.txt\");\n").find("nul.txt:1: a NUL byte"), std::string::npos);
}

// gmsh's merge-time side files (Common/OpenFile.cpp of gmsh 4.8 and 4.11, MergeFile: after
// merging any file F it merges F + ".opt" if stat() finds it; its only one). F is each file gmsh
// merges: the entry it opens (t.geo, or the scene's .msh), a Merge or MergeWithBoundingBox of a
// .geo, .msh, .step, .stp or .brep, and F.opt itself (F.opt.opt). Whatever statement names one of
// them, it is refused, never staged; core/mesh/meshing_child.h's box makes one inert besides
// (tests/test_meshing_child.cpp, ASideFileStagedAnywayIsInert).
TEST_F(SceneSourcesTest, NoSideFileOfAnyMergedFileIsStagedWhateverNamesIt) {
  write("scene/m.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  write("scene/g.geo", "x = 1;\n");
  write("scene/s.step", "ISO-10303-21;\n");
  write("scene/s.brep", "DBRep_DrawableShape\nCASCADE Topology V1\n");
  const std::string merged = "Merge \"m.msh\";\nMerge \"g.geo\";\nMerge \"s.step\";\nMergeWithBoundingBox \"s.brep\";\n";
  EXPECT_EQ(refusal(merged), "");  // the control: the merges themselves are accepted
  for (const char* side : {"t.geo.opt", "m.msh.opt", "g.geo.opt", "s.step.opt", "s.brep.opt", "t.geo.opt.opt"})
    for (const char* statement : {"Include \"%\";", "Merge \"%\";", "v() = ListFromFile(\"%\");",
                                  "ShapeFromFile(\"%\");", "If (0) v() = ListFromFile(\"%\"); EndIf"}) {
      std::string named = statement;
      named.replace(named.find('%'), 1, side);
      SCOPED_TRACE(named);
      write(std::string("scene/") + side, "Sleep 6;\n");
      const std::string m = refusal(merged + named + "\n");
      EXPECT_NE(m.find("t.geo:5: '"), std::string::npos) << m;
      EXPECT_NE(m.find("no file of a scene may end in .opt"), std::string::npos) << m;
    }
  // The scene's own geometry or mesh named *.opt.
  write("scene/x.geo.opt", "x = 1;\n");
  try {
    thinlayer::read_scene_sources((dir / "scene").string(), "x.geo.opt", false, "s.json:3:5");
    ADD_FAILURE() << "a geometry named *.opt was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no file of a scene may end in .opt"), std::string::npos) << e.what();
  }
}

TEST_F(SceneSourcesTest, AnIncludedScriptIsScannedInTurn) {
  write("scene/part.geo", "Point(1) = {0, 0, 0};\n\nSystem \"touch pwned\";\n");
  const std::string m = refusal("Include \"part.geo\";\n");
  EXPECT_NE(m.find("part.geo:3: 'System' runs a command"), std::string::npos) << m;
}

TEST_F(SceneSourcesTest, IncludeLoopsAreRefusedADiamondIsNot) {
  write("scene/loop.geo", "Include \"t.geo\";\n");
  EXPECT_NE(refusal("Include \"loop.geo\";\n").find("an include loop"), std::string::npos);
  EXPECT_NE(refusal("Include \"t.geo\";\n").find("an include loop"), std::string::npos);
  write("scene/a.geo", "Include \"d.geo\";\n");
  write("scene/b.geo", "Include \"d.geo\";\n");
  write("scene/d.geo", "x = 1;\n");
  EXPECT_EQ(refusal("Include \"a.geo\";\nInclude \"b.geo\";\n"), "");
}

TEST_F(SceneSourcesTest, AMeshMustBeginWithMeshFormat) {
  const std::string script = "System \"touch pwned\";\nSleep 1e7;\n";
  EXPECT_NE(refusal(script, /*mesh=*/true).find("t.msh:1: a mesh file that does not begin with $MeshFormat"),
            std::string::npos);
  EXPECT_EQ(refusal("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n", /*mesh=*/true), "");
  write("scene/data.msh", script);
  EXPECT_NE(refusal("Merge \"data.msh\";\n").find("data.msh:1: a mesh file that does not begin with $MeshFormat"),
            std::string::npos);
}

TEST_F(SceneSourcesTest, AMergeOfAnExtensionGmshReadsAnotherWayIsRefused) {
  for (const char* name : {"x.Msh", "x.xao", "x.inp", "x.Step", "x.msh.gz", "x.pos", "x"}) {
    SCOPED_TRACE(name);
    write(std::string("scene/") + name, "$MeshFormat\n");
    const std::string m = refusal(std::string("Merge \"") + name + "\";\n");
    EXPECT_NE(m.find("t.geo:1: 'Merge' of \"" + std::string(name) + "\""), std::string::npos) << m;
    EXPECT_NE(m.find("a reader thinlayer cannot check"), std::string::npos) << m;
  }
  write("scene/s.step", "not a STEP file\n");
  EXPECT_NE(refusal("Merge \"s.step\";\n").find("s.step:1: not a STEP file"), std::string::npos);
  write("scene/s.step", "ISO-10303-21;\nHEADER;\n");
  EXPECT_EQ(refusal("Merge \"s.step\";\n"), "");
}

TEST_F(SceneSourcesTest, NamesGmshReadsOtherwiseAreRefused) {
  write("scene/sub/inc.geo", "x = 1;\n");
  write("outside.geo", "x = 1;\n");
  EXPECT_NE(refusal("Include \"sub\\inc.geo\";\n").find("holding a backslash"), std::string::npos);
  EXPECT_NE(refusal("Include \"/etc/passwd\";\n").find("an absolute file name"), std::string::npos);
  EXPECT_NE(refusal("Include \"C:/x.geo\";\n").find("an absolute file name"), std::string::npos);
  EXPECT_NE(refusal("Include \"../outside.geo\";\n").find("outside the scene's folder"), std::string::npos);
  EXPECT_NE(refusal("Include \"sub/../../outside.geo\";\n").find("outside the scene's folder"), std::string::npos);
  EXPECT_NE(refusal("Include \"\";\n").find("an empty file name"), std::string::npos);
  EXPECT_NE(refusal("Include \"sub/\";\n").find("names a folder"), std::string::npos);
  fs::create_symlink(dir / "outside.geo", dir / "scene/link.geo");
  EXPECT_NE(refusal("Include \"link.geo\";\n").find("a link to a file outside the scene's folder"), std::string::npos);
}

TEST_F(SceneSourcesTest, WhatIsNoRegularFileIsRefusedAtOnce) {
  ASSERT_EQ(::mkfifo((dir / "scene/fifo.geo").c_str(), 0600), 0);
  EXPECT_NE(refusal("Include \"fifo.geo\";\n").find("is a FIFO"), std::string::npos);  // a read would wait for ever
  EXPECT_NE(refusal("Merge \"fifo.geo\";\n").find("is a FIFO"), std::string::npos);
  fs::create_directories(dir / "scene/folder.geo");
  EXPECT_NE(refusal("Include \"folder.geo\";\n").find("is a folder"), std::string::npos);
  EXPECT_NE(refusal("Include \"missing.geo\";\n").find("No such file"), std::string::npos);
}

TEST_F(SceneSourcesTest, ScriptsAreBounded) {
  EXPECT_NE(refusal(std::string(thinlayer::max_script_bytes + 1, ';')).find("larger than 4 MiB"), std::string::npos);
  EXPECT_NE(refusal("$MeshFormat\n").find("t.geo:1: a script that begins with '$'"), std::string::npos);
}

}  // namespace
