#pragma once
// Bookkeeping shared by the layer-mode scenes of every case: the layer's attributes, and the
// statuses of S seen through the layer's two faces (SPEC §2.2).
#include <vector>

#include "core/fem/material.h"
#include "core/io/scene_record.h"
#include "core/mesh/layer_band.h"

namespace thinlayer {

// Combined statuses of two faces' fields, node by node: gap if either face is open, else
// slide if either slides, else stick. Node k of both faces is node k of S; a face may extend
// beyond S (the bar's S- under D).
std::vector<int> combined_statuses(const InterfaceFields& plus_face, const InterfaceFields& minus_face);

struct LayerCounts {
  StatusCount plus_face, minus_face, combined;
};

// Adds the layer's attributes (lambda_eps, mu_eps, layer_elements, layer_quadrature, layer mesh
// quality) and the combined statuses to a record whose interfaces are S+ then S-, and returns
// the counts. `selective`: the layer's λ part integrated at the cell centre (cases/layer_quadrature.h).
LayerCounts finish_layer_record(SceneRecord& record, const Material& layer, int layer_elements, bool selective,
                                const MeshQuality& quality);

}  // namespace thinlayer
