#include "core/mesh/distortion.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace thinlayer {

namespace {

// SplitMix64: a tiny, well-mixed hash, spelled out so that the offsets do not depend on a
// standard library's distribution implementation.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Uniform in [-1, 1) from the top 53 bits.
double symmetric_unit(std::uint64_t bits) { return 2.0 * static_cast<double>(bits >> 11) * 0x1.0p-53 - 1.0; }

}  // namespace

void distort_interior(Mesh& mesh, double fraction, double h, std::uint64_t seed) {
  if (!(fraction >= 0 && fraction < 0.5)) throw std::invalid_argument("mesh distortion must be in [0, 0.5)");
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("mesh distortion: element size must be > 0");
  std::vector<bool> on_boundary(mesh.num_nodes(), false);
  for (const auto& [name, nodes] : mesh.node_sets)
    for (int n : nodes) on_boundary[n] = true;
  for (const auto& [name, edges] : mesh.edge_sets)
    for (const auto& e : edges) on_boundary[e[0]] = on_boundary[e[1]] = true;
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    if (on_boundary[n]) continue;
    const std::uint64_t key = splitmix64(seed ^ splitmix64(static_cast<std::uint64_t>(n)));
    mesh.nodes(n, 0) += fraction * h * symmetric_unit(splitmix64(key));
    mesh.nodes(n, 1) += fraction * h * symmetric_unit(splitmix64(key + 1));
  }
}

}  // namespace thinlayer
