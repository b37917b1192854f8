#pragma once
// Making room for the layers of a scene's layer mode (SPEC §5, "Real thickness").
//
// The minus body of a bondline keeps its geometry; the plus body's nodes on the bondline move by
// ε along their nodal normal (minus → plus), and the layer's band fills the gap. So that a layer
// can be as thick as the joint allows, not only as thick as the plus body's first row of cells,
// the whole plus body moves with its bondline: its nodes follow the elastic extension of the
// bondline's offset (a plane-strain body, ν = 0.25, each cell's modulus scaled by (mean area / its
// area) so that the small cells along the bondline move almost rigidly; the offset imposed on its
// bondline nodes, its nodes on any other bondline held, everything else free). Where every offset
// of a body is the same (a straight bondline, a body free to move away) the body translates by it,
// exactly: the lap joint's upper strip moves up by ε. A closed curved bondline shrinks its plus
// body (a plug); a body held on another bondline is squeezed between the two. The offset is linear
// in ε, so each cell corner's orientation is a quadratic in ε, and the thickness at which the first
// cell inverts is found exactly.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/mesh/mesh.h"

namespace thinlayer {

// Imposed displacements of some nodes of one body (mm): the bondline offsets and the held nodes (0).
using NodeOffsets = std::map<int, Eigen::Vector2d>;

struct Morph {
  std::vector<Mesh> meshes;  // every body, moved where it had offsets
  // The smallest s > 0 at which some cell of a moved body would invert if the offsets were
  // scaled by s (s = 1: the offsets asked for); +inf if none ever does.
  double inversion_scale = 0;
  std::string inverting_body;            // where: the body's name
  Eigen::Vector2d inverting_cell_centre;  // and the cell's centre before moving (mm)
};

// `offsets[b]`: the imposed displacements of body b (empty: the body does not move). A body with
// offsets must have at least two of them (no rigid motion is left). Q1 and P1 cells.
Morph morph_bodies(const std::vector<Mesh>& meshes, const std::vector<std::string>& names,
                   const std::vector<NodeOffsets>& offsets);

}  // namespace thinlayer
