#pragma once
// Structured Q1 bands through a thin layer, and simple mesh-quality figures.
//
// No gmsh here: a band is pure arithmetic on two matched polylines, so it works for layers
// much thinner than gmsh's geometric tolerance (thickness 1e-8 relative to a length of
// order 1 and below).
#include <Eigen/Core>

#include "core/mesh/mesh.h"

namespace thinlayer {

using FacePolyline = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

// A structured Q1 band between two matched polylines: node i of `minus_face` faces node i of
// `plus_face` (same count, ordered the same way along the band). `elements_across` >= 2
// elements through the thickness; intermediate nodes on the straight segment minus_i→plus_i,
// at minus_i + (j / elements_across)·(plus_i − minus_i); the face nodes are copied exactly.
//
// Numbering: node (i, j) (i along the band, j = 0 on the minus face .. elements_across on the
// plus face) is i·(elements_across + 1) + j. Cells counter-clockwise (whichever side of
// `minus_face` the band lies on), listed i-major.
//
// Named sets: node sets "S-" (the minus_face nodes, in order) and "S+" (plus_face, in
// order); edge sets "S-" and "S+" (consecutive face segments, oriented with the band on
// their left, listed in face order — so one of them runs against the node order); node sets
// "end_first", "end_last" (the elements_across + 1 nodes of each end segment, from the minus
// to the plus face).
//
// Throws std::invalid_argument on mismatched sizes, fewer than 2 nodes, elements_across < 2,
// non-finite coordinates, or a face pair that would give an inverted or degenerate cell (the
// message names the face segment i → i+1 and the layer j). The test is relative: every
// corner of every cell must have a positive sine between its two sides, beyond what
// round-off in the node coordinates can produce (so it holds at any thickness and scale).
Mesh layer_band(const Eigen::Ref<const FacePolyline>& minus_face,
                const Eigen::Ref<const FacePolyline>& plus_face, int elements_across);

struct MeshQuality {
  double min_angle_deg = 0, max_angle_deg = 0;  // interior corner angles over all cells
  double max_aspect_ratio = 0;                   // longest / shortest side of a cell
  double min_scaled_jacobian = 0;                // see mesh_quality
  int cells = 0;
};

// Quality figures of a mesh, over all its cells:
//  - corner angles: the interior angle at each corner of each (counter-clockwise) cell, in
//    (0°, 360°); a reflex corner (> 180°) means a non-convex quad, a zero one a degenerate
//    cell;
//  - aspect ratio: longest / shortest side of each cell (infinite for a zero-length side);
//  - scaled Jacobian at the corners: cross(e1, e2) / (|e1| |e2|) with e1, e2 the two sides
//    leaving the corner (the sine of the corner angle; 1 for a rectangle, <= 0 for an
//    inverted corner); for P1 times 2/√3, so that an equilateral triangle scores 1 (the usual
//    Verdict definitions).
// Throws std::invalid_argument on a mesh without cells.
MeshQuality mesh_quality(const Mesh& mesh);

}  // namespace thinlayer
