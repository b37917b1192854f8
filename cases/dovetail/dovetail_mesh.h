#pragma once
// Meshes of the dovetail assembly (SPEC §2.2), lengths in units of L = 1.
//
//   base Ω⁻:  the rectangle [−1, 1] × [−1, 0] minus the slot, the trapezoid with top edge
//             (−0.4, 0)–(0.4, 0) and bottom edge (−0.6, −0.5)–(0.6, −0.5);
//   tenon Ω⁺: the slot trapezoid plus the stem [−0.4, 0.4] × [0, 0.5];
//   S:        the three slot faces: left flank, bottom, right flank.
//
// Limit mode: one gmsh model, both surfaces sharing the three S curves, so base and tenon
// have the very same nodes along S. The S curves are transfinite (uniform spacing close to
// h_interface); elsewhere the mesh is unstructured, its size growing linearly with the
// distance to S from h_interface to h_far. All cells are Q1: gmsh's "simple full-quad"
// recombination (Mesh.RecombinationAlgorithm = 2, set for the call and restored) meshes
// with half the boundary nodes, recombines and splits every cell into quads, which always
// gives an all-quad mesh but needs an even number of segments on every transfinite curve.
// So each S curve gets the even segment count nearest to its length / h_interface: at the
// default h_interface = 0.025, 22 segments on each flank (length √0.29 ≈ 0.5385) and 48 on
// the bottom (1.2), i.e. 23 + 49 + 23 − 2 = 93 distinct nodes on S.
//
// Layer mode (SPEC §2.2): the base unchanged; the tenon = the limit tenon with its nodes
// moved by offset_map (same cells, same node numbering and sets), which puts its S nodes
// on the slot faces offset inwards by ε; the layer = layer_band between the two.
#include <Eigen/Core>

#include "core/mesh/layer_band.h"
#include "core/mesh/mesh.h"

namespace thinlayer::dovetail {

// Geometry (L = 1).
constexpr double base_half_width = 1.0;      // base: [−1, 1] × [−1, 0]
constexpr double base_depth = 1.0;
constexpr double mouth_half_width = 0.4;     // slot top edge at y = 0
constexpr double slot_bottom_half_width = 0.6;
constexpr double slot_depth = 0.5;           // slot bottom at y = −0.5
constexpr double stem_height = 0.5;          // stem [−0.4, 0.4] × [0, 0.5]

// Length of one flank, √(0.2² + 0.5²), and of S (two flanks and the bottom).
double flank_length();
double interface_length();

// Half-width of the slot at height y ∈ [−0.5, 0]: c(y) = 0.4 − 0.4 y.
double slot_half_width(double y);
// Half-width at height y ∈ [−0.5 + ε, 0] of the slot trapezoid offset inwards by ε on its
// three faces (flanks moved by ε along their inward normals, bottom moved up by ε, top edge
// kept at y = 0): c_ε(y) = c(y) − ε·√1.16 (√1.16 = 1 / cos of the flank's tilt).
double offset_half_width(double y, double eps);
// c_ε(0): the half top width of the offset trapezoid, i.e. the half-width of the layer-mode
// tenon's stem.
double offset_half_width_at_mouth(double eps);

// The continuous map Φ_ε from the limit tenon onto the layer-mode tenon:
//   y ≤ 0 (trapezoid): y' = (1 − 2ε) y (so −0.5 → −0.5 + ε, 0 → 0),
//                      x' = x · c_ε(y') / c(y);
//   y > 0 (stem):      y' = y, x' = x · c_ε(0) / 0.4.
// It maps the slot faces onto the offset faces and the slot corners onto the offset corners.
Eigen::Vector2d offset_map(const Eigen::Vector2d& point, double eps);

struct MeshOptions {
  double h_interface = 0.025;  // spacing along S, in [0.001, 0.5]
  double h_far = 0.1;          // element size far from S, >= h_interface and <= 1
  int layer_elements = 2;      // Q1 elements through the layer (layer mode), >= 2
};

// The number of segments on each flank and on the bottom of S for a given h_interface (the
// even count nearest to length / h_interface, at least 2), and the resulting number of
// distinct nodes on S, 2·flank + bottom + 1.
struct InterfaceSegments {
  int flank = 0, bottom = 0;
  int nodes() const { return 2 * flank + bottom + 1; }
};
InterfaceSegments interface_segments(double h_interface);

// Limit-mode meshes, all Q1, cells counter-clockwise.
//  base:  node set "S" (along S from the left mouth corner (−0.4, 0) down the left flank,
//         along the bottom, up the right flank to (0.4, 0), mouth corners included), edge
//         set "S"; node and edge set "bottom" (y = −1, nodes by increasing x);
//  tenon: node set "S" (same order and the same positions as the base's), edge set "S";
//         node and edge set "top" (y = 0.5, nodes by increasing x).
// Edge sets are oriented with their own body on the left (so the base's "S" edges run
// against the node order and the tenon's with it).
// Throws std::invalid_argument on bad options, std::runtime_error if gmsh fails or does not
// produce the expected mesh (all quads, the expected S nodes, convex cells).
struct LimitMeshes {
  Mesh base, tenon;
};
LimitMeshes make_limit_meshes(const MeshOptions& options = {});

// The thickest layer of the layer mode: a tenth of the characteristic length L = 1 (a thicker layer
// is no thin layer).
constexpr double thickest_layer = 0.1;

// Layer-mode meshes for a layer of thickness eps ∈ (0, thickest_layer]:
//  base:  limit.base, unchanged;
//  tenon: limit.tenon with every node moved by offset_map(·, eps): same cells, node
//         numbering and named sets ("S", "top"); its S nodes lie on the offset faces;
//  layer: layer_band(base S nodes, tenon S nodes, layer_elements): node sets "S-" (node i
//         at the position of the base's S node i), "S+" (at the tenon's S node i),
//         "end_first" (the band's end at the left mouth corner), "end_last" (right mouth);
//         edge sets "S-", "S+" (layer on the left).
// Throws std::invalid_argument on a bad eps or layer_elements, or limit meshes without the
// named sets above; std::runtime_error if a moved tenon cell is not convex.
struct LayerMeshes {
  Mesh base, layer, tenon;
  double eps = 0;
};
LayerMeshes make_layer_meshes(const LimitMeshes& limit, double eps, int layer_elements);

}  // namespace thinlayer::dovetail
