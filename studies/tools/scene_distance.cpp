#include "studies/tools/scene_distance.h"

#include <algorithm>
#include <stdexcept>

#include "studies/tools/error_norms.h"

namespace thinlayer {

namespace {

// Row of node `node` of body `body` in a record: the adherents come first, in scene order,
// in both modes (the layer is the last body).
int row_of(const SceneFileBulk& bulk, int body, int node) {
  int offset = 0;
  for (int b = 0; b < body; ++b) offset += bulk.meshes().bodies[b].num_nodes();
  return offset + node;
}

int adherent_nodes(const SceneFileBulk& bulk) {
  int n = 0;
  for (const Mesh& m : bulk.meshes().bodies) n += m.num_nodes();
  return n;
}

struct Fields {
  Eigen::VectorXd u, jump_N, jump_T, sigma_N, sigma_T;
};

Fields fields_of(const SceneFileBulk& bulk, const Interface& S, const SceneRecord& r) {
  const int n = adherent_nodes(bulk);
  if (r.u.rows() < n || r.interfaces.empty()) throw std::invalid_argument("scene distance: record does not fit the scene");
  Fields f;
  f.u.resize(2 * n);
  for (int i = 0; i < n; ++i) f.u.segment<2>(2 * i) = r.u.row(i).transpose();
  const int m = static_cast<int>(S.nodes.size());
  f.jump_N.resize(m);
  f.jump_T.resize(m);
  for (int k = 0; k < m; ++k) {
    const InterfaceNode& s = S.nodes[k];
    const Eigen::Vector2d d = r.u.row(row_of(bulk, s.minus_body, s.minus_node)).transpose() -
                              r.u.row(row_of(bulk, s.plus_body, s.plus_node)).transpose();  // u⁻ − u⁺
    f.jump_N[k] = s.normal.dot(d);
    f.jump_T[k] = -s.tangent().dot(d);
  }
  f.sigma_N = r.interfaces.front().sigma_N;  // S (limit) or S+ (layer): the plus body's face
  f.sigma_T = r.interfaces.front().sigma_T;
  if (f.sigma_N.size() != m) throw std::invalid_argument("scene distance: S has a different node count");
  return f;
}

Interface limit_interface(const SceneFileBulk& bulk) {
  return make_scene_limit_interface(bulk.spec(), bulk.model(), bulk.interface_nodes(), InterfaceLaw{});
}

}  // namespace

const std::vector<std::string>& scene_distance_quantities() {
  static const std::vector<std::string> q = {"u", "jump_N", "jump_T", "sigma_N", "sigma_T"};
  return q;
}

std::map<std::string, double> scene_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                             const SceneRecord& limit, int* status_diff) {
  const Interface S = limit_interface(bulk);
  const Fields a = fields_of(bulk, S, layer), b = fields_of(bulk, S, limit);
  const double U = std::max(b.u.cwiseAbs().maxCoeff(), 1e-300);  // mm
  const double sigma = std::max({b.sigma_N.cwiseAbs().maxCoeff(), b.sigma_T.cwiseAbs().maxCoeff(), 1e-300});
  Eigen::VectorXd length(S.nodes.size());
  for (std::size_t k = 0; k < S.nodes.size(); ++k) length[static_cast<Eigen::Index>(k)] = S.nodes[k].length;
  std::map<std::string, double> e;
  e["u"] = relative_distance(a.u, b.u, Eigen::VectorXd::Ones(a.u.size()), U);
  e["jump_N"] = relative_distance(a.jump_N, b.jump_N, length, U);
  e["jump_T"] = relative_distance(a.jump_T, b.jump_T, length, U);
  e["sigma_N"] = relative_distance(a.sigma_N, b.sigma_N, length, sigma);
  e["sigma_T"] = relative_distance(a.sigma_T, b.sigma_T, length, sigma);
  if (status_diff) {
    const std::vector<int>& statuses = layer.combined_status.empty() ? layer.interfaces.front().status : layer.combined_status;
    const std::vector<int>& reference = limit.interfaces.front().status;
    *status_diff = 0;
    for (std::size_t k = 0; k < std::min(statuses.size(), reference.size()); ++k) *status_diff += statuses[k] != reference[k];
  }
  return e;
}

}  // namespace thinlayer
