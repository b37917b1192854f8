#pragma once
// The user's own joint (SPEC §5): a JSON scene file, read and checked against its schema.
// Lengths in mm, stresses and moduli in daN/mm², λ̄ and μ̄ in daN/mm³, tractions in daN/mm².
//
// Every key is known (a typo is refused, not ignored), every value has its type and range,
// and each error names the file, line and column of the bad key or value. Paths (geometry,
// mesh) are relative to the scene file's folder.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "cases/scene/json_positions.h"
#include "core/fem/material.h"
#include "core/interface/law.h"
#include "core/mesh/mesh.h"

namespace thinlayer {

struct SceneBodySpec {
  std::string name;    // the key in "bodies"
  std::string group;   // gmsh physical surface
  double lambda = 0, mu = 0;  // daN/mm²
  std::string where;   // "<file>:<line>:<col>" of its key, for later errors (a group missing from the mesh)
  std::string group_where;
};

// The glue of layer mode: λ_ε = ε^γ λ_g, μ_ε = ε^δ μ_g (γ ≥ 0, 0 ≤ δ < 2).
struct SceneLayerSpec {
  double gamma = 1, delta = 1;
  double lambda_g = 0, mu_g = 0;  // daN/mm²
};

struct SceneInterfaceSpec {
  std::string group;          // gmsh physical curve(s) shared by both bodies
  std::string plus, minus;    // body names; the normal points from minus into plus
  double friction = 0;
  std::optional<SceneLayerSpec> layer;  // both modes
  std::optional<InterfaceLaw> law;      // or: a limit law only (λ̄, μ̄ may be inf)
  std::string where, group_where;
};

struct SceneSupportSpec {
  std::string group;                            // physical curve or point
  std::array<std::optional<double>, 2> u;       // mm; empty = free
  std::string where;
};

struct SceneLoadSpec {
  std::string group;               // physical curve
  std::array<double, 2> traction;  // daN/mm², (x, y)
  std::string where;
};

struct SceneSpec {
  std::string file;    // the scene file, as given
  std::string folder;  // its folder: paths below are relative to it
  std::string name;
  std::string geometry, mesh;  // exactly one set: a .geo to mesh, or a .msh 4.1 used as is (full paths)
  std::string geometry_where;
  std::optional<double> h_interface, h_far;  // mm, "mesh_size" (geometry only)
  ElementType element = ElementType::Q1;
  PlaneHypothesis plane = PlaneHypothesis::Strain;
  std::vector<SceneBodySpec> bodies;  // in file order
  SceneInterfaceSpec interface;
  std::vector<SceneSupportSpec> supports;
  std::vector<SceneLoadSpec> loads;
  std::vector<double> eps;  // the studies' ε grid (mm); empty = the default one
  int layer_elements = 2;
  std::size_t max_nodes = 2'000'000;  // --max-nodes: a larger mesh is refused before meshing (mesh_estimate.h)

  int body_index(const std::string& name) const;  // -1 if none
  // The limit law: the scene's "law", or the limit of its layer (Table 1, like the dovetail).
  InterfaceLaw limit_law() const;
  bool has_layer() const { return interface.layer.has_value(); }
};

// Reads and checks a scene file: throws InputError with "<file>:<line>:<col>: ..." (or
// "scene file X does not exist").
SceneSpec read_scene_spec(const std::string& path);
SceneSpec scene_spec_from_json(const PositionedJson& json, const std::string& folder);

}  // namespace thinlayer
