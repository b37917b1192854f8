#pragma once
// A 2D finite-element mesh with named node and edge sets.
//
// Lengths are in the case's length unit (mm for the bar, L = 1 for the dovetail).
// Cells are listed counter-clockwise; a mesh holds one element type.
#include <array>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace thinlayer {

enum class ElementType { Q1, P1 };

inline const char* to_string(ElementType e) { return e == ElementType::Q1 ? "Q1" : "P1"; }

struct Mesh {
  ElementType element = ElementType::Q1;
  // Node coordinates, one row per node.
  Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor> nodes;
  // Cell connectivity: 4 node indices (Q1) or 3 (P1), counter-clockwise.
  std::vector<std::array<int, 4>> quads;
  std::vector<std::array<int, 3>> triangles;
  // Named node sets (sorted along the boundary they describe) and named edge sets
  // (boundary segments, each as its two end nodes, oriented with the body on the left).
  std::map<std::string, std::vector<int>> node_sets;
  std::map<std::string, std::vector<std::array<int, 2>>> edge_sets;

  int num_nodes() const { return static_cast<int>(nodes.rows()); }
  int num_cells() const {
    return element == ElementType::Q1 ? static_cast<int>(quads.size())
                                      : static_cast<int>(triangles.size());
  }
  const std::vector<int>& node_set(const std::string& name) const {
    auto it = node_sets.find(name);
    if (it == node_sets.end()) throw std::runtime_error("mesh has no node set '" + name + "'");
    return it->second;
  }
  const std::vector<std::array<int, 2>>& edge_set(const std::string& name) const {
    auto it = edge_sets.find(name);
    if (it == edge_sets.end()) throw std::runtime_error("mesh has no edge set '" + name + "'");
    return it->second;
  }
};

}  // namespace thinlayer
