#include "core/solvers/descent_blocks.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace thinlayer {

std::vector<RowKind> tresca_rows(const ContactProblem& problem, const Eigen::VectorXd& s) {
  std::vector<RowKind> kind(2 * problem.num_nodes(), RowKind::Free);
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceLaw& law = problem.law(k);
    if (law.bilateral) {
      if (law.normal_active()) kind[2 * k] = RowKind::Equality;
      if (law.K_T() > 0) kind[2 * k + 1] = RowKind::Equality;
      continue;
    }
    if (law.normal_active()) kind[2 * k] = RowKind::Obstacle;
    if (law.normal_active() && law.tangential_active() && s[k] > 0) kind[2 * k + 1] = RowKind::Friction;
  }
  return kind;
}

bool layer_descent_applies(const ContactProblem& problem) {
  if (problem.system().floating_bands().empty()) return false;
  const Eigen::VectorXd& C = problem.compliance();
  for (int row = 0; row < C.size(); ++row)
    if (std::isfinite(C[row]) && C[row] != 0) return false;  // a finite spring
  return true;
}

namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

}  // namespace

DescentBlocks descent_blocks(const MixedSystem& mixed) {
  const int ny = mixed.num_unknowns();
  const auto& B = mixed.B_y();
  UnionFind sets(ny);
  // Each band column's unknowns (its translation and every level above its foot) stay together.
  for (int b = 0; b < mixed.num_bands(); ++b) {
    const BandLayout& L = mixed.band_layout(b);
    const int offset = mixed.band_offset(b);
    for (int i = 0; i < L.columns; ++i)
      for (int j = 1; j <= L.across; ++j)
        for (int c = 0; c < 2; ++c) {
          sets.join(offset + L.v(i, j) + c, offset + L.t(i));
          sets.join(offset + L.t(i) + c, offset + L.t(i));
        }
  }
  // Every unknown of a node's two rows joins the node's block.
  const int m2 = static_cast<int>(B.rows());
  std::vector<int> first_of_row(m2, -1);
  for (int row = 0; row < m2; ++row)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, row); it; ++it) {
      const int anchor = first_of_row[row - row % 2];
      if (anchor < 0) first_of_row[row - row % 2] = static_cast<int>(it.col());
      else sets.join(static_cast<int>(it.col()), anchor);
    }
  DescentBlocks out;
  std::map<int, int> block_of_root;
  out.block_of_row.assign(m2, -1);
  for (int row = 0; row < m2; ++row) {
    const int anchor = first_of_row[row - row % 2];
    if (anchor < 0) continue;  // a node whose rows touch no free unknown (prescribed on both sides)
    const int root = sets.find(anchor);
    auto [it, added] = block_of_root.emplace(root, static_cast<int>(out.blocks.size()));
    if (added) out.blocks.emplace_back();
    out.blocks[it->second].rows.push_back(row);
    out.block_of_row[row] = it->second;
  }
  for (int j = 0; j < ny; ++j) {
    auto it = block_of_root.find(sets.find(j));
    if (it == block_of_root.end()) out.interior.push_back(j);
    else out.blocks[it->second].y.push_back(j);
  }
  return out;
}

}  // namespace thinlayer
