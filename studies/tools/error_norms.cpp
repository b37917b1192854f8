#include "studies/tools/error_norms.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace thinlayer {

double weighted_norm(const Eigen::VectorXd& a, const Eigen::VectorXd& w) {
  if (a.size() != w.size()) throw std::invalid_argument("weighted_norm: one weight per value needed");
  return std::sqrt((w.array() * a.array().square()).sum());
}

double relative_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& w, double scale) {
  if (a.size() != b.size() || a.size() != w.size())
    throw std::invalid_argument("relative_distance: fields and weights must have the same size");
  if ((w.array() < 0).any()) throw std::invalid_argument("relative_distance: weights must be >= 0");
  if (!(scale > 0) || !std::isfinite(scale)) throw std::invalid_argument("relative_distance: scale must be finite and > 0");
  const double floor = scale * std::sqrt(w.sum());
  const double denominator = std::max(weighted_norm(b, w), floor);
  if (!(denominator > 0)) throw std::invalid_argument("relative_distance: empty field");
  return weighted_norm(a - b, w) / denominator;
}

}  // namespace thinlayer
