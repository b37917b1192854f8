#pragma once
// Deliberately distorted meshes, for the stress tests of S5: a mesh whose interior nodes are
// moved by a reproducible pseudo-random offset.
#include <cstdint>

#include "core/mesh/mesh.h"

namespace thinlayer {

// Moves every node that lies on no named node set or edge set (the interior) by an offset
// drawn uniformly from [-fraction h, fraction h] in x and in y, h the given element size. The
// boundary stays where it is, so supports, loads and interfaces are unchanged. The offsets come
// from a fixed hash of (seed, node index): the same call gives the same mesh on every machine.
// On a structured grid of spacing h every cell stays valid for fraction < 1/4 (quads) and
// < 1/6 (the triangles of a split grid): a corner's cross product is at least h²(1 - 4 fraction),
// respectively h²(1 - 6 fraction). Beyond that a cell may invert; check with mesh_quality().

// Throws std::invalid_argument unless 0 <= fraction < 0.5 and h > 0.
void distort_interior(Mesh& mesh, double fraction, double h, std::uint64_t seed = 1);

}  // namespace thinlayer
