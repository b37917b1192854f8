#include "studies/tools/scene_distance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

std::map<std::string, double> verdict_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                               const SceneRecord& limit, double d) {
  std::map<std::string, double> e;
  e["reactions"] = reaction_distance(layer, limit);
  e["u"] = scene_distance(bulk, layer, limit).at("u");
  const EndStresses a = peaks_at_distance(bulk, layer, d), b = peaks_at_distance(bulk, limit, d);
  double sigma = 0;  // the limit's largest |σ| on S
  for (const BondlineField& f : bondline_fields(bulk, limit))
    for (std::size_t k = 0; k < f.s.size(); ++k) sigma = std::max({sigma, std::abs(f.sigma_N[k]), std::abs(f.sigma_T[k])});
  const double floor = std::max(1e-6 * sigma, 1e-300);
  e["peel_at_d"] = std::abs(a.peel - b.peel) / std::max(std::abs(b.peel), floor);
  e["shear_at_d"] = std::abs(a.shear - b.shear) / std::max(std::abs(b.shear), floor);
  return e;
}

}  // namespace thinlayer
