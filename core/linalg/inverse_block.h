#pragma once
// The principal block (A⁻¹)_ΓΓ of the inverse of a symmetric positive definite matrix A on a
// set of unknowns Γ, from a supernodal CHOLMOD factor P A Pᵀ = L Lᵀ of any fill-reducing order
// (the one a plain solve uses: Γ need not come last):
//   (A⁻¹)_ΓΓ = Zᵀ Z,   Z = L⁻¹ P E_Γ   (E_Γ: the identity's columns on Γ).
// Column j of Z is the forward solve of a unit vector: nonzero only on the path from Γ_j's
// column to the root of the elimination tree. So the forward solve visits only the supernodes
// with some Γ in their subtree, and at each only those Γ columns — consecutive in the factor's
// order, which is postordered — and Zᵀ Z accumulates supernode by supernode (Z_sᵀ Z_s, Z_s the
// rows of Z at supernode s's columns). Unknowns in different trees (A's connected parts: the
// bodies) share no path, so (A⁻¹)_ΓΓ is block-diagonal over the trees: one block per tree.
// Internal to core/linalg: only sparse_cholesky.cpp includes this header.
#include <vector>

#include <cholmod.h>
#include <Eigen/Core>

namespace thinlayer::inverse_block {

// One tree's block: its Γ unknowns (indices of A, in the factor's order) and (A⁻¹) on them.
struct Block {
  std::vector<int> unknowns;
  Eigen::MatrixXd inverse;  // symmetric, both triangles filled
};

// The blocks of (A⁻¹)_ΓΓ, one per tree of L's elimination forest holding some of `gamma`
// (distinct indices of A), in the factor's order. L: a real supernodal LL' factor whose
// ordering is postordered (CHOLMOD's default analysis); throws std::logic_error otherwise.
std::vector<Block> per_tree(const cholmod_factor& L, const std::vector<int>& gamma);

}  // namespace thinlayer::inverse_block
