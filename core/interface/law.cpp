#include "core/interface/law.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace thinlayer {

Limit limit_of(double value) {
  if (value == 0) return Limit::Zero;
  if (std::isinf(value)) return Limit::Infinite;
  return Limit::Finite;
}

const char* to_string(Limit l) {
  switch (l) {
    case Limit::Zero: return "0";
    case Limit::Finite: return "finite";
    case Limit::Infinite: return "inf";
  }
  return "?";
}

InterfaceLaw InterfaceLaw::make(double lambda_bar, double mu_bar, double friction) {
  auto check = [](const char* name, double v) {
    if (std::isnan(v) || v < 0) {
      std::ostringstream msg;
      msg << name << " must be a number in [0, inf], got " << v;
      throw std::invalid_argument(msg.str());
    }
  };
  check("lambda_bar", lambda_bar);
  check("mu_bar", mu_bar);
  if (!(friction >= 0) || std::isinf(friction)) {
    std::ostringstream msg;
    msg << "friction must be a finite number >= 0, got " << friction;
    throw std::invalid_argument(msg.str());
  }
  return InterfaceLaw{lambda_bar, mu_bar, friction};
}

InterfaceLaw InterfaceLaw::make_bilateral(double lambda_bar, double mu_bar) {
  InterfaceLaw law = make(lambda_bar, mu_bar, 0.0);
  law.bilateral = true;
  return law;
}

InterfaceLaw InterfaceLaw::tie() {
  const double inf = std::numeric_limits<double>::infinity();
  return make_bilateral(inf, inf);
}

char InterfaceLaw::table1_case() const {
  // Rows of Table 1 by μ̄ (0, finite, ∞), columns by λ̄ (∞, finite, 0).
  static const char table[3][3] = {{'e', 'c', 'a'}, {'f', 'd', 'b'}, {'i', 'h', 'g'}};
  const int row = static_cast<int>(limit_of(mu_bar));
  const int col = 2 - static_cast<int>(limit_of(lambda_bar));
  return table[row][col];
}

std::string InterfaceLaw::describe() const {
  std::string text = bilateral ? "bilateral spring, Table 1 class (" : "Table 1 case (";
  text += table1_case();
  text += ")";
  return text;
}

LocalStress local_stress(const InterfaceLaw& law, double jump_N, double jump_T) {
  if (std::isinf(law.K_N()) || std::isinf(law.K_T()))
    throw std::invalid_argument("local_stress: the law is rigid (K = inf); the stress is not a function of the jump");
  LocalStress s;
  if (law.bilateral) return {-law.K_N() * jump_N, -law.K_T() * jump_T};  // either sign of [u]_N
  s.sigma_N = -law.K_N() * std::max(jump_N, 0.0);  // spring in series with a stop
  const double threshold = law.friction * std::abs(s.sigma_N);
  const double trial = -law.K_T() * jump_T;         // spring alone
  // Spring in series with a skidding block: the spring force never exceeds the threshold.
  s.sigma_T = std::abs(trial) <= threshold ? trial : std::copysign(threshold, trial);
  return s;
}

}  // namespace thinlayer
