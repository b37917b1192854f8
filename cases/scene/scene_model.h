#pragma once
// The finite-element models of a scene file in both modes (SPEC §5).
//
// Limit mode: the user's bodies, in file order, and the interface "S" between plus and minus,
// node to node (SPEC §1.4): normals and tributary lengths from the plus body's edges.
// Layer mode (as the dovetail, SPEC §2.2): the minus body keeps its geometry; the plus body's
// interface nodes move by ε along their nodal normal (minus → plus), its other nodes stay;
// a structured band of layer_elements ≥ 2 Q1 elements fills the gap. The layer is appended as
// the last body, "layer", so the adherents' nodes keep their rows in both modes. Interfaces
// "S+" (plus body / layer) and "S-" (layer / minus body), Signorini–Coulomb with the scene's f.
//
// A body with no support is held by its contact alone, like the layer (Body::floating).
#include <string>
#include <vector>

#include "cases/scene/scene_mesh.h"
#include "cases/scene/scene_spec.h"
#include "core/fem/model.h"
#include "core/interface/interface.h"
#include "core/mesh/layer_band.h"

namespace thinlayer {

// The interface curve as matched node pairs, ordered along it (one open chain).
struct SceneInterfaceNodes {
  std::vector<int> plus, minus;  // node k of S: node plus[k] of the plus body, minus[k] of the minus body
};

// Checks what the meshes must satisfy (InputError at the scene file's line and column): the
// interface curve lies on the boundary of both of its bodies, with matching nodes, as one open
// chain; every body is held by a support or by the interface; a support or load touches some
// body. Returns the interface's node pairs.
SceneInterfaceNodes check_scene_meshes(const SceneSpec& spec, const SceneMeshes& meshes);

Model make_scene_limit_model(const SceneSpec& spec, const SceneMeshes& meshes);
Interface make_scene_limit_interface(const SceneSpec& spec, const Model& model, const SceneInterfaceNodes& S,
                                     const InterfaceLaw& law);

// The largest ε the plus body's elements along the interface allow: half the smallest depth,
// along the nodal normal, of a plus-body cell touching the interface (mm). A thicker layer
// would flatten or invert those cells.
double scene_thickest_layer(const SceneSpec& spec, const SceneMeshes& meshes, const SceneInterfaceNodes& S);

struct SceneLayerModel {
  Model model;
  std::vector<Interface> interfaces;  // S+, S-
  int layer_body = 0;
  MeshQuality layer_quality;
  double lambda_eps = 0, mu_eps = 0;  // daN/mm²
};
// Throws std::invalid_argument for ε outside (0, scene_thickest_layer] or a scene without a
// "layer" (a "law" scene has no layer mode).
SceneLayerModel make_scene_layer_model(const SceneSpec& spec, const SceneMeshes& meshes, const SceneInterfaceNodes& S,
                                       double eps);

}  // namespace thinlayer
