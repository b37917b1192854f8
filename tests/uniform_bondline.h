#pragma once
// Test helper: the closed form of a straight bondline of direction (dx, dy) crossing bodies in one
// uniform stress state (u = G x + c in each body, the same G: ε_xx = 0, ε_yy = e, 2ε_xy = a), so
// that the bondline carries the constant traction σn and a spring law (case d: K_N = λ_g + 2μ_g,
// K_T = μ_g; sticking, or bilateral) makes the jump exactly [u]_N = −σ_N/K_N, [u]_T = −σ_T/K_T.
// Plane strain, mm and daN. Everything here is computed by hand, not by the code under test.
#include <cmath>

#include <Eigen/Core>

struct UniformBondline {
  double dx = 10, dy = 4;                 // the bondline's direction, from its minus-side left end
  double lambda = 4500, mu = 5400;        // every body
  double lambda_g = 2000, mu_g = 1000;    // glue; limit law (d): λ̄ = λ_g, μ̄ = μ_g (γ = δ = 1)
  double e = -1e-3, a = 2e-4;
  double s() const { return dy / std::hypot(dx, dy); }
  double c() const { return dx / std::hypot(dx, dy); }
  Eigen::Vector2d n() const { return {-s(), c()}; }  // from the lower (minus) body into the upper (plus)
  Eigen::Vector2d t() const { return {c(), s()}; }   // n turned clockwise
  Eigen::Matrix2d sigma() const {
    Eigen::Matrix2d S;
    S << lambda * e, mu * a, mu * a, (lambda + 2 * mu) * e;
    return S;
  }
  double sigma_N() const { return n().dot(sigma() * n()); }
  // The minus side pushes the plus body with −σ_N n + σ_T t = σ(−n), the traction on its face.
  double sigma_T() const { return -t().dot(sigma() * n()); }
  double K_N() const { return lambda_g + 2 * mu_g; }
  double K_T() const { return mu_g; }
  double jump_N() const { return -sigma_N() / K_N(); }  // [u]_N > 0: interpenetration under compression
  double jump_T() const { return -sigma_T() / K_T(); }
  Eigen::Vector2d Delta() const { return -jump_N() * n() + jump_T() * t(); }  // u⁺ − u⁻ across the bondline
};
