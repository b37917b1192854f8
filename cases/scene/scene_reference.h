#pragma once
// The reference against which SPEC §1.3 classifies an engineer's glue in a scene file: the
// adherents' moduli λ_m, μ_m and the characteristic length L (λ_g/t and μ_g/t are compared with
// λ_m/L and μ_m/L: below 3 % the limit is 0, above 30 times ∞, the ratio in between).
//
// L is the scene's "characteristic_length" if it gives one; otherwise the thickness of its
// thinnest adherent, measured as 2·area/perimeter of each body joined by a bondline (a strip's
// thickness t: 2 l t / (2 l + 2 t) ≈ t for a long strip; a disc's radius). The paper takes L = 1
// for its dovetail, "the characteristic length of the adherents" (§3.3).
// λ_m and μ_m of a bondline are the smaller of its two adherents' (the softer side decides how
// stiff the glue must be to count as rigid). A λ_m ≤ 0 (an adherent with ν ≤ 0) is no reference
// for λ_g/t: μ_m stands in for it.
#include <vector>

#include "cases/scene/scene_spec.h"
#include "core/interface/classifier.h"
#include "core/mesh/mesh.h"

namespace thinlayer {

// 2·area/perimeter of a mesh (mm): a strip's thickness, a disc's radius.
double mesh_thickness(const Mesh& mesh);

// The scene's L (mm): the given one, or the smallest mesh_thickness of the bodies on bondlines.
double scene_characteristic_length(const SceneSpec& spec, const std::vector<Mesh>& meshes);

// λ_m, μ_m of bondline i and the scene's L.
AdherentData bondline_reference(const SceneSpec& spec, int i, double L);

}  // namespace thinlayer
