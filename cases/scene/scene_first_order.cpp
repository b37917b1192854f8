#include "cases/scene/scene_first_order.h"

#include <chrono>
#include <stdexcept>

#include "cases/scene/scene_file_scenes.h"
#include "cases/scene/scene_model.h"
#include "core/solvers/answer_statuses.h"
#include "core/solvers/first_order_layer.h"
#include "core/solvers/layer_end_cell.h"

namespace thinlayer {

namespace {

// Each bondline's layer at the asked thickness: its glue's moduli there (a law only: none).
std::vector<LayerAtThickness> layers_at(const SceneSpec& spec, double eps) {
  std::vector<LayerAtThickness> out;
  for (const SceneInterfaceSpec& i : spec.interfaces) {
    LayerAtThickness l;
    l.plane = spec.plane;
    if (i.has_layer_mode()) {
      l.thickness = layer_thickness(i, eps);  // throws for the paper's family without eps
      const LameModuli m = i.glue_model().at(l.thickness);
      l.lambda = m.lambda;
      l.mu = m.mu;
      // The end cell's deficits at the layer's own ν = λ / (2 (λ + μ)) (core/solvers/layer_end_cell.h).
      const LayerEndDeficits ends = layer_end_deficits(m.lambda / (2 * (m.lambda + m.mu)), spec.plane);
      l.end_deficit_N = ends.normal;
      l.end_deficit_T = ends.shear;
    }
    out.push_back(l);
  }
  return out;
}

// The free-DOF part of a full-numbering vector.
Eigen::VectorXd gather_free(const LinearSystem& system, const Eigen::VectorXd& full) {
  Eigen::VectorXd free = Eigen::VectorXd::Zero(system.num_free());
  for (int g = 0; g < system.num_dofs(); ++g)
    if (const int i = system.free_index(g); i >= 0) free[i] = full[g];
  return free;
}

}  // namespace

namespace {

// The first-order answer of `layers` as a limit record: one more substitution on `factored`.
std::optional<SceneRecord> answer(const SceneFileBulk& bulk, const ContactProblem& problem, const SolveReport& limit,
                                  const std::vector<Active>& statuses, const std::vector<LayerAtThickness>& layers,
                                  const MixedSystem& factored, const std::string& id, double status_tolerance) {
  const LinearSystem& system = problem.system();
  const FirstOrderLoad load = first_order_layer_load(problem, layers, system.expand(limit.u), limit.r, statuses);
  const MixedSystem::Answer delta = factored.solve_again(gather_free(system, load.body_forces), load.row_values);
  if (delta.singular || !delta.u.allFinite() || !delta.r.allFinite()) return std::nullopt;
  SolveReport first = limit;  // u₁ = u₀ + δu, and the spring's force r₀ + δr
  first.u = limit.u + delta.u;
  first.r = limit.r + delta.r;
  first.message = "the first-order layer answer about the limit answer (one extra solve on its statuses)";
  // The layer's traction on each face: the spring's force and the first-order load's part on that side,
  // in the rows' convention (force on the plus side = −n r_N + t r_T, on the minus side its opposite).
  SolveReport plus = first, minus = first;
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceNode& n = problem.node(k);
    plus.r[2 * k] -= n.normal.dot(load.plus_force[k]);
    plus.r[2 * k + 1] += n.tangent().dot(load.plus_force[k]);
    minus.r[2 * k] += n.normal.dot(load.minus_force[k]);
    minus.r[2 * k + 1] -= n.tangent().dot(load.minus_force[k]);
  }
  SceneRecord record = record_scene(id, bulk.model(), problem, plus, status_tolerance);
  // The supports supply what the loads, the springs and the first-order load leave unbalanced.
  const Eigen::VectorXd spring = system.scatter(problem.B().transpose() * first.r);
  record.reactions = system.reactions(system.expand(first.u), spring + load.body_forces);
  // Each bondline's two faces, as a layer record has them (S+ on the plus adherent, S- on the minus).
  std::vector<InterfaceFields> faces;
  const std::vector<InterfaceFields> minus_faces = interface_fields(problem, minus, status_tolerance);
  for (std::size_t i = 0; i < record.interfaces.size(); ++i) {
    faces.push_back(record.interfaces[i]);
    faces.back().name = interface_name(bulk.spec(), static_cast<int>(i), "S+");
    faces.push_back(minus_faces[i]);
    faces.back().name = interface_name(bulk.spec(), static_cast<int>(i), "S-");
    faces.back().node_plus = record.interfaces[i].node_plus;
    faces.back().node_minus = record.interfaces[i].node_minus;
  }
  record.interfaces = std::move(faces);
  return record;
}

}  // namespace

SceneFirstOrder scene_first_order(const SceneFileBulk& bulk, const ContactProblem& problem, const SolveReport& limit,
                                  const std::string& limit_id, MixedSystem* factored, double eps,
                                  double status_tolerance, bool interior_too) {
  const auto start = std::chrono::steady_clock::now();
  SceneFirstOrder out;
  std::vector<LayerAtThickness> layers;
  try {
    layers = layers_at(bulk.spec(), eps);
  } catch (const std::invalid_argument& e) {
    out.note = std::string("not computed: ") + e.what();
    return out;
  }
  for (const LayerAtThickness& l : layers) out.thickness.push_back(l.thickness);
  if (!limit.converged) {
    out.note = "not computed: the limit solve did not converge";
    return out;
  }
  const std::vector<Active> statuses = answer_statuses(problem, limit.r, status_tolerance);
  std::unique_ptr<MixedSystem> own;
  if (!factored) {  // a scene with a contact face: its answer's statuses, factored once
    own = std::make_unique<MixedSystem>(problem);
    own->solve(statuses);
    factored = own.get();
    out.extra_factorisation = true;
  }
  out.record = answer(bulk, problem, limit, statuses, layers, *factored, limit_id + "-first-order", status_tolerance);
  if (!out.record) {
    out.note = "not computed: the limit mode's system at its statuses is singular";
    return out;
  }
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (interior_too) {
    for (LayerAtThickness& l : layers) l.end_deficit_N = l.end_deficit_T = 0;
    out.interior = answer(bulk, problem, limit, statuses, layers, *factored, limit_id + "-first-order-interior",
                          status_tolerance);
  }
  return out;
}

}  // namespace thinlayer
