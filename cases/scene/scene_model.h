#pragma once
// The finite-element models of a scene file in both modes (SPEC §5).
//
// Limit mode: the user's bodies, in file order, and one interface per bondline between its plus
// and minus bodies, node to node (SPEC §1.4): normals and tributary lengths from the plus body's
// edges. Named "S" in the one-bondline form, "<group>/S" in the list form.
// Layer mode (as the dovetail, SPEC §2.2): each minus body keeps its geometry; the plus bodies make
// room for the layers (cases/scene/scene_morph.h: their bondline nodes move by ε along the nodal
// normal, minus → plus, the rest of the body follows); a structured band of layer_elements ≥ 2 Q1
// elements fills each gap. The layers are appended after the adherents ("layer", or
// "layer-<group>" in the list form), so the adherents' nodes keep their rows in both modes.
// Interfaces "S+" (plus body / layer) and "S-" (layer / minus body), each face tied (bonded) or
// Signorini-Coulomb with the bondline's f (contact); a bondline that gives a law only keeps it.
//
// A body with no support is held by its interfaces alone, like the layer (Body::floating).
// Loads: a traction, a pressure (normal to the curve, compressive positive) or a force (a
// resultant spread uniformly along the curve, or on a physical point); each is built on the
// model's own node positions, so a moved plus body carries the same resultant force.
#include <string>
#include <vector>

#include "cases/scene/scene_mesh.h"
#include "cases/scene/scene_spec.h"
#include "core/fem/model.h"
#include "core/interface/interface.h"
#include "core/mesh/layer_band.h"

namespace thinlayer {

// One bondline as matched node pairs, ordered along it (one open chain).
struct SceneInterfaceNodes {
  std::vector<int> plus, minus;  // node k of S: node plus[k] of the plus body, minus[k] of the minus body
};

// Checks what the meshes must satisfy (InputError at the scene file's line and column): each
// bondline lies on the boundary of both of its bodies, with matching nodes, as one open chain;
// every body is held by a support or by a bondline, and every group of bodies joined by bondlines
// by some support; a support or load touches some body. Returns each bondline's node pairs.
std::vector<SceneInterfaceNodes> check_scene_meshes(const SceneSpec& spec, const SceneMeshes& meshes);

// The names of bondline i's interfaces in the results: "S", "S+", "S-" in the one-bondline form,
// "<group>/S", ... in the list form. `face`: "S", "S+" or "S-".
std::string interface_name(const SceneSpec& spec, int i, const std::string& face);

Model make_scene_limit_model(const SceneSpec& spec, const SceneMeshes& meshes);
// Bondline i in limit mode, with the given law.
Interface make_scene_limit_interface(const SceneSpec& spec, const Model& model, int i, const SceneInterfaceNodes& S,
                                     const InterfaceLaw& law);

// The thickest layer the joint allows, the same ε on every layer bondline (mm), and why it is
// that: a tenth of the shortest such bondline (a layer thicker than that is not thin), or half
// the thickness at which moving the plus bodies would invert a cell (the body is too thin there).
struct ThickestLayer {
  double eps = 0;  // mm; 0 for a scene without a layer mode
  std::string reason;
};
ThickestLayer scene_thickest_layer(const SceneSpec& spec, const SceneMeshes& meshes,
                                   const std::vector<SceneInterfaceNodes>& S);

struct SceneLayerModel {
  Model model;
  std::vector<Interface> interfaces;  // per bondline in order: S+, S- (a layer) or S (a law only)
  std::vector<int> layer_body;        // per bondline: the index of its layer in model.bodies, or -1
  std::vector<MeshQuality> layer_quality;  // per bondline (cells = 0 without a layer)
  std::vector<double> thickness;      // per bondline, mm (0 without a layer)
  std::vector<LameModuli> moduli;     // per bondline: the layer's λ_ε, μ_ε
};
// `eps`: every layer's thickness (mm), or 0 for each engineer's glue's own thickness. Throws
// std::invalid_argument for a thickness the joint's geometry cannot hold, saying why, and for a
// scene without a layer mode (only laws) or not Q1 (the band is Q1).
SceneLayerModel make_scene_layer_model(const SceneSpec& spec, const SceneMeshes& meshes,
                                       const std::vector<SceneInterfaceNodes>& S, double eps);

// The thickness of bondline i's layer at the asked ε (0: its glue's own; mm). Throws for a
// paper-family layer without ε.
double layer_thickness(const SceneInterfaceSpec& i, double eps);

// The law of a bondline that gives a law only ("law"): bilateral when both faces are bonded.
InterfaceLaw scene_given_law(const SceneInterfaceSpec& i);

// The force resultant [Fx, Fy] each load group applies to the model (force unit per mm of thickness).
std::map<std::string, Eigen::Vector2d> applied_load_resultants(const Model& model);

}  // namespace thinlayer
