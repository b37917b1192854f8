#include "core/linalg/inverse_block.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <cblas.h>

namespace thinlayer::inverse_block {

namespace {

// The supernodal elimination forest of a factor. Supernode s holds the columns
// [super[s], super[s+1]) as one dense column-major block of height(s) rows: its own columns
// first, then the rows below, ascending (row indices at rows[pi[s] ...], values at x[px[s]]).
// Its parent holds its first row below its own columns; a parent always comes after its child.
struct Forest {
  const int *super = nullptr, *pi = nullptr, *px = nullptr, *rows = nullptr;
  const double* x = nullptr;
  int count = 0;                   // supernodes
  std::vector<int> supernode_of;   // of each column
  std::vector<int> parent;         // -1 for a root
  std::vector<int> first;          // the first column of s's subtree
  std::vector<int> root;           // the root of s's tree

  int columns(int s) const { return super[s + 1] - super[s]; }
  int height(int s) const { return pi[s + 1] - pi[s]; }
  const double* block(int s) const { return x + px[s]; }
  const int* rows_below(int s) const { return rows + pi[s] + columns(s); }
};

Forest forest_of(const cholmod_factor& L) {
  if (!L.is_super || !L.is_ll || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT)
    throw std::logic_error("inverse_block: needs a real supernodal LL' factor");
  Forest f;
  f.super = static_cast<const int*>(L.super);
  f.pi = static_cast<const int*>(L.pi);
  f.px = static_cast<const int*>(L.px);
  f.rows = static_cast<const int*>(L.s);
  f.x = static_cast<const double*>(L.x);
  f.count = static_cast<int>(L.nsuper);
  f.supernode_of.resize(L.n);
  f.parent.assign(f.count, -1);
  f.first.resize(f.count);
  std::vector<int> subtree_columns(f.count);
  for (int s = 0; s < f.count; ++s) {
    std::fill(f.supernode_of.begin() + f.super[s], f.supernode_of.begin() + f.super[s + 1], s);
    f.first[s] = f.super[s];
    subtree_columns[s] = f.columns(s);
  }
  for (int s = 0; s < f.count; ++s) {
    if (f.height(s) > f.columns(s)) f.parent[s] = f.supernode_of[f.rows_below(s)[0]];
    const int p = f.parent[s];
    if (p < 0) continue;
    f.first[p] = std::min(f.first[p], f.first[s]);
    subtree_columns[p] += subtree_columns[s];
  }
  // Postordered: each subtree's columns are consecutive, so its Γ columns are too.
  for (int s = 0; s < f.count; ++s)
    if (subtree_columns[s] != f.super[s + 1] - f.first[s])
      throw std::logic_error("inverse_block: the factor's ordering is not postordered");
  f.root.resize(f.count);
  for (int s = f.count - 1; s >= 0; --s) f.root[s] = f.parent[s] < 0 ? s : f.root[f.parent[s]];
  return f;
}

// Γ in the factor's order: each one's column of L, ascending, and its unknown of A.
struct SortedGamma {
  std::vector<int> column, unknown;
};

SortedGamma sorted_gamma(const cholmod_factor& L, const std::vector<int>& gamma) {
  const int n = static_cast<int>(L.n);
  std::vector<bool> in_gamma(n, false);
  for (int i : gamma) {
    if (i < 0 || i >= n || in_gamma[i])
      throw std::invalid_argument("inverse_block: the unknowns must be distinct indices of the matrix");
    in_gamma[i] = true;
  }
  const int* perm = static_cast<const int*>(L.Perm);  // column k of L is unknown perm[k] of A
  SortedGamma g;
  for (int k = 0; k < n; ++k)
    if (in_gamma[perm[k]]) g.column.push_back(k), g.unknown.push_back(perm[k]);
  return g;
}

// Z's rows at the columns of the supernodes with Γ below them, stored transposed: supernode s
// holds the Γ range [lo[s], hi[s]) of its subtree, and its part of Zᵀ is a k × columns(s)
// block (k = hi − lo, column-major, leading dimension k). A chain of supernodes with the same
// range (a parent with one child on Γ's paths and no Γ of its own: a separator split into
// several supernodes) shares one panel, side by side, so that their Z_sᵀ Z_s are one update of
// rank columns(panel) instead of several thin ones (each a pass over a k × k block).
struct Panels {
  std::vector<int> lo, hi;           // per supernode
  std::vector<int> panel, column0;   // per supernode: its panel (-1: none), its first column in it
  std::vector<int> width;            // per panel
  std::vector<size_t> offset;        // per panel, into values
  std::vector<double> values;

  int size(int s) const { return hi[s] - lo[s]; }
  double* of(int s) { return values.data() + offset[panel[s]] + static_cast<size_t>(column0[s]) * size(s); }
  bool last_of_panel(int s) const { return s + 1 == static_cast<int>(panel.size()) || panel[s + 1] != panel[s]; }
};

Panels panels_of(const Forest& f, const SortedGamma& g) {
  Panels p;
  p.lo.resize(f.count);
  p.hi.resize(f.count);
  p.panel.assign(f.count, -1);
  p.column0.assign(f.count, 0);
  const auto& c = g.column;
  for (int s = 0; s < f.count; ++s) {
    p.lo[s] = static_cast<int>(std::lower_bound(c.begin(), c.end(), f.first[s]) - c.begin());
    p.hi[s] = static_cast<int>(std::lower_bound(c.begin(), c.end(), f.super[s + 1]) - c.begin());
    if (!p.size(s)) continue;
    const int prev = s - 1;
    if (prev >= 0 && p.panel[prev] >= 0 && f.parent[prev] == s && p.lo[prev] == p.lo[s] && p.hi[prev] == p.hi[s]) {
      p.panel[s] = p.panel[prev];
      p.column0[s] = p.width[p.panel[s]];
      p.width[p.panel[s]] += f.columns(s);
    } else {
      p.panel[s] = static_cast<int>(p.width.size());
      p.width.push_back(f.columns(s));
    }
  }
  p.offset.assign(p.width.size() + 1, 0);
  for (int s = 0; s < f.count; ++s)
    if (p.size(s) && p.column0[s] == 0) p.offset[p.panel[s] + 1] = static_cast<size_t>(p.width[p.panel[s]]) * p.size(s);
  for (size_t q = 0; q + 1 < p.offset.size(); ++q) p.offset[q + 1] += p.offset[q];
  p.values.assign(p.offset.back(), 0.0);
  // The right-hand sides P E_Γ: Γ_j's unit entry at its own column.
  for (int j = 0; j < static_cast<int>(c.size()); ++j) {
    const int s = f.supernode_of[c[j]];
    p.of(s)[static_cast<size_t>(c[j] - f.super[s]) * p.size(s) + (j - p.lo[s])] = 1.0;
  }
  return p;
}

// Supernode s's step of the forward solve on its Γ columns: Z_s = L_ss⁻¹ Z_s, then the rows
// below it, Z_R −= L_Rs Z_s, subtracted from its ancestors' blocks (all transposed).
void forward_step(const Forest& f, int s, Panels& p, std::vector<double>& update) {
  const int k = p.size(s), c = f.columns(s), h = f.height(s), below = h - c;
  double* Zt = p.of(s);
  const double* L = f.block(s);
  cblas_dtrsm(CblasColMajor, CblasRight, CblasLower, CblasTrans, CblasNonUnit, k, c, 1.0, L, h, Zt, k);
  if (!below) return;
  update.resize(static_cast<size_t>(k) * below);
  cblas_dgemm(CblasColMajor, CblasNoTrans, CblasTrans, k, below, c, 1.0, Zt, k, L + c, h, 0.0, update.data(), k);
  const int* rows = f.rows_below(s);
  for (int i = 0; i < below; ++i) {
    const int a = f.supernode_of[rows[i]];  // an ancestor: its Γ range holds s's
    double* target = p.of(a) + static_cast<size_t>(rows[i] - f.super[a]) * p.size(a) + (p.lo[s] - p.lo[a]);
    const double* u = update.data() + static_cast<size_t>(i) * k;
    for (int j = 0; j < k; ++j) target[j] -= u[j];
  }
}

}  // namespace

std::vector<Block> per_tree(const cholmod_factor& L, const std::vector<int>& gamma) {
  const Forest f = forest_of(L);
  const SortedGamma g = sorted_gamma(L, gamma);
  Panels p = panels_of(f, g);
  std::vector<int> block_of(f.count, -1);  // per root
  std::vector<Block> blocks;
  for (int s = 0; s < f.count; ++s) {
    if (f.parent[s] >= 0 || !p.size(s)) continue;
    block_of[s] = static_cast<int>(blocks.size());
    blocks.push_back({{g.unknown.begin() + p.lo[s], g.unknown.begin() + p.hi[s]},
                      Eigen::MatrixXd::Zero(p.size(s), p.size(s))});
  }
  std::vector<double> update;
  for (int s = 0; s < f.count; ++s) {
    if (!p.size(s)) continue;
    forward_step(f, s, p, update);
    if (!p.last_of_panel(s)) continue;
    // Zᵀ Z += the panel's rows of Z: one symmetric rank-width update of the tree's block.
    const int r = f.root[s], k = p.size(s);
    Eigen::MatrixXd& G = blocks[block_of[r]].inverse;
    const int at = p.lo[s] - p.lo[r];
    const double* Zt = p.values.data() + p.offset[p.panel[s]];
    cblas_dsyrk(CblasColMajor, CblasLower, CblasNoTrans, k, p.width[p.panel[s]], 1.0, Zt, k, 1.0,
                G.data() + at + static_cast<size_t>(at) * G.rows(), static_cast<int>(G.rows()));
  }
  for (Block& b : blocks) b.inverse.triangularView<Eigen::StrictlyUpper>() = b.inverse.transpose();
  return blocks;
}

}  // namespace thinlayer::inverse_block
