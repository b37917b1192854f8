#pragma once
// A table filled row by row and written column by column: one 1-D dataset per column under a
// group, the layout of the studies' tables in a results file.
#include <map>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"

namespace thinlayer {

class ColumnTable {
 public:
  // Appends a value to a column (created on first use; a column keeps the type it started with).
  void add(const std::string& column, double value);
  void add(const std::string& column, int value);
  void add(const std::string& column, const std::string& value);

  // Writes every column as group/<column>. Throws std::logic_error if the columns differ in
  // length (a row left incomplete is a bug in the caller). An empty table writes nothing.
  void write(H5Writer& out, const std::string& group) const;

 private:
  std::map<std::string, std::vector<double>> doubles_;
  std::map<std::string, std::vector<int>> ints_;
  std::map<std::string, std::vector<std::string>> strings_;
};

}  // namespace thinlayer
