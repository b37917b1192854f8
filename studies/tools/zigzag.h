#pragma once
// The node-to-node zigzag of a stress along the dovetail's right flank (S2's quadrature control,
// studies/drivers/quadrature_control.h): the mode that selective integration leaves free in a
// nearly incompressible layer (cases/layer_quadrature.h), excited at the slot's bottom corner
// and decaying up the flank over ℓ_z nodes.
#include <optional>
#include <vector>

#include "studies/tools/mode_distance.h"

namespace thinlayer {

// The S nodes of the right flank farther than `corner_distance` (L units) from both of its
// corners (0: every node strictly between them), from the bottom corner up.
std::vector<int> right_flank_nodes(const DovetailNodes& nodes, double corner_distance = 0);

// The alternating part of v along a chain of nodes: z_i = (v_{i−1} − 2 v_i + v_{i+1}) / 4 for the
// interior nodes (a zigzag a(−1)^i gives |z_i| = |a|; a straight line gives 0). One fewer at each end.
std::vector<double> alternating_part(const std::vector<double>& v);

// The decay length, in nodes, of |z| away from its peak: −1/slope of ln|z| over the `span` nodes
// after the peak (5: the zigzag's reach on the dovetail is 0.6 … 8 nodes for ε = 1e-4 … 1e-8, the
// flank 16 nodes long). Empty when fewer than 3 nodes remain after the peak or |z| does not decay.
std::optional<double> zigzag_reach(const std::vector<double>& z, int span = 5);

// The root mean square of z over its entries (daN/mm² for a stress).
double rms(const std::vector<double>& z);

}  // namespace thinlayer
