#include "studies/tools/mode_distance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cases/dovetail/dovetail.h"
#include "cases/dovetail/dovetail_mesh.h"
#include "studies/tools/error_norms.h"

namespace thinlayer {

namespace {

const double U = std::hypot(dovetail::pull_x, dovetail::pull_y);  // mm
const double sigma_ref = dovetail::mu_m * U / 1.0;                // daN/mm², L = 1

// The displacement of node i of the base or of the tenon in a record (bodies in the order
// base, [layer,] tenon: the tenon's nodes are the last ones).
Eigen::Vector2d base_u(const SceneRecord& r, int i) { return r.u.row(i).transpose(); }
Eigen::Vector2d tenon_u(const SceneRecord& r, const DovetailNodes& n, int i) {
  return r.u.row(r.u.rows() - n.tenon_nodes + i).transpose();
}

// Keeps the entries whose mask is true.
Eigen::VectorXd masked(const Eigen::VectorXd& v, const std::vector<bool>& keep) {
  Eigen::VectorXd out(std::count(keep.begin(), keep.end(), true));
  for (Eigen::Index i = 0, j = 0; i < v.size(); ++i)
    if (keep[i]) out[j++] = v[i];
  return out;
}

struct Fields {
  Eigen::VectorXd u, jump_N, jump_T, sigma_N, sigma_T;
};

Fields fields_of(const SceneRecord& r, const DovetailNodes& n) {
  if (r.u.rows() < n.base_nodes + n.tenon_nodes) throw std::invalid_argument("mode_distance: record has too few nodes");
  if (r.interfaces.empty()) throw std::invalid_argument("mode_distance: record has no interface");
  const int m = static_cast<int>(n.S.size());
  const InterfaceFields& stress_face = r.interfaces.front();  // S (limit) or S+ (layer)
  if (stress_face.sigma_N.size() != m) throw std::invalid_argument("mode_distance: S has a different node count");
  Fields f;
  f.u.resize(2 * (n.base_nodes + n.tenon_nodes));
  for (int i = 0; i < n.base_nodes; ++i) f.u.segment<2>(2 * i) = base_u(r, i);
  for (int i = 0; i < n.tenon_nodes; ++i) f.u.segment<2>(2 * (n.base_nodes + i)) = tenon_u(r, n, i);
  f.jump_N.resize(m);
  f.jump_T.resize(m);
  for (int k = 0; k < m; ++k) {
    const Eigen::Vector2d d = base_u(r, n.S[k].minus_node) - tenon_u(r, n, n.S[k].plus_node);  // u⁻ − u⁺
    f.jump_N[k] = n.S[k].normal.dot(d);
    f.jump_T[k] = -n.S[k].tangent().dot(d);
  }
  f.sigma_N = stress_face.sigma_N;
  f.sigma_T = stress_face.sigma_T;
  return f;
}

// The tenon-top reaction's distance (daN per unit thickness), relative to the reference's
// reaction or, where that vanishes, to R_ref = σ_ref × the top edge's width: in case (a) the
// limit tenon is free but for its pull, so it needs no force at all.
double reaction_distance(const SceneRecord& a, const SceneRecord& b) {
  const auto ra = a.reactions.find("tenon_top"), rb = b.reactions.find("tenon_top");
  if (ra == a.reactions.end() || rb == b.reactions.end()) throw std::invalid_argument("mode_distance: no tenon_top reaction");
  const double R_ref = sigma_ref * 2 * dovetail::mouth_half_width;
  return (ra->second - rb->second).norm() / std::max(rb->second.norm(), R_ref);
}

// The status of each S node: the record's own in limit mode, combined over the faces in layer mode.
const std::vector<int>& combined_status(const SceneRecord& r) {
  return r.combined_status.empty() ? r.interfaces.front().status : r.combined_status;
}

}  // namespace

const std::vector<std::string>& distance_quantities() {
  static const std::vector<std::string> q = {"R_top",  "u",       "u_away",       "jump_N",  "jump_N_away", "jump_T",
                                             "jump_T_away", "sigma_N", "sigma_N_away", "sigma_T", "sigma_T_away"};
  return q;
}

double distance_to_slot_corner(const Eigen::Vector2d& x) {
  using namespace dovetail;
  const Eigen::Vector2d corners[4] = {{-mouth_half_width, 0}, {mouth_half_width, 0},
                                      {-slot_bottom_half_width, -slot_depth}, {slot_bottom_half_width, -slot_depth}};
  double d = INFINITY;
  for (const Eigen::Vector2d& c : corners) d = std::min(d, (x - c).norm());
  return d;
}

ModeDistance mode_distance(const SceneRecord& layer, const SceneRecord& limit, const DovetailNodes& nodes,
                           double corner_radius) {
  const Fields a = fields_of(layer, nodes), b = fields_of(limit, nodes);
  const int m = static_cast<int>(nodes.S.size());
  Eigen::VectorXd length(m);
  std::vector<bool> S_away(m);
  for (int k = 0; k < m; ++k) {
    length[k] = nodes.S[k].length;
    S_away[k] = distance_to_slot_corner(nodes.base_x.row(nodes.S[k].minus_node).transpose()) > corner_radius;
  }
  std::vector<bool> bulk_away;  // per DOF, like the u vectors
  for (int i = 0; i < nodes.base_nodes; ++i)
    bulk_away.insert(bulk_away.end(), 2, distance_to_slot_corner(nodes.base_x.row(i).transpose()) > corner_radius);
  for (int i = 0; i < nodes.tenon_nodes; ++i)
    bulk_away.insert(bulk_away.end(), 2, distance_to_slot_corner(nodes.tenon_x.row(i).transpose()) > corner_radius);

  ModeDistance d;
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(a.u.size());
  d.e["u"] = relative_distance(a.u, b.u, ones, U);
  d.e["u_away"] = relative_distance(masked(a.u, bulk_away), masked(b.u, bulk_away), masked(ones, bulk_away), U);
  auto interface = [&](const std::string& name, const Eigen::VectorXd& x, const Eigen::VectorXd& y, double scale) {
    d.e[name] = relative_distance(x, y, length, scale);
    d.e[name + "_away"] = relative_distance(masked(x, S_away), masked(y, S_away), masked(length, S_away), scale);
  };
  interface("jump_N", a.jump_N, b.jump_N, U);
  interface("jump_T", a.jump_T, b.jump_T, U);
  interface("sigma_N", a.sigma_N, b.sigma_N, sigma_ref);
  interface("sigma_T", a.sigma_T, b.sigma_T, sigma_ref);
  d.e["R_top"] = reaction_distance(layer, limit);

  const std::vector<int>& statuses = combined_status(layer);
  const std::vector<int>& reference = combined_status(limit);
  for (int k = 0; k < std::min<int>(statuses.size(), reference.size()); ++k) d.status_diff += statuses[k] != reference[k];
  return d;
}

}  // namespace thinlayer
