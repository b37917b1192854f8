#pragma once
// Anderson acceleration (type II, "Anderson mixing") of a fixed-point iteration x ← G(x):
// with the last m residuals f_k = G(x_k) − x_k, the next iterate is
//   x_{k+1} = G(x_k) − ΔG γ,   γ = argmin ‖f_k − ΔF γ‖,
// ΔF, ΔG the differences of successive residuals and map values. For a map that is linear (or
// nearly) it converges like GMRES instead of like the plain iteration's slowest mode. Used on
// the friction thresholds of the Tresca fixed point and on the anchor of the layer's selection
// spring (core/solvers/floating_layer.cpp).
#include <deque>

#include <Eigen/Core>

namespace thinlayer {

class AndersonAcceleration {
 public:
  explicit AndersonAcceleration(int memory) : memory_(memory) {}
  // Given the current iterate x and its image G(x), the next iterate.
  Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& G_x);
  // Forgets the history (after the map changed, e.g. new contact statuses).
  void reset() {
    residuals_.clear();
    images_.clear();
  }

 private:
  int memory_;
  std::deque<Eigen::VectorXd> residuals_, images_;
};

}  // namespace thinlayer
