#include "studies/tools/bondline_fields.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace thinlayer {

namespace {

// Row of node `node` of body `body` in a record: the adherents come first, in scene order,
// in both modes (the layers are the last bodies).
int row_of(const SceneFileBulk& bulk, int body, int node) {
  int offset = 0;
  for (int b = 0; b < body; ++b) offset += bulk.meshes().bodies[b].num_nodes();
  return offset + node;
}

}  // namespace

Eigen::VectorXd adherent_displacements(const SceneFileBulk& bulk, const SceneRecord& r) {
  int n = 0;
  for (const Mesh& m : bulk.meshes().bodies) n += m.num_nodes();
  if (r.u.rows() < n) throw std::invalid_argument("scene record " + r.id + " does not fit the scene");
  Eigen::VectorXd u(2 * n);
  for (int i = 0; i < n; ++i) u.segment<2>(2 * i) = r.u.row(i).transpose();
  return u;
}

std::vector<BondlineField> bondline_fields(const SceneFileBulk& bulk, const SceneRecord& r) {
  const std::vector<Interface> limit = bulk.limit_interfaces(0, /*with_laws=*/false);
  std::vector<BondlineField> out;
  std::size_t status_at = 0;  // into the layer record's combined status (every bondline, in order)
  for (std::size_t i = 0; i < limit.size(); ++i) {
    const Interface& S = limit[i];
    const InterfaceFields& face = r.interfaces.at(plus_face_of(bulk, r, static_cast<int>(i)));
    const std::size_t m = S.nodes.size();
    if (static_cast<std::size_t>(face.sigma_N.size()) != m)
      throw std::invalid_argument("scene record " + r.id + ": bondline " + std::to_string(i) + " has another node count");
    // The minus adherent's face: S- in layer mode, else the plus face's (limit mode, a law only).
    const int plus_index = plus_face_of(bulk, r, static_cast<int>(i));
    const InterfaceFields& minus_face =
        r.interfaces.at(face.name.size() > 1 && face.name.back() == '+' ? plus_index + 1 : plus_index);
    BondlineField f;
    f.bondline = bulk.spec().interfaces[i].group;
    double s = 0;
    for (std::size_t k = 0; k < m; ++k) {
      const InterfaceNode& n = S.nodes[k];
      if (k > 0) s += (n.x - S.nodes[k - 1].x).norm();
      const Eigen::Vector2d d = r.u.row(row_of(bulk, n.minus_body, n.minus_node)).transpose() -
                                r.u.row(row_of(bulk, n.plus_body, n.plus_node)).transpose();  // u⁻ − u⁺
      f.s.push_back(s);
      f.x.push_back(n.x.x());
      f.y.push_back(n.x.y());
      f.length.push_back(n.length);
      f.sigma_N.push_back(face.sigma_N[static_cast<Eigen::Index>(k)]);
      f.sigma_T.push_back(face.sigma_T[static_cast<Eigen::Index>(k)]);
      f.sigma_N_minus.push_back(minus_face.sigma_N[static_cast<Eigen::Index>(k)]);
      f.sigma_T_minus.push_back(minus_face.sigma_T[static_cast<Eigen::Index>(k)]);
      f.jump_N.push_back(n.normal.dot(d));
      f.jump_T.push_back(-n.tangent().dot(d));
      f.status.push_back(r.combined_status.empty() ? face.status[k] : r.combined_status.at(status_at + k));
    }
    status_at += m;
    out.push_back(std::move(f));
  }
  return out;
}

BondlinePeaks bondline_peaks(const BondlineField& f) {
  BondlinePeaks p;
  if (!f.s.empty()) p.s_peel = p.s_shear = f.s.front();
  for (std::size_t k = 0; k < f.s.size(); ++k) {
    if (f.sigma_N[k] > p.peel) p.peel = f.sigma_N[k], p.s_peel = f.s[k];
    if (std::abs(f.sigma_T[k]) > p.shear) p.shear = std::abs(f.sigma_T[k]), p.s_shear = f.s[k];
    p.compression = std::max(p.compression, -f.sigma_N[k]);
  }
  return p;
}

}  // namespace thinlayer

namespace thinlayer {

namespace {

// values at arc length s (linear between nodes; clamped to the bondline).
double at(const std::vector<double>& s, const std::vector<double>& values, double target) {
  if (s.empty()) return 0.0;
  if (target <= s.front()) return values.front();
  if (target >= s.back()) return values.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), target) - s.begin());
  const double w = (target - s[k - 1]) / (s[k] - s[k - 1]);
  return (1 - w) * values[k - 1] + w * values[k];
}

}  // namespace

EndStresses end_stresses(const BondlineField& f, double d) {
  EndStresses e;
  e.d = d;
  e.peel = e.peel_end = -INFINITY;
  if (f.s.empty()) return {d, 0, 0, 0, 0};
  const double length = f.s.back();
  for (const double target : {f.s.front() + d, length - d})
    for (const auto* faces : {&f.sigma_N, &f.sigma_N_minus}) e.peel = std::max(e.peel, at(f.s, *faces, target));
  for (const double target : {f.s.front() + d, length - d})
    for (const auto* faces : {&f.sigma_T, &f.sigma_T_minus}) e.shear = std::max(e.shear, std::abs(at(f.s, *faces, target)));
  for (const std::size_t k : {std::size_t{0}, f.s.size() - 1}) {
    e.peel_end = std::max({e.peel_end, f.sigma_N[k], f.sigma_N_minus[k]});
    e.shear_end = std::max({e.shear_end, std::abs(f.sigma_T[k]), std::abs(f.sigma_T_minus[k])});
  }
  return e;
}

}  // namespace thinlayer
