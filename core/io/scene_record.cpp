#include "core/io/scene_record.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/io/cell_stress.h"
#include "core/io/units.h"

namespace thinlayer {

StatusCount InterfaceFields::counts() const {
  std::vector<NodeStatus> s;
  for (int v : status) s.push_back(static_cast<NodeStatus>(v));
  return count_statuses(s);
}

std::vector<InterfaceFields> interface_fields(const ContactProblem& problem, const SolveReport& report,
                                              double status_tolerance) {
  const Eigen::VectorXd g = problem.jumps(report.u);
  std::vector<InterfaceFields> result;
  int k = 0;
  for (const Interface& interface : problem.interfaces()) {
    const int m = static_cast<int>(interface.nodes.size());
    InterfaceFields f;
    f.name = interface.name;
    f.x.resize(m, 2);
    f.normal.resize(m, 2);
    f.length.resize(m);
    f.jump_N.resize(m);
    f.jump_T.resize(m);
    f.sigma_N.resize(m);
    f.sigma_T.resize(m);
    for (int i = 0; i < m; ++i, ++k) {
      const InterfaceNode& node = interface.nodes[i];
      f.x.row(i) = node.x.transpose();
      f.normal.row(i) = node.normal.transpose();
      f.length[i] = node.length;
      f.jump_N[i] = g[2 * k];
      f.jump_T[i] = g[2 * k + 1];
      f.sigma_N[i] = report.r[2 * k] / node.length;
      f.sigma_T[i] = report.r[2 * k + 1] / node.length;
    }
    const std::vector<InterfaceLaw> laws(m, interface.law);
    for (NodeStatus s : classify_statuses(laws, f.sigma_N, f.sigma_T, status_tolerance))
      f.status.push_back(static_cast<int>(s));
    result.push_back(std::move(f));
  }
  return result;
}

SceneRecord record_scene(const std::string& id, const Model& model, const ContactProblem& problem,
                         const SolveReport& report, double status_tolerance) {
  SceneRecord s;
  s.id = id;
  int num_nodes = 0, num_cells = 0, per_cell = 0;
  for (const Body& b : model.bodies) {
    num_nodes += b.mesh.num_nodes();
    num_cells += b.mesh.num_cells();
    per_cell = std::max(per_cell, b.mesh.element == ElementType::Q1 ? 4 : 3);
  }
  s.nodes.resize(num_nodes, 2);
  s.cells = H5Writer::RowMatrixXi::Constant(num_cells, per_cell, -1);  // -1 pads a mixed mesh
  int node_offset = 0, cell = 0;
  std::vector<int> body_offset;
  for (const Body& b : model.bodies) {
    s.body_names.push_back(b.name);
    s.cell_body.insert(s.cell_body.end(), b.mesh.num_cells(), static_cast<int>(body_offset.size()));
    body_offset.push_back(node_offset);
    s.nodes.middleRows(node_offset, b.mesh.num_nodes()) = b.mesh.nodes;
    for (const auto& q : b.mesh.quads) {
      for (int a = 0; a < 4; ++a) s.cells(cell, a) = node_offset + q[a];
      ++cell;
    }
    for (const auto& t : b.mesh.triangles) {
      for (int a = 0; a < 3; ++a) s.cells(cell, a) = node_offset + t[a];
      ++cell;
    }
    node_offset += b.mesh.num_nodes();
  }
  const Eigen::VectorXd u_full = problem.system().expand(report.u);
  s.u = Eigen::Map<const H5Writer::RowMatrixXd>(u_full.data(), num_nodes, 2);
  s.cell_stress = cell_stresses(model, u_full);
  s.interfaces = interface_fields(problem, report, status_tolerance);
  for (size_t i = 0; i < s.interfaces.size(); ++i)
    for (const InterfaceNode& node : problem.interfaces()[i].nodes) {
      s.interfaces[i].node_plus.push_back(body_offset[node.plus_body] + node.plus_node);
      s.interfaces[i].node_minus.push_back(node.on_foundation() ? -1 : body_offset[node.minus_body] + node.minus_node);
    }
  const Eigen::VectorXd interface_force = problem.B().transpose() * report.r;
  s.reactions = problem.system().reactions(u_full, problem.system().scatter(interface_force));
  s.text["solver"] = report.solver;
  if (!report.method.empty()) s.text["solver_method"] = report.method;
  s.text["solver_message"] = report.message;
  s.integers["iterations"] = report.iterations;
  s.integers["converged"] = report.converged ? 1 : 0;
  s.text["stop_cause"] = to_string(report.stop_cause);
  s.numbers["condition_estimate"] = report.condition_estimate;
  s.numbers["residual"] = report.residual.value();
  s.numbers["residual_interface"] = report.residual.interface;
  s.numbers["residual_bulk"] = report.residual.bulk;
  // SPEC §1.5: each body's and each interface's residual, with their names.
  s.residual_per_body = report.residual.per_body;
  s.residual_floor_per_body = report.residual.per_body_floor;
  s.residual_nodal_floor_per_body = report.residual.per_body_nodal_floor;
  s.residual_per_interface = report.residual.per_interface;
  s.residual_floor_per_interface = report.residual.per_interface_floor;
  for (const Interface& i : problem.interfaces()) s.interface_names.push_back(i.name);
  s.numbers["tolerance"] = report.tolerance;
  s.numbers["wall_time_s"] = report.wall_time_s;
  s.numbers["status_tolerance"] = status_tolerance;
  s.integers["num_nodes"] = num_nodes;
  s.integers["num_cells"] = num_cells;
  return s;
}

namespace {

// SPEC §4 / S5: a NaN or Inf is never written as a result. Inputs may be infinite (a rigid
// law's λ̄ = ∞), so only the solution's fields are checked.
void require_finite_results(const SceneRecord& scene) {
  auto check = [&](const std::string& what, auto begin, auto end) {
    for (auto it = begin; it != end; ++it)
      if (!std::isfinite(*it))
        throw std::runtime_error("scene " + scene.id + ": refusing to write a non-finite value in " + what);
  };
  check("u", scene.u.data(), scene.u.data() + scene.u.size());
  for (const InterfaceFields& f : scene.interfaces)
    for (const Eigen::VectorXd* v : {&f.jump_N, &f.jump_T, &f.sigma_N, &f.sigma_T})
      check("interface " + f.name, v->data(), v->data() + v->size());
  for (const auto& [name, R] : scene.reactions) check("reaction " + name, R.data(), R.data() + 2);
  for (const char* name : {"residual", "residual_interface", "residual_bulk"})
    if (scene.numbers.count(name)) check(name, &scene.numbers.at(name), &scene.numbers.at(name) + 1);
  check("residual_per_body", scene.residual_per_body.begin(), scene.residual_per_body.end());
  check("residual_floor_per_body", scene.residual_floor_per_body.begin(), scene.residual_floor_per_body.end());
  check("residual_floor_per_interface", scene.residual_floor_per_interface.begin(),
        scene.residual_floor_per_interface.end());
  check("residual_nodal_floor_per_body", scene.residual_nodal_floor_per_body.begin(),
        scene.residual_nodal_floor_per_body.end());
  check("residual_per_interface", scene.residual_per_interface.begin(), scene.residual_per_interface.end());
}

}  // namespace

void record_friction_path(SceneRecord& scene, const std::vector<double>& multipliers, double friction) {
  if (multipliers.empty()) return;
  std::ostringstream path;
  for (double t : multipliers) path << t * friction << ",";
  path << friction;
  scene.text["friction_path"] = path.str();
}

void write_scene(H5Writer& file, const SceneRecord& scene) {
  require_finite_results(scene);
  const std::string g = "/scenes/" + scene.id;
  file.group(g);
  for (const auto& [name, value] : scene.text) file.attr(g, name, value);
  for (const auto& [name, value] : scene.numbers) {
    file.attr(g, name, value);
    if (const std::string unit = unit_of(name, scene.force_unit); !unit.empty()) file.attr(g, name + "_units", unit);
  }
  for (const auto& [name, value] : scene.integers) file.attr(g, name, value);
  // A dataset with its unit, under the unit's name for it (units.h).
  auto with_unit = [&](const std::string& path, const std::string& quantity) {
    file.attr(path, "units", unit_of(quantity, scene.force_unit));
  };
  file.dataset(g + "/mesh/nodes", scene.nodes);
  with_unit(g + "/mesh/nodes", "nodes");
  file.dataset(g + "/mesh/cells", scene.cells);
  file.attr(g + "/mesh/cells", "description", "node indices (rows of mesh/nodes) per cell, counter-clockwise; -1 pads");
  if (!scene.cell_body.empty()) {  // a record made by record_scene (tests may build bare ones)
    file.dataset(g + "/mesh/cell_body", scene.cell_body);
    file.attr(g + "/mesh/cell_body", "description", "index of each cell's body in mesh/body_names");
    file.dataset(g + "/mesh/body_names", scene.body_names);
    file.dataset(g + "/mesh/cell_stress", scene.cell_stress);
    with_unit(g + "/mesh/cell_stress", "cell_stress");
    file.attr(g + "/mesh/cell_stress", "description", "sigma_11, sigma_22, sigma_12 at each cell's centre");
  }
  file.dataset(g + "/u", scene.u);
  with_unit(g + "/u", "u");
  for (const InterfaceFields& f : scene.interfaces) {
    const std::string p = g + "/interface/" + f.name;
    auto vec = [](const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); };
    file.attr(p, "force_convention", force_convention);
    file.dataset(p + "/x", f.x);
    file.dataset(p + "/normal", f.normal);
    file.dataset(p + "/length", vec(f.length));
    file.dataset(p + "/jump_N", vec(f.jump_N));
    file.dataset(p + "/jump_T", vec(f.jump_T));
    file.dataset(p + "/sigma_N", vec(f.sigma_N));
    file.dataset(p + "/sigma_T", vec(f.sigma_T));
    for (const char* q : {"x", "normal", "length", "jump_N", "jump_T", "sigma_N", "sigma_T"}) with_unit(p + "/" + q, q);
    file.dataset(p + "/status", f.status);
    file.attr(p + "/status", "legend", status_legend);
    if (!f.node_plus.empty()) {
      file.dataset(p + "/node_plus", f.node_plus);
      file.attr(p + "/node_plus", "description", "row of mesh/nodes of each interface node on the plus side");
      file.dataset(p + "/node_minus", f.node_minus);
      file.attr(p + "/node_minus", "description",
                "row of mesh/nodes of each interface node on the minus side; -1: the rigid foundation");
    }
  }
  for (const auto& [name, R] : scene.reactions) {
    file.dataset(g + "/reactions/" + name, std::vector<double>{R.x(), R.y()});
    with_unit(g + "/reactions/" + name, "reactions");
    file.attr(g + "/reactions/" + name, "description", "[R_x, R_y], the force the boundary exerts on the body");
  }
  if (!scene.combined_status.empty()) {
    file.dataset(g + "/combined_status", scene.combined_status);
    file.attr(g + "/combined_status", "legend", status_legend);
  }
  // SPEC §1.5's residuals, one value per body or interface, named in `list_attr` (an array of
  // names: a body's name may hold a comma).
  auto residuals = [&](const std::string& name, const std::vector<double>& values, const char* list_attr,
                       const std::vector<std::string>& names, const char* evaluation) {
    if (values.empty()) return;
    file.dataset(g + "/" + name, values);
    with_unit(g + "/" + name, name);
    file.attr(g + "/" + name, list_attr, names);
    if (evaluation) file.attr(g + "/" + name, "evaluation", evaluation);
  };
  residuals("residual_per_body", scene.residual_per_body, "bodies", scene.body_names, nullptr);
  // What double precision can resolve of each body's residual for this answer (the residual
  // cannot be expected below it): Residual::per_body_floor.
  residuals("residual_floor_per_body", scene.residual_floor_per_body, "bodies", scene.body_names,
            "a layer band's balance in its column basis (its digits kept), every other body nodally");
  // A user re-evaluating K u from the written nodal `u` resolves a body's residual only to this.
  residuals("residual_nodal_floor_per_body", scene.residual_nodal_floor_per_body, "bodies", scene.body_names,
            "K_b u_b from the nodal u as written: what re-evaluating the file's u resolves");
  residuals("residual_per_interface", scene.residual_per_interface, "interfaces", scene.interface_names, nullptr);
  // What rounding the answer's u and r to double moves each interface's natural map by.
  residuals("residual_floor_per_interface", scene.residual_floor_per_interface, "interfaces", scene.interface_names,
            "u_eps (|r| + kappa (|B||u| + |g_D| + |C r|)) per row, the answer rounded to double");
}

}  // namespace thinlayer
