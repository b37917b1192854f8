#pragma once
// The paper's tables and the project's regression baseline, read from reference/*.csv.
// The directory is $THINLAYER_REFERENCE_DIR when set, else the source tree's reference/.
#include <string>
#include <vector>

#include "core/solvers/contact_problem.h"

namespace thinlayer {

std::string reference_dir();

struct Table3Row {
  int row = 0;
  double mu_bar = 0, lambda_bar = 0;  // daN/mm³
  StatusCount paper;                 // the paper's counts (out of 32 nodes)
};
std::vector<Table3Row> load_table3_paper(const std::string& dir = reference_dir());

// The project's converged counts for its default bar model (SPEC §2.1.1), per row.
std::vector<StatusCount> load_table3_baseline(const std::string& dir = reference_dir());

struct Table1Row {
  char law_case = '?';
  std::string lambda_limit, mu_limit;  // "0", "finite", "inf"
};
std::vector<Table1Row> load_table1(const std::string& dir = reference_dir());

struct Table2Row {
  char law_case = '?';
  double gamma = 0, delta = 0;
};
std::vector<Table2Row> load_table2(const std::string& dir = reference_dir());

// The project's predicted convergence rate of each dovetail case (study S2), derived by hand
// in studies/convergence_rates.md.
struct PredictedRate {
  char law_case = '?';
  double gamma = 0, delta = 0, p = 0;
  std::string dominant_term;
};
std::vector<PredictedRate> load_predicted_rates(const std::string& dir = reference_dir());

}  // namespace thinlayer
