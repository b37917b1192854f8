#include "core/interface/classifier.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace thinlayer {

double classify_coefficient(double ratio, double reference, const ClassifierThresholds& t) {
  if (!(ratio >= 0) || !std::isfinite(ratio)) throw std::invalid_argument("classifier: ratio must be finite and >= 0");
  if (!(reference > 0) || !std::isfinite(reference)) throw std::invalid_argument("classifier: reference must be finite and > 0");
  if (ratio < t.zero_below * reference) return 0.0;
  if (ratio > t.infinite_above * reference) return std::numeric_limits<double>::infinity();
  return ratio;
}

InterfaceLaw classify_layer(const LayerData& layer, const AdherentData& adherent, double friction,
                            const ClassifierThresholds& t) {
  if (!(layer.eps > 0) || !std::isfinite(layer.eps)) throw std::invalid_argument("classifier: eps must be finite and > 0");
  if (!(adherent.L > 0)) throw std::invalid_argument("classifier: L must be > 0");
  const double lambda_bar = classify_coefficient(layer.lambda_eps / layer.eps, adherent.lambda_m / adherent.L, t);
  const double mu_bar = classify_coefficient(layer.mu_eps / layer.eps, adherent.mu_m / adherent.L, t);
  return InterfaceLaw::make(lambda_bar, mu_bar, friction);
}

}  // namespace thinlayer
