// The discrete limit-mode problem of a scene file, written out exactly as thinlayer solves it, with
// thinlayer's own answer beside it: what a peer code (scripts/getfem_peer.py: GetFEM) needs to solve
// the SAME discrete problem without any mesh, and to be compared with thinlayer number by number.
//
//   build/thinlayer_export_problem --scene cases/friction_lap/friction_lap.json --h 0.25 --out /tmp/flap_0.25
//
// --h is the element size along the bondlines (mm, the scene's mesh_size "interface"; its "far" size
// kept in the file's proportion: the rule of thinlayer_scaling's joint_at). The problem is the
// limit mode's, ContactProblem(bulk.system(), bulk.limit_interfaces(0)) (cases/scene/scene_file_scenes.cpp):
//
//   K u = F + Bᵀ r   on the free DOFs,     g = B u + g_D,     d = g + C r,
//   per interface node k (rows 2k: normal N, 2k+1: tangential T), Signorini–Coulomb on (r, d):
//   r_N ≤ 0, d_N ≤ 0, r_N d_N = 0;  |r_T| ≤ f |r_N|, d_T = −ζ r_T (ζ ≥ 0);
//   r_N = 0 (r_T = 0) where the law has no normal (tangential) stiffness; a bilateral node: d = 0.
//   Signs (core/interface/interface.h): [u]_N = n·(u⁻ − u⁺) > 0 is interpenetration, [u]_T = t·(u⁺ − u⁻),
//   n from the minus side into the plus side, t = (n_y, −n_x); r is the force on the plus side,
//   r_N ≤ 0 in compression.
//
// Units: lengths mm, forces in the scene's force unit (problem.json "units": N for mm-N, daN for
// mm-daN) per mm of thickness (plane strain). Every vector file has one value per line (%.17g; an
// infinite compliance is written "inf"), every matrix is Matrix Market "coordinate real general",
// 1-based, every entry stored (K is symmetric but written in full).
//
//   problem.json   sizes (n_free, m nodes, 2m rows), scene, h, units, the interfaces (name, law
//                  λ̄ μ̄ f bilateral, K_N = λ̄ + 2μ̄, K_T = μ̄ in force/mm³, first node, node count),
//                  the bodies' names, the status tolerance and the residual's load floor
//   K.mtx          n_free × n_free stiffness of the free DOFs (force/mm per mm)
//   F.txt          n_free loads: external forces minus K_fd u_d (force per mm)
//   B.mtx          2m × n_free jump operator: g = B u + g_D (dimensionless)
//   gD.txt         2m jump offsets from prescribed DOFs (mm)
//   C.txt          2m compliances 1/(K ℓ) of the law's springs (mm per (force/mm)); 0 rigid, inf free
//   kappa.txt      2m row stiffnesses κ of the SPEC residual's natural map (force/mm per mm)
//   body.txt       n_free: the body index (problem.json "bodies") of each free DOF
//   nodes.csv      per node k: interface, x, y, n_x, n_y (mm, unit), ℓ (mm, tributary length),
//                  f, normal_active, tangential_active, bilateral (0/1)
//   reactions.mtx  R (s × n_free) and reactions_offset.txt R0 (s): each support's resultant on each
//                  body it holds, per component, is R u + R0 (force per mm; what the support exerts
//                  on the body); reactions.csv names row i: support, body, component (0 x, 1 y)
//   u.txt, r.txt   thinlayer's answer (solve_fast, the default fast solver): u (n_free, mm), r (2m,
//                  force per mm: the nodal forces, σ = r / ℓ)
//   status.txt     m statuses of that answer: 0 gap, 1 slide, 2 stick (classify_statuses on σ = r/ℓ
//                  with the tolerance of problem.json, interface by interface)
//   u_bonded.txt, r_bonded.txt   the bonded solve: every node stuck (d = 0 on both rows; the sparse
//                  Newton's start, core/solvers/sparse_newton.h: stuck_statuses), one sparse LU
//   thinlayer.json the solve's method, steps (factorisations), converged, stop cause, residual
//                  (value, interface, bulk, floor), the times of --repeat solves (s, one BLAS thread:
//                  the solver's own wall time, the call's wall and CPU time) and their medians, the
//                  bonded solve's time, the reactions of the answer (rows of reactions.csv) and the
//                  answer's status counts
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

#include "cases/scene/scene_file_scenes.h"
#include "cases/scene/scene_spec.h"
#include "core/fem/linear_system.h"
#include "core/io/scene_record.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/mixed_system.h"
#include "core/solvers/solver_choice.h"
#include "core/solvers/sparse_newton.h"
#include "studies/parallel/blas_threads.h"
#include "benchmarks/driver_main.h"
#include "benchmarks/scene_at.h"

namespace thinlayer {
namespace {

namespace fs = std::filesystem;

std::ofstream open(const fs::path& path) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  return out;
}

// %.17g: every double read back exactly; +∞ as "inf" (what Python's float() and numpy read).
std::string number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

void write_vector(const fs::path& path, const Eigen::VectorXd& v) {
  std::ofstream out = open(path);
  for (Eigen::Index i = 0; i < v.size(); ++i) out << number(v[i]) << '\n';
}

void write_matrix_market(const fs::path& path, const Eigen::SparseMatrix<double>& A) {
  std::ofstream out = open(path);
  out << "%%MatrixMarket matrix coordinate real general\n";
  out << A.rows() << ' ' << A.cols() << ' ' << A.nonZeros() << '\n';
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      out << it.row() + 1 << ' ' << it.col() + 1 << ' ' << number(it.value()) << '\n';
}

// Each support's resultant on each body, per component, as an affine map of the free DOFs:
// at a prescribed DOF the support supplies K_full u_full − F_ext (no interface force acts there:
// B has free columns only), summed over the DOFs it owns. DOF ownership as LinearSystem's: the
// first condition that names a DOF owns it.
struct ReactionOperator {
  Eigen::SparseMatrix<double> R;  // rows × free DOFs
  Eigen::VectorXd offset;
  std::vector<std::string> support, body;
  std::vector<int> component;
};

ReactionOperator reaction_operator(const Model& model, const LinearSystem& system) {
  const SparseMatrix K_full = assemble_stiffness(model);
  const Eigen::VectorXd& F_ext = system.external_force();
  std::map<int, int> row_of_dof;
  ReactionOperator op;
  std::map<std::tuple<std::string, int, int>, int> rows;
  for (const DirichletCondition& bc : model.dirichlet) {
    const int offset = model.dof_offset(bc.body);
    for (int node : bc.nodes) {
      const int dof = offset + 2 * node + bc.component;
      if (row_of_dof.count(dof)) continue;
      const auto key = std::make_tuple(bc.name, bc.body, bc.component);
      auto [it, inserted] = rows.try_emplace(key, static_cast<int>(op.support.size()));
      if (inserted) {
        op.support.push_back(bc.name);
        op.body.push_back(model.bodies[bc.body].name);
        op.component.push_back(bc.component);
      }
      row_of_dof[dof] = it->second;
    }
  }
  const int s = static_cast<int>(op.support.size());
  op.offset = Eigen::VectorXd::Zero(s);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int col = 0; col < K_full.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K_full, col); it; ++it) {
      const auto row = row_of_dof.find(static_cast<int>(it.row()));
      if (row == row_of_dof.end()) continue;
      const int j = system.free_index(static_cast<int>(it.col()));
      if (j >= 0) triplets.emplace_back(row->second, j, it.value());
      else op.offset[row->second] += it.value() * system.prescribed_value(static_cast<int>(it.col()));
    }
  for (const auto& [dof, row] : row_of_dof) op.offset[row] -= F_ext[dof];
  op.R.resize(s, system.num_free());
  op.R.setFromTriplets(triplets.begin(), triplets.end());
  return op;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

int export_problem(const std::string& scene_path, double h, const fs::path& out, int repeat) {
  fs::create_directories(out);
  SceneFileBulk bulk(scene_at(scene_path, h));
  const LinearSystem& system = bulk.system();
  const ContactProblem problem(system, bulk.limit_interfaces(0));
  const int n = system.num_free(), m = problem.num_nodes();

  // The problem.
  write_matrix_market(out / "K.mtx", system.K());
  write_vector(out / "F.txt", system.F());
  write_matrix_market(out / "B.mtx", problem.B());
  write_vector(out / "gD.txt", problem.jump_offset());
  write_vector(out / "C.txt", problem.compliance());
  write_vector(out / "kappa.txt", problem.kappa());
  {
    std::ofstream body = open(out / "body.txt");
    for (int i = 0; i < n; ++i) body << system.body_of(i) << '\n';
  }
  {
    std::ofstream nodes = open(out / "nodes.csv");
    nodes << "k,interface,x,y,n_x,n_y,length,friction,normal_active,tangential_active,bilateral\n";
    for (int k = 0; k < m; ++k) {
      const InterfaceNode& node = problem.node(k);
      const InterfaceLaw& law = problem.law(k);
      nodes << k << ',' << problem.interface_of(k) << ',' << number(node.x.x()) << ',' << number(node.x.y()) << ','
            << number(node.normal.x()) << ',' << number(node.normal.y()) << ',' << number(node.length) << ','
            << number(law.friction) << ',' << law.normal_active() << ',' << law.tangential_active() << ','
            << law.bilateral << '\n';
    }
  }
  const ReactionOperator reactions = reaction_operator(bulk.model(), system);
  write_matrix_market(out / "reactions.mtx", reactions.R);
  write_vector(out / "reactions_offset.txt", reactions.offset);
  {
    std::ofstream names = open(out / "reactions.csv");
    names << "row,support,body,component\n";
    for (std::size_t i = 0; i < reactions.support.size(); ++i)
      names << i << ',' << reactions.support[i] << ',' << reactions.body[i] << ',' << reactions.component[i] << '\n';
  }

  const std::string force = bulk.spec().units.force;
  nlohmann::json meta;
  meta["scene"] = scene_path;
  meta["h"] = h;
  meta["n_free"] = n;
  meta["nodes"] = m;
  meta["units"] = {{"length", "mm"}, {"force", force + " per mm of thickness"}, {"stress", bulk.spec().units.stress()},
                   {"stiffness", bulk.spec().units.stiffness()}};
  meta["status_tolerance"] = default_status_tolerance;
  meta["residual_load_floor"] = residual_load_floor;
  for (int b = 0; b < system.num_bodies(); ++b) meta["bodies"].push_back(system.body_name(b));
  int first = 0;
  for (const Interface& i : problem.interfaces()) {
    const int count = static_cast<int>(i.nodes.size());
    meta["interfaces"].push_back({{"name", i.name},
                                  {"lambda_bar", i.law.lambda_bar},
                                  {"mu_bar", i.law.mu_bar},
                                  {"K_N", i.law.K_N()},
                                  {"K_T", i.law.K_T()},
                                  {"friction", i.law.friction},
                                  {"bilateral", i.law.bilateral},
                                  {"first_node", first},
                                  {"node_count", count}});
    first += count;
  }
  open(out / "problem.json") << meta.dump(2) << '\n';

  // thinlayer's answer: the fast solver as `thinlayer solve` runs it on this problem, `repeat` times.
  SolveReport report;
  std::vector<double> solve_s, wall_s, cpu_s;
  for (int i = 0; i < repeat; ++i) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    report = solve_fast(problem);
    cpu_s.push_back(double(std::clock() - cpu_start) / CLOCKS_PER_SEC);
    wall_s.push_back(seconds_since(start));
    solve_s.push_back(report.wall_time_s);
  }
  write_vector(out / "u.txt", report.u);
  write_vector(out / "r.txt", report.r);
  std::vector<int> status;
  for (const InterfaceFields& f : interface_fields(problem, report, default_status_tolerance))
    status.insert(status.end(), f.status.begin(), f.status.end());
  {
    std::ofstream s = open(out / "status.txt");
    for (int v : status) s << v << '\n';
  }

  // The bonded solve: every node stuck, one LU of the whole mixed system (the sparse Newton's start).
  const auto bonded_start = std::chrono::steady_clock::now();
  MixedSystem mixed(problem);
  const MixedSystem::Answer bonded = mixed.solve(stuck_statuses(problem));
  const double bonded_s = seconds_since(bonded_start);
  if (bonded.singular) throw std::runtime_error("the bonded solve is singular");
  write_vector(out / "u_bonded.txt", bonded.u);
  write_vector(out / "r_bonded.txt", bonded.r);

  nlohmann::json answer;
  answer["solver"] = report.solver;
  answer["method"] = report.method;
  answer["steps"] = report.iterations;
  answer["converged"] = report.converged;
  answer["stop_cause"] = to_string(report.stop_cause);
  answer["message"] = report.message;
  answer["residual"] = {{"value", report.residual.value()},
                        {"interface", report.residual.interface},
                        {"bulk", report.residual.bulk},
                        {"floor", report.residual.floor()},
                        {"tolerance", report.tolerance}};
  answer["solve_time_s"] = solve_s;
  answer["solve_time_median_s"] = median(solve_s);
  answer["call_time_s"] = wall_s;  // solve_fast as called: the solve and what it builds around it
  answer["call_time_median_s"] = median(wall_s);
  // The process's CPU time of each call (one BLAS thread): what a machine shared with other jobs
  // leaves of the wall clock's meaning.
  answer["call_cpu_s"] = cpu_s;
  answer["call_cpu_median_s"] = median(cpu_s);
  answer["bonded_solve_time_s"] = bonded_s;
  answer["blas_threads"] = 1;
  const Eigen::VectorXd R = reactions.R * report.u + reactions.offset;
  for (Eigen::Index i = 0; i < R.size(); ++i)
    answer["reactions"].push_back({{"support", reactions.support[i]},
                                   {"body", reactions.body[i]},
                                   {"component", reactions.component[i]},
                                   {"value", R[i]}});
  const StatusCount counts = [&] {
    std::vector<NodeStatus> s;
    for (int v : status) s.push_back(static_cast<NodeStatus>(v));
    return count_statuses(s);
  }();
  answer["status_counts"] = {{"gap", counts.gap}, {"slide", counts.slide}, {"stick", counts.stick}};
  open(out / "thinlayer.json") << answer.dump(2) << '\n';

  // Self-check: the reaction operator against LinearSystem::reactions of the same answer.
  const auto reference = system.reactions(system.expand(report.u), system.scatter(problem.B().transpose() * report.r));
  for (const auto& [name, value] : reference) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (Eigen::Index i = 0; i < R.size(); ++i)
      if (reactions.support[i] == name) sum[reactions.component[i]] += R[i];
    if ((sum - value).norm() > 1e-9 * std::max(1.0, value.norm()))
      throw std::runtime_error("reaction operator disagrees with LinearSystem::reactions on support " + name);
  }
  std::printf("%s at h = %g: %d free DOFs, %d interface nodes; thinlayer %s, %d steps, residual %.2e, %.4f s "
              "(median of %d); written to %s\n",
              scene_path.c_str(), h, n, m, report.method.c_str(), report.iterations, report.residual.value(),
              median(solve_s), repeat, out.string().c_str());
  return report.converged ? 0 : 1;
}

int usage() {
  std::fprintf(stderr, "usage: thinlayer_export_problem --scene FILE.json --h H --out DIR [--repeat N]\n");
  return 2;
}

int run(int argc, char** argv) {
  std::string scene, out;
  double h = 0;
  int repeat = 3;
  if (argc % 2 == 0) return usage();
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--scene") scene = value;
    else if (key == "--h") h = std::stod(value);
    else if (key == "--out") out = value;
    else if (key == "--repeat") repeat = std::stoi(value);
    else return usage();
  }
  if (scene.empty() || out.empty() || !(h > 0) || repeat < 1) return usage();
  use_one_blas_thread();
  return export_problem(scene, h, out, repeat);
}

}  // namespace
}  // namespace thinlayer

int main(int argc, char** argv) { return thinlayer::run_driver("thinlayer_export_problem", thinlayer::run, argc, argv); }
