#include "core/linalg/least_imbalance.h"

#include <memory>
#include <stdexcept>

#include <glpk.h>

namespace thinlayer {

namespace {

struct ProblemDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

}  // namespace

// Columns: x (n of them), then s⁺ and s⁻ ≥ 0 for each row (m each); rows: G x − s⁺ + s⁻ = −b.
// Minimise Σ w_i (s⁺ + s⁻): at the optimum s⁺ − s⁻ = G x + b and one of each pair is 0.
LeastImbalance least_imbalance(const Eigen::SparseMatrix<double>& G, const Eigen::VectorXd& b,
                               const std::vector<bool>& free_column, const Eigen::VectorXd& row_weight) {
  const int m = static_cast<int>(G.rows()), n = static_cast<int>(G.cols());
  if (b.size() != m || static_cast<int>(free_column.size()) != n || (row_weight.size() != 0 && row_weight.size() != m))
    throw std::invalid_argument("least_imbalance: sizes do not match");
  LeastImbalance out;
  out.x = Eigen::VectorXd::Zero(n);
  out.imbalance = b;
  out.total = row_weight.size() ? row_weight.cwiseProduct(b.cwiseAbs()).sum() : b.lpNorm<1>();
  if (m == 0) return out;
  std::unique_ptr<glp_prob, ProblemDeleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MIN);
  glp_add_rows(lp.get(), m);
  for (int i = 0; i < m; ++i) glp_set_row_bnds(lp.get(), i + 1, GLP_FX, -b[i], -b[i]);
  glp_add_cols(lp.get(), n + 2 * m);
  // GLPK's arrays are 1-based: element 0 is unused.
  std::vector<int> index(1);
  std::vector<double> value(1);
  const Eigen::SparseMatrix<double> Gc = G;  // column-major: one column at a time
  for (int j = 0; j < n; ++j) {
    glp_set_col_bnds(lp.get(), j + 1, free_column[j] ? GLP_FR : GLP_LO, 0.0, 0.0);
    index.resize(1);
    value.resize(1);
    for (Eigen::SparseMatrix<double>::InnerIterator it(Gc, j); it; ++it) {
      index.push_back(static_cast<int>(it.row()) + 1);
      value.push_back(it.value());
    }
    glp_set_mat_col(lp.get(), j + 1, static_cast<int>(index.size()) - 1, index.data(), value.data());
  }
  for (int i = 0; i < m; ++i)
    for (int sign = 0; sign < 2; ++sign) {
      const int col = n + 2 * i + sign + 1;
      glp_set_col_bnds(lp.get(), col, GLP_LO, 0.0, 0.0);
      glp_set_obj_coef(lp.get(), col, row_weight.size() ? row_weight[i] : 1.0);
      int row[2] = {0, i + 1};
      double coef[2] = {0, sign == 0 ? -1.0 : 1.0};
      glp_set_mat_col(lp.get(), col, 1, row, coef);
    }
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_OFF;  // glp_exact starts from the basis the simplex leaves
  glp_std_basis(lp.get());  // the slacks s±: a valid basis, and silent (glp_adv_basis prints)
  if (glp_simplex(lp.get(), &parm) != 0 || glp_get_status(lp.get()) != GLP_OPT)
    throw std::runtime_error("least_imbalance: GLPK's simplex found no optimum");
  // The exact simplex from that basis: in rational arithmetic, the optimum of the double data.
  out.exact = glp_exact(lp.get(), &parm) == 0 && glp_get_status(lp.get()) == GLP_OPT;
  if (!out.exact) throw std::runtime_error("least_imbalance: GLPK's exact simplex did not confirm the optimum");
  out.total = glp_get_obj_val(lp.get());
  for (int j = 0; j < n; ++j) out.x[j] = glp_get_col_prim(lp.get(), j + 1);
  for (int i = 0; i < m; ++i)
    out.imbalance[i] = glp_get_col_prim(lp.get(), n + 2 * i + 1) - glp_get_col_prim(lp.get(), n + 2 * i + 2);
  return out;
}

}  // namespace thinlayer
