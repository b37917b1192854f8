#include "core/io/reference_tables.h"

#include <cstdlib>
#include <stdexcept>

#include "core/io/csv_table.h"

namespace thinlayer {

std::string reference_dir() {
  if (const char* env = std::getenv("THINLAYER_REFERENCE_DIR"); env && *env) return env;
  return THINLAYER_REFERENCE_DIR;
}

namespace {

StatusCount counts(const CsvTable& t, int i) {
  return {t.integer(i, "gap"), t.integer(i, "slide"), t.integer(i, "stick")};
}

char law_case(const CsvTable& t, int i) {
  const std::string& s = t.text(i, "case");
  if (s.size() != 1 || s[0] < 'a' || s[0] > 'i') throw std::runtime_error(t.path() + ": bad case '" + s + "'");
  return s[0];
}

}  // namespace

std::vector<Table3Row> load_table3_paper(const std::string& dir) {
  const CsvTable t = CsvTable::read(dir + "/table3_paper.csv");
  std::vector<Table3Row> rows;
  for (int i = 0; i < t.rows(); ++i)
    rows.push_back({t.integer(i, "row"), t.number(i, "mu_bar"), t.number(i, "lambda_bar"), counts(t, i)});
  return rows;
}

std::vector<StatusCount> load_table3_baseline(const std::string& dir) {
  const CsvTable t = CsvTable::read(dir + "/table3_baseline.csv");
  std::vector<StatusCount> rows;
  for (int i = 0; i < t.rows(); ++i) {
    if (t.integer(i, "row") != i + 1) throw std::runtime_error(t.path() + ": rows must be 1, 2, ... in order");
    rows.push_back(counts(t, i));
  }
  return rows;
}

std::vector<Table1Row> load_table1(const std::string& dir) {
  const CsvTable t = CsvTable::read(dir + "/table1.csv");
  std::vector<Table1Row> rows;
  for (int i = 0; i < t.rows(); ++i) rows.push_back({law_case(t, i), t.text(i, "lambda_limit"), t.text(i, "mu_limit")});
  return rows;
}

std::vector<Table2Row> load_table2(const std::string& dir) {
  const CsvTable t = CsvTable::read(dir + "/table2.csv");
  std::vector<Table2Row> rows;
  for (int i = 0; i < t.rows(); ++i) rows.push_back({law_case(t, i), t.number(i, "gamma"), t.number(i, "delta")});
  return rows;
}

std::vector<PredictedRate> load_predicted_rates(const std::string& dir) {
  const CsvTable t = CsvTable::read(dir + "/predicted_rates.csv");
  std::vector<PredictedRate> rows;
  for (int i = 0; i < t.rows(); ++i)
    rows.push_back({law_case(t, i), t.number(i, "gamma"), t.number(i, "delta"), t.number(i, "p_predicted"),
                    t.text(i, "dominant_term")});
  return rows;
}

}  // namespace thinlayer
