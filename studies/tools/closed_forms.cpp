#include "studies/tools/closed_forms.h"

#include <cmath>
#include <limits>

namespace thinlayer {

double Volkersen::omega() const { return std::sqrt((G / eta) * (1 / E1t1 + 1 / E2t2)); }

double Volkersen::shear(double x) const {
  const double w = omega(), g = G / eta;
  const double B = -g * P / (E1t1 * w);
  const double A = g * P * (1 / E2t2 + std::cosh(w * l) / E1t1) / (w * std::sinh(w * l));
  return A * std::cosh(w * x) + B * std::sinh(w * x);
}

double GolandReissner::k_nonlinear() const {
  const double u2 = std::sqrt(3 * P / (2 * E * t)) / t;
  return 1 / (1 + 2 * std::sqrt(2.0) * std::tanh(u2 * c));  // cosh / (cosh + 2√2 sinh)
}

double GolandReissner::k() const { return std::isnan(k_given) ? k_nonlinear() : k_given; }

double GolandReissner::k_prime() const {
  return std::isnan(k_prime_given) ? k() * (c / t) * std::sqrt(3 * P / (E * t)) : k_prime_given;
}

double GolandReissner::beta() const { return std::sqrt(8 * G * t / (E * eta)); }

double GolandReissner::lambda() const { return (c / t) * std::pow(6 * Ea * t / (E * eta), 0.25); }

double GolandReissner::shear(double x) const {
  const double kk = k(), b = beta() / t;
  return P / (8 * c) * (b * c * (1 + 3 * kk) * std::cosh(b * x) / std::sinh(b * c) + 3 * (1 - kk));
}

double GolandReissner::peel(double x) const {
  const double L = lambda();
  if (L > 300) return std::numeric_limits<double>::quiet_NaN();
  const double kk = k(), kp = k_prime();
  const double R1 = std::cosh(L) * std::sin(L) + std::sinh(L) * std::cos(L);
  const double R2 = std::sinh(L) * std::cos(L) - std::cosh(L) * std::sin(L);
  const double Delta = 0.5 * (std::sin(2 * L) + std::sinh(2 * L));
  const double y = L * x / c;
  return P * t / (Delta * c * c) *
         ((R2 * L * L * kk / 2 + L * kp * std::cosh(L) * std::cos(L)) * std::cosh(y) * std::cos(y) +
          (R1 * L * L * kk / 2 + L * kp * std::sinh(L) * std::sin(L)) * std::sinh(y) * std::sin(y));
}

}  // namespace thinlayer
