#pragma once
// The user's own joint (SPEC §5): a JSON scene file, read and checked against its schema.
// Units: lengths in mm; forces in daN (default, "units": "mm-daN": stresses and moduli in
// daN/mm²) or N ("units": "mm-N": stresses and moduli in MPa). Nothing is converted: every number
// of a scene is in its own units, and the results are written in them (they say which).
// λ̄ and μ̄ are in the stress unit per mm.
//
// Every key is known (a typo is refused, not ignored), every value has its type and range,
// and each error names the file, line and column of the bad key or value. Paths (geometry,
// mesh) are relative to the scene file's folder.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cases/scene/json_positions.h"
#include "cases/scene/scene_sources.h"
#include "core/fem/material.h"
#include "core/interface/glue.h"
#include "core/interface/law.h"
#include "core/mesh/mesh.h"

namespace thinlayer {

// The longest name a scene gives (its "name", a group's): names become HDF5 groups, scene ids
// and the report's file names (cases/scene/json_positions.h caps a key, a body's name, alike).
constexpr std::size_t max_scene_name_bytes = 64;

struct SceneBodySpec {
  std::string name;    // the key in "bodies"
  std::string group;   // gmsh physical surface
  double lambda = 0, mu = 0;  // stress unit (daN/mm² or MPa), given or from "E", "nu"
  std::string where;   // "<file>:<line>:<col>" of its key, for later errors (a group missing from the mesh)
  std::string group_where;
};

// The paper's glue family in layer mode: λ_ε = ε^γ λ_g, μ_ε = ε^δ μ_g (γ ≥ 0, 0 ≤ δ < 2).
struct SceneLayerSpec {
  double gamma = 1, delta = 1;
  double lambda_g = 0, mu_g = 0;  // stress unit (per mm^γ, per mm^δ)
};

// An engineer's glue: fixed Young's modulus and Poisson ratio, and its nominal thickness.
struct SceneGlueSpec {
  double E = 0, nu = 0;  // stress unit, 1
  double thickness = 0;  // mm
};

struct SceneInterfaceSpec {
  // The bondline's name in the results: "" in the one-bondline form ("interface": interface/S,
  // S+, S-), its group in the list form ("interfaces": interface/<group>/S, ...).
  std::string name;
  std::string group;          // gmsh physical curve(s) shared by both bodies
  std::string plus, minus;    // body names; the normal points from minus into plus
  double friction = 0;        // on a contact face (none needed when both faces are bonded)
  LayerFaces faces;           // "faces": each face of the layer bonded or in contact (default contact)
  std::optional<SceneLayerSpec> layer;  // the paper's family: both modes
  std::optional<SceneGlueSpec> glue;    // or an engineer's glue: both modes
  std::optional<double> lambda_bar, mu_bar;  // or "law": a limit law only (may be inf)
  // "make_room": the direction in which the plus body moves to make room for the layer in layer
  // mode (a unit vector; given as any nonzero [dx, dy]). Absent: the bondline's nodal normal (from
  // minus into plus). A scarf joint's load axis keeps its pulled strip in line (docs/joints.md, "Make room
  // in a chosen direction").
  std::optional<std::array<double, 2>> make_room;
  std::string where, group_where, make_room_where;

  bool has_layer_mode() const { return layer.has_value() || glue.has_value(); }
  // The glue of layer mode (the paper's family or an engineer's); throws if the bondline gives a law only.
  Glue glue_model() const;
  // "bondline 'x'" or "the interface", for messages.
  std::string label() const;
};

enum class LoadKind { Traction, Pressure, Force };
const char* to_string(LoadKind kind);

struct SceneLoadSpec {
  std::string group;               // physical curve (a force may also be on a physical point)
  LoadKind kind = LoadKind::Traction;
  std::array<double, 2> vector{};  // traction (stress unit, x and y) or force (force unit per mm of thickness)
  double pressure = 0;             // stress unit, normal to the curve, compressive positive
  std::string where;
};

struct SceneSupportSpec {
  std::string group;                            // physical curve or point
  std::array<std::optional<double>, 2> u;       // mm; empty = free
  std::string where;
};

// "mm-daN" (default) or "mm-N".
struct SceneUnits {
  std::string force = "daN";
  std::string name() const { return "mm-" + force; }
  std::string stress() const { return force == "N" ? "MPa" : "daN/mm^2"; }
  std::string stiffness() const { return force + "/mm^3"; }  // λ̄, μ̄, K: stress per mm
};

struct SceneSpec {
  std::string file;    // the scene file, as given
  std::string folder;  // its folder: paths below are relative to it
  std::string name;
  std::string geometry, mesh;  // exactly one set: a .geo to mesh, or a .msh 4.1 used as is (full paths)
  std::string geometry_where;
  // The geometry or mesh and every file it reads, read and checked once: the bytes gmsh is given
  // (cases/scene/scene_sources.h). Shared by the copies of a spec (the studies' bulks).
  std::shared_ptr<const SceneSources> sources;
  std::optional<double> h_interface, h_far;  // mm, "mesh_size" (geometry only)
  ElementType element = ElementType::Q1;
  PlaneHypothesis plane = PlaneHypothesis::Strain;
  SceneUnits units;
  std::optional<double> characteristic_length;  // mm, L of SPEC §1.3 (default: from the adherents)
  std::vector<SceneBodySpec> bodies;  // in file order
  std::vector<SceneInterfaceSpec> interfaces;  // in file order; one in the "interface" form
  bool interface_list = false;  // given as "interfaces": [...] (output names <group>/S, ...)
  std::vector<SceneSupportSpec> supports;
  std::vector<SceneLoadSpec> loads;
  std::vector<double> eps;  // the studies' ε grid (mm); empty = the default one
  int layer_elements = 2;
  std::size_t max_nodes = 2'000'000;  // --max-nodes: a larger mesh is refused before meshing (mesh_estimate.h)

  int body_index(const std::string& name) const;  // -1 if none
  // Some bondline has a layer mode ("layer" or "glue").
  bool has_layer() const;
  // Every layer-mode bondline gives an engineer's glue (its thicknesses are the scene's own).
  bool engineer_glue_only() const;
};

// Reads and checks a scene file: throws InputError with "<file>:<line>:<col>: ..." (or
// "scene file X does not exist").
SceneSpec read_scene_spec(const std::string& path);
SceneSpec scene_spec_from_json(const PositionedJson& json, const std::string& folder);

}  // namespace thinlayer
