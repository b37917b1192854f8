#include "cases/layer_scene.h"

#include "cases/film_admissibility.h"
#include "cases/layer_quadrature.h"

namespace thinlayer {

std::vector<int> combined_statuses(const InterfaceFields& plus_face, const InterfaceFields& minus_face) {
  const size_t n = std::min(plus_face.status.size(), minus_face.status.size());
  std::vector<int> combined;
  for (size_t k = 0; k < n; ++k)
    combined.push_back(static_cast<int>(combined_status(static_cast<NodeStatus>(plus_face.status[k]),
                                                        static_cast<NodeStatus>(minus_face.status[k]))));
  return combined;
}

LayerCounts finish_layer_record(SceneRecord& r, const Material& layer, int layer_elements, bool selective,
                                const MeshQuality& quality) {
  r.numbers["lambda_eps"] = layer.lambda;
  r.numbers["mu_eps"] = layer.mu;
  r.integers["layer_elements"] = layer_elements;
  r.text["layer_quadrature"] = quadrature_name(selective);
  r.numbers["layer_min_angle_deg"] = quality.min_angle_deg;
  r.numbers["layer_max_aspect_ratio"] = quality.max_aspect_ratio;
  const InterfaceFields& plus = r.interfaces.at(0);
  const InterfaceFields& minus = r.interfaces.at(1);
  r.combined_status = combined_statuses(plus, minus);
  record_film_admissibility(r);
  std::vector<NodeStatus> combined;
  for (int v : r.combined_status) combined.push_back(static_cast<NodeStatus>(v));
  return {plus.counts(), minus.counts(), count_statuses(combined)};
}

}  // namespace thinlayer
