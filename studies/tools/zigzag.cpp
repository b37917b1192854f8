#include "studies/tools/zigzag.h"

#include <algorithm>
#include <cmath>

#include "cases/dovetail/dovetail_mesh.h"

namespace thinlayer {

std::vector<int> right_flank_nodes(const DovetailNodes& nodes, double corner_distance) {
  using namespace dovetail;
  // A point of the right flank lies on the line from (0.4, 0) to (0.6, −0.5), strictly inside.
  const Eigen::Vector2d top(mouth_half_width, 0), bottom(slot_bottom_half_width, -slot_depth);
  const Eigen::Vector2d along = (top - bottom).normalized();
  const double length = (top - bottom).norm(), tolerance = 1e-9 + corner_distance;
  std::vector<std::pair<double, int>> found;  // (distance from the bottom corner, S node)
  for (size_t k = 0; k < nodes.S.size(); ++k) {
    const Eigen::Vector2d x = nodes.base_x.row(nodes.S[k].minus_node).transpose() - bottom;
    const double s = x.dot(along), off = std::abs(x.x() * along.y() - x.y() * along.x());
    if (off < 1e-9 && s > tolerance && s < length - tolerance) found.push_back({s, static_cast<int>(k)});
  }
  std::sort(found.begin(), found.end());
  std::vector<int> flank;
  for (const auto& [s, k] : found) flank.push_back(k);
  return flank;
}

std::vector<double> alternating_part(const std::vector<double>& v) {
  std::vector<double> z;
  for (size_t i = 1; i + 1 < v.size(); ++i) z.push_back((v[i - 1] - 2 * v[i] + v[i + 1]) / 4);
  return z;
}

std::optional<double> zigzag_reach(const std::vector<double>& z, int span) {
  if (z.empty()) return std::nullopt;
  size_t peak = 0;
  for (size_t i = 1; i < z.size(); ++i)
    if (std::abs(z[i]) > std::abs(z[peak])) peak = i;
  // Least-squares slope of ln|z_i| against i over the nodes after the peak.
  std::vector<double> n, y;
  for (size_t i = peak + 1; i < z.size() && static_cast<int>(i - peak) <= span; ++i)
    if (std::abs(z[i]) > 0) {
      n.push_back(static_cast<double>(i));
      y.push_back(std::log(std::abs(z[i])));
    }
  if (n.size() < 3) return std::nullopt;
  double mn = 0, my = 0;
  for (size_t i = 0; i < n.size(); ++i) mn += n[i] / n.size(), my += y[i] / n.size();
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < n.size(); ++i) sxy += (n[i] - mn) * (y[i] - my), sxx += (n[i] - mn) * (n[i] - mn);
  const double slope = sxy / sxx;
  if (!(slope < 0)) return std::nullopt;
  return -1 / slope;
}

double rms(const std::vector<double>& z) {
  if (z.empty()) return 0;
  double s = 0;
  for (double v : z) s += v * v;
  return std::sqrt(s / z.size());
}

}  // namespace thinlayer
