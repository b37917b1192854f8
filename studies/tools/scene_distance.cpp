#include "studies/tools/scene_distance.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include <Eigen/Dense>

#include "studies/tools/bondline_fields.h"
#include "studies/tools/error_norms.h"

namespace thinlayer {

namespace {

struct Fields {
  Eigen::VectorXd u, jump_N, jump_T, sigma_N, sigma_T, length;
  std::vector<int> status;
};

// Every bondline's fields, one after the other.
Fields fields_of(const SceneFileBulk& bulk, const SceneRecord& r) {
  Fields f;
  f.u = adherent_displacements(bulk, r);
  std::vector<double> jump_N, jump_T, sigma_N, sigma_T, length;
  for (const BondlineField& b : bondline_fields(bulk, r)) {
    jump_N.insert(jump_N.end(), b.jump_N.begin(), b.jump_N.end());
    jump_T.insert(jump_T.end(), b.jump_T.begin(), b.jump_T.end());
    sigma_N.insert(sigma_N.end(), b.sigma_N.begin(), b.sigma_N.end());
    sigma_T.insert(sigma_T.end(), b.sigma_T.begin(), b.sigma_T.end());
    length.insert(length.end(), b.length.begin(), b.length.end());
    f.status.insert(f.status.end(), b.status.begin(), b.status.end());
  }
  auto vec = [](const std::vector<double>& v) { return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(v.data(), v.size())); };
  f.jump_N = vec(jump_N);
  f.jump_T = vec(jump_T);
  f.sigma_N = vec(sigma_N);
  f.sigma_T = vec(sigma_T);
  f.length = vec(length);
  return f;
}

}  // namespace

const std::vector<std::string>& scene_distance_quantities() {
  static const std::vector<std::string> q = {"u", "jump_N", "jump_T", "sigma_N", "sigma_T"};
  return q;
}

std::map<std::string, double> scene_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                             const SceneRecord& limit, int* status_diff) {
  const Fields a = fields_of(bulk, layer), b = fields_of(bulk, limit);
  // The scales: the limit mode's; the layer mode's where the limit's is negligible beside it (a law
  // that carries nothing: a scale of round-off size made every stress distance overflow, 8.2e+300).
  auto scale = [](double limit, double layer) { return std::max(limit >= 1e-9 * layer ? limit : layer, 1e-300); };
  const double U = scale(b.u.cwiseAbs().maxCoeff(), a.u.cwiseAbs().maxCoeff());  // mm
  const double sigma = scale(std::max(b.sigma_N.cwiseAbs().maxCoeff(), b.sigma_T.cwiseAbs().maxCoeff()),
                             std::max(a.sigma_N.cwiseAbs().maxCoeff(), a.sigma_T.cwiseAbs().maxCoeff()));
  std::map<std::string, double> e;
  e["u"] = relative_distance(a.u, b.u, Eigen::VectorXd::Ones(a.u.size()), U);
  e["jump_N"] = relative_distance(a.jump_N, b.jump_N, b.length, U);
  e["jump_T"] = relative_distance(a.jump_T, b.jump_T, b.length, U);
  e["sigma_N"] = relative_distance(a.sigma_N, b.sigma_N, b.length, sigma);
  e["sigma_T"] = relative_distance(a.sigma_T, b.sigma_T, b.length, sigma);
  if (status_diff) {  // the combined status of every node of S against the limit's
    *status_diff = 0;
    for (std::size_t k = 0; k < std::min(a.status.size(), b.status.size()); ++k) *status_diff += a.status[k] != b.status[k];
  }
  return e;
}

double reaction_distance(const SceneRecord& a, const SceneRecord& b) {
  double diff = 0, ref = 0;
  for (const auto& [name, R] : b.reactions) {
    const auto it = a.reactions.find(name);
    const Eigen::Vector2d Ra = it == a.reactions.end() ? Eigen::Vector2d::Zero() : it->second;
    diff += (Ra - R).squaredNorm();
    ref += R.squaredNorm();
  }
  return ref > 0 ? std::sqrt(diff / ref) : std::sqrt(diff);
}

const std::vector<std::string>& verdict_quantities() {
  static const std::vector<std::string> q = {"reactions", "u", "peel_at_d", "shear_at_d"};
  return q;
}

EndStresses peaks_at_distance(const SceneFileBulk& bulk, const SceneRecord& record, double d) {
  EndStresses out;
  out.d = d;
  out.peel = out.peel_end = -INFINITY;
  for (const BondlineField& f : bondline_fields(bulk, record)) {
    const EndStresses e = end_stresses(f, d);
    out.peel = std::max(out.peel, e.peel);
    out.shear = std::max(out.shear, e.shear);
    out.peel_end = std::max(out.peel_end, e.peel_end);
    out.shear_end = std::max(out.shear_end, e.shear_end);
  }
  return out;
}

std::vector<ReactionComponent> reaction_components(const Model& model) {
  // The unknowns: one reaction per held nodal DOF, in the order of the conditions; a DOF held twice
  // belongs to the first condition (as LinearSystem's reactions).
  std::set<std::pair<int, int>> seen;  // (global DOF, body)
  std::vector<Eigen::Vector3d> columns;  // each unknown's (F_x, F_y, M / size) about the origin
  std::vector<std::pair<std::string, int>> owner;
  double size = 1e-300;
  for (const Body& b : model.bodies)
    for (int k = 0; k < b.mesh.num_nodes(); ++k) size = std::max(size, b.mesh.nodes.row(k).cwiseAbs().maxCoeff());
  for (const DirichletCondition& c : model.dirichlet)
    for (int node : c.nodes) {
      if (!seen.insert({model.dof_offset(c.body) + 2 * node + c.component, c.body}).second) continue;
      const Eigen::Vector2d x = model.bodies[c.body].mesh.nodes.row(node).transpose();
      const Eigen::Vector2d e = Eigen::Vector2d::Unit(c.component);
      columns.emplace_back(e.x(), e.y(), (x.x() * e.y() - x.y() * e.x()) / size);
      owner.emplace_back(c.name, c.component);
    }
  Eigen::MatrixXd At(columns.size(), 3);  // Aᵀ: one row per unknown
  for (std::size_t j = 0; j < columns.size(); ++j) At.row(static_cast<Eigen::Index>(j)) = columns[j].transpose();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(At);
  std::vector<ReactionComponent> out;
  std::set<std::pair<std::string, int>> done;
  for (const auto& key : owner) {
    if (!done.insert(key).second) continue;
    Eigen::VectorXd phi = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(columns.size()));
    for (std::size_t j = 0; j < owner.size(); ++j)
      if (owner[j] == key) phi[static_cast<Eigen::Index>(j)] = 1;
    const Eigen::VectorXd y = qr.solve(phi);
    out.push_back({key.first, key.second, (At * y - phi).norm() <= 1e-9 * phi.norm()});
  }
  return out;
}

std::string determinate_reactions(const std::vector<ReactionComponent>& components) {
  std::string s;
  for (const ReactionComponent& c : components)
    if (c.determinate) s += (s.empty() ? "" : ", ") + c.group + (c.component == 0 ? " x" : " y");
  return s;
}

std::map<std::string, double> verdict_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                               const SceneRecord& limit, double d) {
  std::map<std::string, double> e;
  // The reactions: the components that can differ, each on its own size (floored, see the header).
  double largest = 0;
  for (const auto& [group, R] : limit.reactions) largest = std::max(largest, R.cwiseAbs().maxCoeff());
  double worst = std::nan("");
  for (const ReactionComponent& c : reaction_components(bulk.model())) {
    if (c.determinate || !limit.reactions.count(c.group)) continue;
    const double b = limit.reactions.at(c.group)[c.component];
    const double a = layer.reactions.count(c.group) ? layer.reactions.at(c.group)[c.component] : 0.0;
    const double distance = std::abs(a - b) / std::max({std::abs(b), 1e-3 * largest, 1e-300});
    worst = std::isnan(worst) ? distance : std::max(worst, distance);
  }
  e["reactions"] = worst;
  e["u"] = scene_distance(bulk, layer, limit).at("u");
  const EndStresses a = peaks_at_distance(bulk, layer, d), b = peaks_at_distance(bulk, limit, d);
  double peel_scale = 0, shear_scale = 0;  // the limit's largest |σ_N|, |σ_T| on every bondline
  for (const BondlineField& f : bondline_fields(bulk, limit))
    for (std::size_t k = 0; k < f.s.size(); ++k) {
      peel_scale = std::max(peel_scale, std::abs(f.sigma_N[k]));
      shear_scale = std::max(shear_scale, std::abs(f.sigma_T[k]));
    }
  e["peel_at_d"] = std::abs(a.peel - b.peel) / std::max(peel_scale, 1e-300);
  e["shear_at_d"] = std::abs(a.shear - b.shear) / std::max(shear_scale, 1e-300);
  return e;
}

void check_peak_distance(const SceneFileBulk& bulk, double d) {
  double shortest = INFINITY;
  for (const Interface& S : bulk.limit_interfaces(0, false)) {
    double length = 0;
    for (std::size_t k = 1; k < S.nodes.size(); ++k) length += (S.nodes[k].x - S.nodes[k - 1].x).norm();
    shortest = std::min(shortest, length);
  }
  if (d > 0.5 * shortest) {
    std::ostringstream s;
    s << "--peak-distance " << d << " mm is beyond half the shortest bondline (" << shortest
      << " mm long): a peak at d from each end would read past its middle";
    throw std::invalid_argument(s.str());
  }
}

}  // namespace thinlayer
