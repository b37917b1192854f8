#include "core/solvers/kink_line_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/linalg/extended_products.h"

namespace thinlayer {

namespace {

Long dot(const LongVector& a, const Eigen::VectorXd& b) {
  Long sum = 0;
  for (Eigen::Index i = 0; i < b.size(); ++i) sum += a[i] * Long(b[i]);
  return sum;
}

LongVector row_times(const Eigen::SparseMatrix<double, Eigen::RowMajor>& B, const Eigen::VectorXd& x) {
  LongVector out = LongVector::Zero(B.rows());
  for (int row = 0; row < B.rows(); ++row)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, row); it; ++it)
      out[row] += Long(it.value()) * Long(x[it.col()]);
  return out;
}

}  // namespace

KinkLineSearch kink_line_search(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& F,
                                const Eigen::SparseMatrix<double, Eigen::RowMajor>& B, const Eigen::VectorXd& g_D,
                                const std::vector<RowKind>& kind, const Eigen::VectorXd& row_threshold,
                                const Eigen::VectorXd& y,
                                const Eigen::VectorXd& delta, double alpha_max_in) {
  KinkLineSearch out;
  const LongVector gradient = times(K, y) - F.cast<Long>();
  const Long slope0 = dot(gradient, delta);
  const Long curvature = dot(times(K, delta), delta);
  LongVector d = row_times(B, y);
  for (Eigen::Index i = 0; i < d.size(); ++i) d[i] += Long(g_D[i]);
  const LongVector dd = row_times(B, delta);

  const Long alpha_max = alpha_max_in;
  out.alpha_max = double(alpha_max);

  // φ'(α) on each interval between breakpoints: slope0 + α·curvature + Σ s_i dd_i σ_i.
  struct Break {
    Long alpha;
    Long jump;  // the change of Σ s_i dd_i σ_i there: 2 s_i |dd_i|
  };
  std::vector<Break> breaks;
  Long friction_slope = 0;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (kind[i] != RowKind::Friction || dd[i] == 0) continue;
    const Long s = row_threshold[i];
    // σ_i just after α = 0: the sign of d_i, or where d_i = 0 the sign of dd_i.
    const Long sigma0 = d[i] > 0 ? 1 : d[i] < 0 ? -1 : (dd[i] > 0 ? 1 : -1);
    friction_slope += s * dd[i] * sigma0;
    if (d[i] != 0 && sigma0 * dd[i] < 0) breaks.push_back({-d[i] / dd[i], 2 * s * std::abs(dd[i])});
  }
  std::sort(breaks.begin(), breaks.end(), [](const Break& a, const Break& b) { return a.alpha < b.alpha; });
  out.slope_at_zero = double(slope0 + friction_slope);
  Long constant = slope0 + friction_slope, lo = 0;
  for (size_t j = 0; j <= breaks.size(); ++j) {
    const Long hi = j < breaks.size() ? std::min(breaks[j].alpha, alpha_max) : alpha_max;
    // φ' = constant + α·curvature on [lo, hi].
    if (constant + lo * curvature >= 0) {
      out.alpha = double(lo);
      return out;
    }
    if (curvature > 0) {
      const Long root = -constant / curvature;
      if (root <= hi) {
        out.alpha = double(root);
        return out;
      }
    }
    if (hi >= alpha_max) break;
    constant += breaks[j].jump;
    lo = hi;
    ++out.breakpoints;
  }
  out.alpha = double(alpha_max);
  out.clipped = true;
  return out;
}

}  // namespace thinlayer
