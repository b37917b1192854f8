#pragma once
// Choosing the law from physical data (paper §3.3): an engineer knows ε, λ_ε, μ_ε, not the
// limits. λ_ε/ε and μ_ε/ε are compared with the adherents' λ_m/L and μ_m/L: below 3 % of the
// reference the limit is taken as 0, above 30 times as ∞, in between as the finite ratio.
#include "core/interface/law.h"

namespace thinlayer {

struct ClassifierThresholds {
  double zero_below = 0.03;       // fraction of the reference value
  double infinite_above = 30.0;   // multiple of the reference value
};

// One coefficient: ratio = λ_ε/ε (daN/mm³), reference = λ_m/L (daN/mm³).
double classify_coefficient(double ratio, double reference, const ClassifierThresholds& t = {});

struct LayerData {
  double eps = 0;        // layer thickness, mm
  double lambda_eps = 0; // daN/mm²
  double mu_eps = 0;     // daN/mm²
};
struct AdherentData {
  double lambda_m = 0;   // daN/mm²
  double mu_m = 0;       // daN/mm²
  double L = 1;          // characteristic length, mm
};

InterfaceLaw classify_layer(const LayerData& layer, const AdherentData& adherent, double friction,
                            const ClassifierThresholds& t = {});

}  // namespace thinlayer
