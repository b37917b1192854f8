// The confined meshing child (core/mesh/meshing_child.h): what gmsh's failures become, and
// what the child cannot do whatever a script asks of it.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <memory>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gmsh.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/stat.h>

#include "core/mesh/gmsh_session.h"
#include "core/mesh/mesh_bytes.h"
#include "core/mesh/meshing_child.h"
#include "core/mesh/private_root.h"
#include "core/mesh/read_box.h"
#include "tests/error_message.h"
#include "core/mesh/staging_folder.h"

extern char** environ;

namespace {

using thinlayer::MeshingChildError;
using thinlayer::MeshingChildLimits;
using thinlayer::meshing_phase;
using thinlayer::run_bounded;
using thinlayer::run_in_meshing_child;

namespace fs = std::filesystem;

// The message of the MeshingChildError that running `work` throws ("" if none).
std::string failure(const std::function<std::string()>& work, const MeshingChildLimits& limits = {}) {
  return message_of<MeshingChildError>([&] { run_in_meshing_child(work, limits); });
}

TEST(MeshingChild, HandsBackWhatTheWorkReturns) {
  std::string big(1 << 20, 'x');  // more than a pipe holds at once
  big[12345] = '\0';
  EXPECT_EQ(run_in_meshing_child([&] { return big; }), big);
}

TEST(MeshingChild, AnExceptionComesBackAsItsMessage) {
  EXPECT_EQ(failure([]() -> std::string { throw std::runtime_error("no surface"); }), "no surface");
  EXPECT_EQ(failure([]() -> std::string { throw std::string("Unknown entity"); }), "gmsh: Unknown entity");
  try {
    run_in_meshing_child([]() -> std::string { throw std::invalid_argument("bad group"); });
    FAIL();
  } catch (const MeshingChildError& e) {
    EXPECT_TRUE(e.input);
  }
}

// gmsh's errors inside its OpenMP regions reach std::terminate (the caller never sees them).
TEST(MeshingChild, AnExceptionThatTerminatesComesBackAsItsMessage) {
  EXPECT_EQ(failure([]() -> std::string {
              [] () noexcept { throw std::string("Mesh size too small"); }();
              return "";
            }),
            "gmsh: Mesh size too small");
}

TEST(MeshingChild, ACrashIsAMessage) {
  EXPECT_EQ(failure([]() -> std::string {
              std::raise(SIGSEGV);
              return "";
            }),
            "gmsh crashed (Segmentation fault)");
  EXPECT_NE(failure([]() -> std::string { std::_Exit(0); }).find("ended without a mesh"), std::string::npos);
}

TEST(MeshingChild, LimitsAreMessages) {
  MeshingChildLimits limits;
  limits.cpu_limit_s = 1;
  EXPECT_NE(failure([]() -> std::string {
              for (volatile unsigned long i = 0;; ++i) {
              }
            }, limits).find("CPU time limit (1 s"), std::string::npos);
  limits = {};
  limits.memory_limit_bytes = 1LL << 30;
  EXPECT_NE(failure([]() -> std::string {
              std::vector<char> v(2LL << 30, 1);
              return std::string(v.data(), 1);
            }, limits).find("memory limit (1 GiB)"), std::string::npos);
}

TEST(MeshingChild, AFailureNamesThePhaseItEndedIn) {
  EXPECT_EQ(failure([]() -> std::string {
              meshing_phase("meshing");
              std::raise(SIGSEGV);
              return "";
            }),
            "gmsh crashed (Segmentation fault) while meshing");
}

// A Sleep, a read that waits: no CPU is spent, only the wall clock stops it.
TEST(MeshingChild, TheWallClockStopsAChildThatWaits) {
  MeshingChildLimits limits;
  limits.wall_limit_s = 1;
  const auto start = std::chrono::steady_clock::now();
  const std::string message = failure([]() -> std::string {
    meshing_phase("reading the geometry");
    ::sleep(60);
    return "";
  }, limits);
  EXPECT_EQ(message, "gmsh did not finish within the wall-clock limit of 1 s (--mesh-timeout) while reading the "
                     "geometry; a loop in the geometry?");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30);  // not the 60 s
}

// A step bounded tighter than the child (the mesh estimate): its own message, as an input error.
TEST(MeshingChild, ABoundedStepEndsWithItsOwnMessage) {
  try {
    run_in_meshing_child([] {
      run_bounded("estimating", 64LL << 20, 30, "the estimate needs too much", [] {
        std::vector<char> v(1LL << 30, 1);
        (void)v;
      });
      return std::string();
    });
    FAIL() << "no error";
  } catch (const MeshingChildError& e) {
    EXPECT_EQ(std::string(e.what()), "the estimate needs too much");
    EXPECT_TRUE(e.input);
  }
  EXPECT_EQ(failure([] {
              run_bounded("estimating", 1LL << 30, 1, "the estimate takes too long", [] { ::sleep(60); });
              return std::string();
            }),
            "the estimate takes too long");
  // Outside a meshing child the step just runs.
  int ran = 0;
  run_bounded("estimating", 1, 1, "never", [&] { ++ran; });
  EXPECT_EQ(ran, 1);
}

// The read box (core/mesh/read_box.h): only the staging folder can be read.
TEST(MeshingChild, ReadsNothingOutsideItsFolderWhereTheKernelHasLandlock) {
  if (thinlayer::landlock_abi() == 0) GTEST_SKIP() << "no Landlock in this kernel: the box is the staging folder only";
  const fs::path dir = fs::temp_directory_path() / ("thinlayer-box-" + std::to_string(::getpid()));
  fs::create_directories(dir / "staged");
  std::ofstream(dir / "staged" / "inside.geo") << "x = 1;\n";
  std::ofstream(dir / "outside.txt") << "secret\n";
  MeshingChildLimits limits;
  limits.read_folder = (dir / "staged").string();
  const std::string answer = run_in_meshing_child([&] {
    std::string what;
    what += ::open("inside.geo", O_RDONLY) >= 0 ? "read inside;" : "cannot read inside;";  // its working directory
    what += ::open((dir / "outside.txt").c_str(), O_RDONLY) >= 0 ? "read outside;" : "";
    what += ::open("/etc/hostname", O_RDONLY) >= 0 ? "read /etc;" : "";
    what += ::open("../outside.txt", O_RDONLY) >= 0 ? "read ..;" : "";
    return what;
  }, limits);
  EXPECT_EQ(answer, "read inside;");
  fs::remove_all(dir);
}

// The child's answer is read back with every count checked: a count beyond the bytes sent is
// refused before anything is allocated (a child running gmsh on a user's file is not trusted).
TEST(MeshingChild, ABrokenAnswerIsRefusedNotAllocated) {
  thinlayer::ByteWriter w;
  thinlayer::put(w, std::uint64_t{1} << 60);  // a vector "of 2^60 elements", then nothing
  const std::string bytes = w.take();
  thinlayer::ByteReader r(bytes);
  std::vector<double> v;
  EXPECT_THROW(thinlayer::get(r, v), std::runtime_error);
  thinlayer::ByteWriter m;
  thinlayer::Mesh mesh;
  mesh.nodes.resize(1, 2);
  mesh.nodes << 0, 0;
  mesh.quads = {{0, 0, 0, 7}};  // node 7 of 1
  thinlayer::put(m, mesh);
  const std::string mesh_bytes = m.take();
  thinlayer::ByteReader mr(mesh_bytes);
  thinlayer::Mesh back;
  EXPECT_THROW(thinlayer::get(mr, back), std::runtime_error);
}

// What a script could ask of gmsh: each attempt fails inside the child, nothing appears outside.
TEST(MeshingChild, CannotRunAProgramOrWriteAFile) {
  const fs::path dir = fs::temp_directory_path() / ("thinlayer-child-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "existing.txt") << "the user's file\n";
  const std::string answer = run_in_meshing_child([&] {
    std::string what;
    what += std::system(("touch " + (dir / "by_system").string()).c_str()) == 0 ? "system ran;" : "";
    what += ::fork() >= 0 ? "forked;" : "";
    what += ::open((dir / "new.txt").c_str(), O_WRONLY | O_CREAT, 0666) >= 0 ? "created;" : "";
    what += ::open((dir / "existing.txt").c_str(), O_WRONLY | O_TRUNC) >= 0 ? "truncated;" : "";
    what += ::open((dir / "existing.txt").c_str(), O_RDWR) >= 0 ? "opened for writing;" : "";
    what += ::unlink((dir / "existing.txt").c_str()) == 0 ? "removed;" : "";
    what += ::rename((dir / "existing.txt").c_str(), (dir / "moved.txt").c_str()) == 0 ? "renamed;" : "";
    what += ::mkdir((dir / "sub").c_str(), 0777) == 0 ? "made a folder;" : "";
    what += ::kill(::getppid(), 0) == 0 ? "signalled its parent;" : "";
    what += ::open((dir / "existing.txt").c_str(), O_RDONLY) >= 0 ? "" : "cannot even read;";
    return what;
  });
  EXPECT_EQ(answer, "");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"existing.txt"});
  std::ifstream in(dir / "existing.txt");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "the user's file");
  fs::remove_all(dir);
}

// A staging folder holding `files` (name, bytes), removed at the end of the test.
struct Staged {
  std::vector<std::string> bytes;
  std::unique_ptr<thinlayer::StagingFolder> folder;
  Staged(std::initializer_list<std::pair<std::string, std::string>> list) {
    const std::vector<std::pair<std::string, std::string>> files(list);
    std::vector<thinlayer::StagedFile> staged;
    bytes.reserve(files.size());
    for (const auto& [name, text] : files) bytes.push_back(text);
    for (std::size_t k = 0; k < files.size(); ++k) staged.push_back({files[k].first, &bytes[k]});
    folder = std::make_unique<thinlayer::StagingFolder>(std::vector<std::string>{}, staged);
  }
  std::string root() const { return folder->root(); }
};

// The child starts with no environment of the user's: PWD alone, the staging folder.
TEST(MeshingChild, StartsWithAnEmptyEnvironment) {
  ::setenv("THINLAYER_TEST_SECRET", "s3cret", 1);
  const Staged staged{{"t.geo", "x = 1;\n"}};
  MeshingChildLimits limits;
  limits.read_folder = staged.root();
  const std::string answer = run_in_meshing_child([] {
    std::string all;
    for (char** e = environ; *e; ++e) all += std::string(*e) + ";";
    return all;
  }, limits);
  EXPECT_EQ(answer, "PWD=" + staged.root() + ";");
  ::unsetenv("THINLAYER_TEST_SECRET");
}

// Nothing outside the staging folder answers, not even a lookup (stat, access, readlink): the
// seccomp filter refuses them whatever the kernel, and the private root, where the kernel gives
// it, holds nothing else. Inside, a file opens and fstat works.
TEST(MeshingChild, NoLookupOutsideItsFolderAnswers) {
  const Staged staged{{"inside.geo", "x = 1;\n"}};
  MeshingChildLimits limits;
  limits.read_folder = staged.root();
  const std::string answer = run_in_meshing_child([] {
    std::string what;
    struct stat info {};
    what += ::stat("/etc/hostname", &info) == 0 ? "stat /etc;" : "";
    what += ::lstat("/etc", &info) == 0 ? "lstat /etc;" : "";
    what += ::access("/etc/passwd", F_OK) == 0 ? "access /etc;" : "";
    char link[256];
    what += ::readlink("/proc/self/exe", link, sizeof link) >= 0 ? "readlink;" : "";
    what += ::open("/etc", O_RDONLY | O_DIRECTORY) >= 0 ? "opened /etc;" : "";
    what += ::open("/etc/hostname", O_PATH) >= 0 ? "O_PATH /etc;" : "";
    what += ::stat("inside.geo", &info) == 0 ? "stat inside;" : "";  // a path: refused too
    const int fd = ::open("inside.geo", O_RDONLY);
    what += fd >= 0 && ::fstat(fd, &info) == 0 && info.st_size == 7 ? "fstat inside;" : "no fstat inside;";
    return what;
  }, limits);
  EXPECT_EQ(answer, "fstat inside;");
}

// Where the kernel gives the namespaces, the child's file system is the staging folder alone:
// what lies beside it does not exist there, for open() too.
TEST(MeshingChild, ItsRootHoldsTheStagingFolderAlone) {
  if (!thinlayer::private_root_available()) GTEST_SKIP() << "no user namespaces here: Landlock and seccomp only";
  const Staged staged{{"inside.geo", "x = 1;\n"}};
  MeshingChildLimits limits;
  limits.read_folder = staged.root();
  const std::string answer = run_in_meshing_child([] {
    std::string what;
    what += ::open("/etc/hostname", O_RDONLY) < 0 && errno == ENOENT ? "no /etc/hostname;" : "/etc/hostname is there;";
    what += ::open("inside.geo", O_RDONLY) >= 0 ? "inside;" : "";
    what += ::socket(AF_INET, SOCK_STREAM, 0) < 0 ? "no socket;" : "";
    return what;
  }, limits);
  EXPECT_EQ(answer, "no /etc/hostname;inside;no socket;");  // ENOENT, not Landlock's EACCES: nothing there
}

// The seccomp filter is an allow-list: what gmsh does not need fails, whatever it is.
TEST(MeshingChild, CallsOffTheAllowListFail) {
  const std::string answer = run_in_meshing_child([] {
    std::string what;
    what += ::socket(AF_UNIX, SOCK_STREAM, 0) >= 0 ? "socket;" : "";
    what += ::mmap(nullptr, 4096, PROT_READ | PROT_EXEC, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0) != MAP_FAILED ? "exec memory;" : "";
    void* page = ::mmap(nullptr, 4096, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    what += page == MAP_FAILED ? "no memory;" : "";
    what += page != MAP_FAILED && ::mprotect(page, 4096, PROT_READ | PROT_EXEC) == 0 ? "made memory executable;" : "";
    int size = 0;
    what += ::ioctl(0, FIONREAD, &size) == 0 ? "ioctl;" : "";
    what += ::dup(0) >= 0 ? "dup;" : "";
    what += ::kill(::getppid(), 0) == 0 ? "signalled its parent;" : "";
    what += ::chdir("/") == 0 ? "chdir;" : "";
    what += ::setsid() >= 0 ? "setsid;" : "";
    // What it needs stays allowed: a thread (gmsh's OpenMP), memory, reading the time.
    int ran = 0;
    std::thread([&] { ran = 1; }).join();
    std::vector<double> big(1 << 24, 1.0);  // 128 MB: mmap
    what += ran == 1 && big.back() == 1.0 && std::chrono::steady_clock::now().time_since_epoch().count() > 0
                ? "thread, memory, clock;" : "";
    return what;
  });
  EXPECT_EQ(answer, "thread, memory, clock;");
}

// gmsh merges F.opt after every file F it merges, if stat() finds it (Common/OpenFile.cpp): the
// scene's sources never stage one (tests/test_geo_scan.cpp), and even staged it is inert in the
// box, which refuses that stat. The control: the same files opened by gmsh outside the box merge it.
TEST(MeshingChild, ASideFileStagedAnywayIsInert) {
  const Staged staged{{"t.geo", "Point(1) = {0, 0, 0};\n"}, {"t.geo.opt", "Point(99) = {1, 1, 0};\n"}};
  auto points = [&] {
    thinlayer::GmshModelScope scope("side-file");
    thinlayer::with_gmsh_errors([&] { gmsh::open(staged.root() + "/t.geo"); });
    gmsh::vectorpair tags;
    gmsh::model::getEntities(tags, 0);
    return std::to_string(tags.size());
  };
  thinlayer::ensure_gmsh_initialized();
  EXPECT_EQ(points(), "2");  // outside the box: t.geo.opt merged
  MeshingChildLimits limits;
  limits.read_folder = staged.root();
  EXPECT_EQ(run_in_meshing_child(points, limits), "1");
}

// OpenCASCADE reads a STEP and a BREP shape in the box (the allow-list measured on the shipped
// scenes, none of which has a shape): merged and meshed like a user's geometry would be.
TEST(MeshingChild, AShapeIsReadAndMeshedInTheBox) {
  const fs::path dir = fs::temp_directory_path() / ("thinlayer-shape-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  thinlayer::ensure_gmsh_initialized();
  {
    thinlayer::GmshModelScope scope("shape");
    thinlayer::with_gmsh_errors([&] {
      gmsh::model::occ::addRectangle(0, 0, 0, 2, 1);
      gmsh::model::occ::synchronize();
      gmsh::write((dir / "r.step").string());
      gmsh::write((dir / "r.brep").string());
    });
  }
  auto slurp = [&](const char* name) {
    std::ifstream in(dir / name, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const char* shape : {"r.step", "r.brep"}) {
    SCOPED_TRACE(shape);
    const Staged staged{{"t.geo", std::string("SetFactory(\"OpenCASCADE\");\nMerge \"") + shape + "\";\n"},
                        {shape, slurp(shape)}};
    MeshingChildLimits limits;
    limits.read_folder = staged.root();
    const std::string answer = run_in_meshing_child([&] {
      thinlayer::GmshModelScope scope("boxed-shape");
      return thinlayer::with_gmsh_errors([&] {
        gmsh::open(staged.root() + "/t.geo");
        gmsh::model::mesh::generate(2);
        std::vector<std::size_t> tags;
        std::vector<double> xyz, uv;
        gmsh::model::mesh::getNodes(tags, xyz, uv);
        gmsh::vectorpair surfaces;
        gmsh::model::getEntities(surfaces, 2);
        return std::to_string(surfaces.size()) + " surface, " + (tags.size() > 4 ? "meshed" : "not meshed");
      });
    }, limits);
    EXPECT_EQ(answer, "1 surface, meshed");
  }
  fs::remove_all(dir);
}

// One wall clock for all the meshing of a command: runs draw on it in turn; a run that outlasts
// what is left is stopped, naming what earlier runs took; once it is spent nothing runs.
TEST(MeshingChild, OneClockBoundsAllTheRunsOfACommand) {
  thinlayer::set_meshing_wall_clock(2.5);
  auto sleeps = [] {
    ::usleep(1'200'000);
    return std::string("slept");
  };
  EXPECT_EQ(run_in_meshing_child(sleeps), "slept");  // about 1.2 s of 2.5
  const std::string second = failure([] {
    meshing_phase("meshing");
    ::sleep(5);
    return std::string();
  });
  EXPECT_EQ(second.rfind("gmsh did not finish within the wall-clock limit of 2.5 s (--mesh-timeout, for all the meshing of "
                         "the command: 1.", 0), 0u) << second;
  EXPECT_NE(second.find("s of it went to earlier meshes) while meshing"), std::string::npos) << second;
  const auto start = std::chrono::steady_clock::now();
  const std::string third = failure(sleeps);
  EXPECT_NE(third.find("the wall-clock limit of 2.5 s (--mesh-timeout, for all the meshing of the command"), std::string::npos)
      << third;
  EXPECT_NE(third.find("is spent: gmsh was not run"), std::string::npos) << third;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.5);
  thinlayer::set_meshing_wall_clock(thinlayer::default_mesh_timeout_s);
}

}  // namespace
