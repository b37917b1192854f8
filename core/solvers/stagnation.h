#pragma once
// When to give up on an outer iteration that no longer gets anywhere. The floating-layer paths
// keep the best iterate they met, so stopping changes no answer, only how long a scene that
// will not converge keeps the machine: at ε = 1e-8 the dual path's anchor updates stall at a
// round-off floor and ran on to their cap (2500 steps, 20–90 s a scene).
#include <algorithm>
#include <deque>

namespace thinlayer {

class Stagnation {
 public:
  // Stagnant once the best residual has not halved over `window` outer steps.
  explicit Stagnation(int window) : window_(window) {}
  // Records the best residual after one more outer step; true when it is time to stop.
  bool after_step(double best) {
    history_.push_back(best);
    if (static_cast<int>(history_.size()) <= window_) return false;
    history_.pop_front();
    return !(best < 0.5 * history_.front());
  }

 private:
  int window_;
  std::deque<double> history_;
};

}  // namespace thinlayer
