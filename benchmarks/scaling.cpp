// Issue 25, target 2: how the layer mode's cost grows with the mesh, against the two yardsticks
// of the same mesh — one linear solve with the layer bonded (benchmarks/bonded_solve.h) and the
// limit mode. One line per mesh level: nodes, interface nodes, each of the three's time and peak
// memory, the ratios; then the growth exponent of each time in the number of interface nodes
// (least squares on log t = p log n + c over the levels that finished).
//
//   build/thinlayer_scaling --joint cases/double_lap/double_lap.json --sizes 0.25,0.125,0.0625
//   build/thinlayer_scaling --dovetail d:1e-3 --sizes 0.05,0.025,0.0125,0.00625
//   build/thinlayer_scaling --limit cases/friction_lap/friction_lap.json --sizes 0.25,0.1,0.05 --before 1
//
// --sizes is the element size along the bondline (mm for a joint, mesh_size's "interface", the
// far size kept in the file's proportion; the dovetail's h_interface, h_far 0.1). Each of the
// three runs in a forked child, so that its peak memory (the child's ru_maxrss: meshing,
// assembly and solve) is its own, and one that exceeds --timeout (s, default 600) is reported
// as such and the levels after it skipped. Times: setup + solve (meshing and assembly excluded),
// one BLAS thread, wall clock of a shared machine — compare within one run. Exit status 0 only if
// every level's three runs finished and both modes converged.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "benchmarks/bonded_solve.h"
#include "cases/dovetail/dovetail.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "cases/scene/scene_file_scenes.h"
#include "cases/scene/scene_model.h"
#include "cases/scene/scene_spec.h"
#include "core/linalg/factor_memory.h"
#include "studies/parallel/blas_threads.h"

namespace thinlayer {
namespace {

// What one child measured.
struct Measured {
  bool finished = false;  // false: timed out or crashed
  double seconds = 0, megabytes = 0, residual = 0;
  int steps = 0, nodes = 0, interface_nodes = 0;
  std::string stop_cause = "-";
};

// Runs `work` in a child; it returns "seconds steps residual nodes interface_nodes stop_cause".
Measured in_child(const std::function<std::string()>& work, int timeout_s) {
  int pipe_fd[2];
  if (pipe(pipe_fd) != 0) throw std::runtime_error("scaling: pipe failed");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("scaling: fork failed");
  if (pid == 0) {
    close(pipe_fd[0]);
    alarm(static_cast<unsigned>(timeout_s));
    try {
      const std::string line = work();
      _exit(write(pipe_fd[1], line.data(), line.size()) < 0 ? 3 : 0);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "thinlayer_scaling: %s\n", e.what());
      _exit(4);
    }
  }
  close(pipe_fd[1]);
  std::string text;
  char buffer[512];
  for (ssize_t n; (n = read(pipe_fd[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<size_t>(n));
  close(pipe_fd[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  Measured m;
  m.megabytes = usage.ru_maxrss / 1024.0;  // Linux: KiB
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || text.empty()) {
    m.stop_cause = WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM ? "timeout"
                   : WIFEXITED(status) && WEXITSTATUS(status) == 4       ? "error"
                                                                         : "crashed";
    return m;
  }
  std::istringstream in(text);
  in >> m.seconds >> m.steps >> m.residual >> m.nodes >> m.interface_nodes;
  std::getline(in >> std::ws, m.stop_cause);  // "round-off floor", "loss of accuracy": the rest of the line
  m.finished = true;
  return m;
}

// Nodes on S: the combined statuses of a layer record, every interface's nodes of a limit one.
size_t interface_nodes(const SceneRecord& record) {
  if (!record.combined_status.empty()) return record.combined_status.size();
  size_t n = 0;
  for (const InterfaceFields& f : record.interfaces) n += f.status.size();
  return n;
}

std::string line_of(double seconds, const SolveReport* report, const SceneRecord* record) {
  std::ostringstream s;
  s.precision(6);
  s << seconds << ' ' << (report ? report->iterations : 0) << ' ' << (report ? report->residual.value() : 0.0) << ' '
    << (record ? record->nodes.rows() : 0) << ' ' << (record ? interface_nodes(*record) : 0) << ' '
    << (report ? to_string(report->stop_cause) : "-");
  return s.str();
}

// The layer mode's method (--layer-method): the interior-point method first (the default) or the ladder.
SolverOptions layer_options;

double setup_and_solve(const SceneRecord& record, const SolveReport& report) {
  return (record.numbers.count("setup_time_s") ? record.numbers.at("setup_time_s") : 0.0) + report.wall_time_s;
}

// A scene file at element size h along its bondlines.
SceneSpec joint_at(const std::string& path, double h) {
  SceneSpec spec = read_scene_spec(path);
  const double far_ratio = spec.h_interface && spec.h_far ? *spec.h_far / *spec.h_interface : 4.0;
  spec.h_interface = h;
  spec.h_far = h * far_ratio;
  return spec;
}

struct Level {
  Measured bonded, layer, limit;
};

Level joint_level(const std::string& path, double h, int timeout_s) {
  Level level;
  level.layer = in_child([&] {
    const SceneFileBulk bulk(joint_at(path, h));
    const SceneFileScene s = solve_scene_file_layer(bulk, 0.0, SolverKind::Fast, layer_options);
    return line_of(setup_and_solve(s.record, s.report), &s.report, &s.record);
  }, timeout_s);
  level.limit = in_child([&] {
    SceneFileBulk bulk(joint_at(path, h));
    const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, {});
    return line_of(setup_and_solve(s.record, s.report), &s.report, &s.record);
  }, timeout_s);
  level.bonded = in_child([&] {
    const SceneSpec spec = joint_at(path, h);
    const SceneFileBulk bulk(spec);
    const SceneLayerModel layer = make_scene_layer_model(spec, bulk.meshes(), bulk.interface_nodes(), 0.0);
    const LinearSystem system(layer.model);
    const ContactProblem problem(system, layer.interfaces);
    return line_of(bonded_solve_seconds(problem), nullptr, nullptr);
  }, timeout_s);
  return level;
}

double growth_exponent(const std::vector<double>& n, const std::vector<double>& t);

// Limit mode only (a joint with a body held by its bondlines alone): the sparse Newton (the
// default), the condensed path it replaced (SolverOptions::sparse_newton off: "before"), and one
// linear solve of the limit mesh with every bondline node pair tied.
struct LimitLevel {
  Measured bonded, limit, before;
};

LimitLevel limit_level(const std::string& path, double h, int timeout_s, bool before) {
  LimitLevel level;
  auto limit_with = [&](bool sparse_newton) {
    return in_child([&] {
      SceneFileBulk bulk(joint_at(path, h));
      SolverOptions options;
      options.sparse_newton = sparse_newton;
      const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, options);
      return line_of(setup_and_solve(s.record, s.report), &s.report, &s.record);
    }, timeout_s);
  };
  level.limit = limit_with(true);
  if (before) level.before = limit_with(false);
  level.bonded = in_child([&] {
    const SceneFileBulk bulk(joint_at(path, h));
    const ContactProblem problem(bulk.system(), bulk.limit_interfaces(0));
    return line_of(bonded_solve_seconds(problem), nullptr, nullptr);
  }, timeout_s);
  return level;
}

int run_limit(const std::string& joint, const std::vector<double>& sizes, int timeout_s, bool before) {
  std::printf("%s: limit mode (sparse Newton) against one bonded linear solve of the same mesh%s\n", joint.c_str(),
              before ? " and the condensed path (before)" : "");
  std::printf("%9s %8s %6s | %9s %8s | %9s %8s %6s %9s %-10s | %9s %6s %-10s | %8s\n", "h", "nodes", "n_S", "bonded_s",
              "MB", "limit_s", "MB", "steps", "residual", "stop", "before_s", "steps", "stop", "t/bond");
  std::vector<double> n_S, t_bonded, t_limit;
  bool all_converged = true;
  for (double h : sizes) {
    const LimitLevel l = limit_level(joint, h, timeout_s, before);
    std::printf("%9g %8d %6d | %9.4f %8.0f | %9.4f %8.0f %6d %9.2e %-10s | %9.4f %6d %-10s | %8.1f\n", h, l.limit.nodes,
                l.limit.interface_nodes, l.bonded.seconds, l.bonded.megabytes, l.limit.seconds, l.limit.megabytes,
                l.limit.steps, l.limit.residual, l.limit.stop_cause.c_str(), l.before.seconds, l.before.steps,
                l.before.stop_cause.c_str(), l.limit.seconds / l.bonded.seconds);
    std::fflush(stdout);
    all_converged = all_converged && l.limit.stop_cause == "converged";
    if (!l.limit.finished || !l.bonded.finished) {
      std::printf("(a run of this level did not finish within %d s: the finer levels are skipped)\n", timeout_s);
      all_converged = false;
      break;
    }
    n_S.push_back(l.limit.interface_nodes);
    t_bonded.push_back(l.bonded.seconds);
    t_limit.push_back(l.limit.seconds);
  }
  std::printf("growth exponent of time in n_S (log-log least squares, %zu levels): limit %.2f, bonded %.2f\n",
              n_S.size(), growth_exponent(n_S, t_limit), growth_exponent(n_S, t_bonded));
  return all_converged ? 0 : 1;
}

Level dovetail_level(char law_case, double eps, double h, int timeout_s) {
  const dovetail::MeshOptions mesh{h, std::max(h, 0.1), 2};
  Level level;
  level.layer = in_child([&] {
    const DovetailLimitBulk bulk(mesh);
    const DovetailScene s =
        solve_dovetail_layer(bulk, dovetail::exponents_of(law_case), eps, std::string(1, law_case), SolverKind::Fast,
                             layer_options);
    return line_of(setup_and_solve(s.record, s.report), &s.report, &s.record);
  }, timeout_s);
  level.limit = in_child([&] {
    DovetailLimitBulk bulk(mesh);
    const DovetailScene s =
        solve_dovetail_limit(bulk, dovetail::exponents_of(law_case), std::string(1, law_case), SolverKind::Fast, {});
    return line_of(setup_and_solve(s.record, s.report), &s.report, &s.record);
  }, timeout_s);
  level.bonded = in_child([&] {
    const DovetailLimitBulk bulk(mesh);
    const dovetail::LayerMeshes meshes = dovetail::make_layer_meshes(bulk.meshes(), eps, mesh.layer_elements);
    const Model model = dovetail::make_layer_model(meshes, dovetail::exponents_of(law_case));
    const LinearSystem system(model);
    const ContactProblem problem(system, dovetail::make_layer_interfaces(model, bulk.friction()));
    return line_of(bonded_solve_seconds(problem), nullptr, nullptr);
  }, timeout_s);
  return level;
}

// The slope p of log t = p log n + c (least squares); NaN with fewer than two points.
double growth_exponent(const std::vector<double>& n, const std::vector<double>& t) {
  if (n.size() < 2) return std::nan("");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < n.size(); ++i) {
    const double x = std::log(n[i]), y = std::log(t[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double k = static_cast<double>(n.size());
  return (k * sxy - sx * sy) / (k * sxx - sx * sx);
}

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> v;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) v.push_back(std::stod(item));
  return v;
}

int usage() {
  std::fprintf(stderr,
               "usage: thinlayer_scaling (--joint FILE.json | --dovetail CASE:EPS) --sizes H1,H2,... [--timeout S]\n"
               "       [--layer-method interior-point|ladder]\n"
               "       thinlayer_scaling --limit FILE.json --sizes H1,H2,... [--before 1] [--timeout S]\n");
  return 2;
}

int run(int argc, char** argv) {
  std::string joint, dovetail_scene, limit_joint;
  std::vector<double> sizes;
  int timeout_s = 600;
  bool before = false;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--joint") joint = value;
    else if (key == "--dovetail") dovetail_scene = value;
    else if (key == "--sizes") sizes = parse_list(value);
    else if (key == "--timeout") timeout_s = std::stoi(value);
    else if (key == "--layer-method") {
      if (value == "ladder") layer_options.layer_method = LayerMethod::Ladder;
      else if (value == "interior-point") layer_options.layer_method = LayerMethod::InteriorPoint;
      else throw std::invalid_argument("--layer-method: interior-point or ladder");
    }
    else if (key == "--limit") limit_joint = value;
    else if (key == "--before") before = value == "1";
    else return usage();
  }
  if (!limit_joint.empty()) {
    if (argc % 2 == 0 || sizes.empty()) return usage();
    use_one_blas_thread();
    keep_factor_memory();
    return run_limit(limit_joint, sizes, timeout_s, before);
  }
  if (argc % 2 == 0 || sizes.empty() || joint.empty() == dovetail_scene.empty()) return usage();
  char law_case = 'd';
  double eps = 1e-3;
  if (!dovetail_scene.empty()) {
    if (dovetail_scene.size() < 3 || dovetail_scene[1] != ':') return usage();
    law_case = dovetail_scene[0];
    eps = std::stod(dovetail_scene.substr(2));
  }
  use_one_blas_thread();
  keep_factor_memory();
  std::printf("%s: layer mode against one bonded linear solve and the limit mode of the same mesh\n",
              joint.empty() ? ("dovetail (" + dovetail_scene + ")").c_str() : joint.c_str());
  std::printf("%9s %8s %6s | %9s %8s | %9s %8s %6s %9s %-10s | %9s %8s | %8s %8s %8s\n", "h", "nodes", "n_S", "bonded_s",
              "MB", "layer_s", "MB", "steps", "residual", "stop", "limit_s", "MB", "t/bond", "t/limit", "MB/bond");
  std::vector<double> n_S, t_bonded, t_layer, t_limit;
  bool all_converged = true;
  for (double h : sizes) {
    const Level l = joint.empty() ? dovetail_level(law_case, eps, h, timeout_s) : joint_level(joint, h, timeout_s);
    std::printf("%9g %8d %6d | %9.4f %8.0f | %9.4f %8.0f %6d %9.2e %-10s | %9.4f %8.0f | %8.1f %8.1f %8.1f\n", h,
                l.layer.nodes, l.layer.interface_nodes, l.bonded.seconds, l.bonded.megabytes, l.layer.seconds,
                l.layer.megabytes, l.layer.steps, l.layer.residual, l.layer.stop_cause.c_str(), l.limit.seconds,
                l.limit.megabytes, l.layer.seconds / l.bonded.seconds, l.layer.seconds / l.limit.seconds,
                l.layer.megabytes / l.bonded.megabytes);
    std::fflush(stdout);
    all_converged = all_converged && l.layer.stop_cause == "converged" && l.limit.stop_cause == "converged";
    if (!l.layer.finished || !l.bonded.finished || !l.limit.finished) {
      std::printf("(a run of this level did not finish within %d s: the finer levels are skipped)\n", timeout_s);
      all_converged = false;
      break;
    }
    n_S.push_back(l.layer.interface_nodes);
    t_bonded.push_back(l.bonded.seconds);
    t_layer.push_back(l.layer.seconds);
    t_limit.push_back(l.limit.seconds);
  }
  std::printf("growth exponent of time in n_S (log-log least squares, %zu levels): layer %.2f, bonded %.2f, limit %.2f\n",
              n_S.size(), growth_exponent(n_S, t_layer), growth_exponent(n_S, t_bonded),
              growth_exponent(n_S, t_limit));
  return all_converged ? 0 : 1;
}

}  // namespace
}  // namespace thinlayer

int main(int argc, char** argv) {
  try {
    return thinlayer::run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "thinlayer_scaling: %s\n", e.what());
    return 2;
  }
}
