#include "core/solvers/answer_statuses.h"

#include <stdexcept>

namespace thinlayer {

std::vector<Active> answer_statuses(const ContactProblem& problem, const Eigen::VectorXd& r, double tolerance) {
  const int m = problem.num_nodes();
  if (r.size() != 2 * m) throw std::invalid_argument("answer_statuses: r does not fit the problem");
  std::vector<Active> out(m, Active::Gap);
  int k0 = 0;  // the classification is relative to each interface's largest stress (SPEC §1.2)
  for (const Interface& interface : problem.interfaces()) {
    const int n = static_cast<int>(interface.nodes.size());
    Eigen::VectorXd sigma_N(n), sigma_T(n);
    for (int i = 0; i < n; ++i) {
      sigma_N[i] = r[2 * (k0 + i)] / interface.nodes[i].length;
      sigma_T[i] = r[2 * (k0 + i) + 1] / interface.nodes[i].length;
    }
    const std::vector<NodeStatus> s = classify_statuses(std::vector<InterfaceLaw>(n, interface.law), sigma_N, sigma_T, tolerance);
    const InterfaceLaw& law = interface.law;
    for (int i = 0; i < n; ++i) {
      Active& a = out[k0 + i];
      if (law.bilateral) a = law.normal_active() || law.K_T() > 0 ? Active::Bonded : Active::Gap;
      else if (s[i] == NodeStatus::Gap || !law.normal_active()) a = Active::Gap;
      else if (!law.tangential_active()) a = Active::Frictionless;
      else if (s[i] == NodeStatus::Slide) a = sigma_T[i] > 0 ? Active::SlidePositive : Active::SlideNegative;
      else a = Active::Stick;
    }
    k0 += n;
  }
  return out;
}

}  // namespace thinlayer
