#include "cases/layer_quadrature.h"

namespace thinlayer {

bool selective_layer_quadrature(double gamma, double delta) { return !(gamma < 1 && gamma < delta); }

bool uses_selective_quadrature(LayerQuadrature quadrature, double gamma, double delta) {
  switch (quadrature) {
    case LayerQuadrature::Selective: return true;
    case LayerQuadrature::Full: return false;
    case LayerQuadrature::ByExponents: break;
  }
  return selective_layer_quadrature(gamma, delta);
}

const char* quadrature_name(bool selective) { return selective ? "selective" : "full"; }

}  // namespace thinlayer
