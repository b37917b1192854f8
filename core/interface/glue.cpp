#include "core/interface/glue.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace thinlayer {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

[[noreturn]] void refuse(const std::string& what, double value) {
  std::ostringstream s;
  s << what << ", got " << value;
  throw std::invalid_argument(s.str());
}

}  // namespace

LameModuli lame_from_young(double E, double nu) {
  if (!(E > 0) || !std::isfinite(E)) refuse("the glue's E must be finite and > 0", E);
  if (!(nu > -1 && nu < 0.5)) refuse("Poisson's ratio must be in (-1, 0.5)", nu);
  return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

const char* to_string(FaceHold face) { return face == FaceHold::Bonded ? "bonded" : "contact"; }

InterfaceLaw face_law(FaceHold face, double friction) {
  return face == FaceHold::Bonded ? InterfaceLaw::tie() : InterfaceLaw::make(inf, inf, friction);
}

InterfaceLaw layer_limit_law(double lambda_bar, double mu_bar, const LayerFaces& faces, double friction) {
  return faces.both_bonded() ? InterfaceLaw::make_bilateral(lambda_bar, mu_bar)
                             : InterfaceLaw::make(lambda_bar, mu_bar, friction);
}

Glue Glue::scaled(double gamma, double delta, double lambda_g, double mu_g) {
  if (!(gamma >= 0) || !std::isfinite(gamma)) refuse("gamma must be finite and >= 0", gamma);
  if (!(delta >= 0 && delta < 2)) refuse("delta must be in [0, 2)", delta);
  if (!(lambda_g >= 0) || !std::isfinite(lambda_g)) refuse("lambda_g must be finite and >= 0", lambda_g);
  if (!(mu_g > 0) || !std::isfinite(mu_g)) refuse("mu_g must be finite and > 0", mu_g);
  Glue g;
  g.gamma_ = gamma;
  g.delta_ = delta;
  g.lambda_g_ = lambda_g;
  g.mu_g_ = mu_g;
  return g;
}

Glue Glue::engineer(double E, double nu, double thickness) {
  if (!(thickness > 0) || !std::isfinite(thickness)) refuse("the glue's thickness must be finite and > 0 (mm)", thickness);
  const LameModuli m = lame_from_young(E, nu);
  Glue g;
  g.engineer_ = true;
  g.gamma_ = g.delta_ = 0;  // fixed moduli: ε⁰
  g.lambda_g_ = m.lambda;
  g.mu_g_ = m.mu;
  g.E_ = E;
  g.nu_ = nu;
  g.thickness_ = thickness;
  return g;
}

LameModuli Glue::at(double eps) const {
  if (!(eps > 0) || !std::isfinite(eps)) refuse("the layer's thickness must be finite and > 0 (mm)", eps);
  if (engineer_) return {lambda_g_, mu_g_};
  return {std::pow(eps, gamma_) * lambda_g_, std::pow(eps, delta_) * mu_g_};
}

InterfaceLaw Glue::limit_law(double eps, const AdherentData& reference, const LayerFaces& faces,
                             double friction) const {
  if (engineer_) {  // SPEC §1.3: the line's own finite springs, K_N = (λ_g + 2μ_g)/ε, K_T = μ_g/ε
    (void)reference;
    const LameModuli m = at(eps);
    return layer_limit_law(m.lambda / eps, m.mu / eps, faces, friction);
  }
  // lim ε^(p−1) g as ε → 0: ∞ below p = 1, g at 1, 0 above (paper §3.1.8, Table 1); 0 for g = 0.
  auto limit_ratio = [](double p, double g) { return g == 0 ? 0.0 : p < 1 ? inf : p > 1 ? 0.0 : g; };
  return layer_limit_law(limit_ratio(gamma_, lambda_g_), limit_ratio(delta_, mu_g_), faces, friction);
}

InterfaceLaw Glue::classified_law(double eps, const AdherentData& reference, const LayerFaces& faces,
                                  double friction) const {
  if (!engineer_) return limit_law(eps, reference, faces, friction);
  const LameModuli m = at(eps);
  const InterfaceLaw chosen = classify_layer({eps, m.lambda, m.mu}, reference, friction);  // paper §3.3
  return layer_limit_law(chosen.lambda_bar, chosen.mu_bar, faces, friction);
}

}  // namespace thinlayer
