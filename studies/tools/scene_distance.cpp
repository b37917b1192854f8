#include "studies/tools/scene_distance.h"

#include <algorithm>
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
  const double U = std::max(b.u.cwiseAbs().maxCoeff(), 1e-300);  // mm
  const double sigma = std::max({b.sigma_N.cwiseAbs().maxCoeff(), b.sigma_T.cwiseAbs().maxCoeff(), 1e-300});
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

}  // namespace thinlayer
