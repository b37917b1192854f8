#pragma once
// Isotropic linear elasticity in 2D, plane strain or plane stress.
// Lamé coefficients in daN/mm² (1 GPa = 100 daN/mm²).
#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

namespace thinlayer {

enum class PlaneHypothesis { Strain, Stress };

inline const char* to_string(PlaneHypothesis p) {
  return p == PlaneHypothesis::Strain ? "strain" : "stress";
}

struct Material {
  double lambda = 0;  // daN/mm²
  double mu = 0;      // daN/mm²
  PlaneHypothesis plane = PlaneHypothesis::Strain;

  // Elasticity matrix in Voigt form (σ11, σ22, σ12) = D (e11, e22, 2 e12).
  Eigen::Matrix3d D() const {
    if (!(std::isfinite(lambda) && std::isfinite(mu)) || mu <= 0 || lambda + mu <= 0)
      throw std::invalid_argument("material: need finite Lamé coefficients with mu > 0 and "
                                  "lambda + mu > 0 (got lambda = " + std::to_string(lambda) +
                                  ", mu = " + std::to_string(mu) + ")");
    // Plane stress is plane strain with the reduced λ* = 2λμ/(λ+2μ) (σ33 = 0).
    const double l = plane == PlaneHypothesis::Strain ? lambda : 2 * lambda * mu / (lambda + 2 * mu);
    Eigen::Matrix3d d;
    d << l + 2 * mu, l, 0,
         l, l + 2 * mu, 0,
         0, 0, mu;
    return d;
  }
};

}  // namespace thinlayer
