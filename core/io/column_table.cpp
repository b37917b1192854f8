#include "core/io/column_table.h"

#include <stdexcept>

namespace thinlayer {

void ColumnTable::add(const std::string& column, double value) { doubles_[column].push_back(value); }
void ColumnTable::add(const std::string& column, int value) { ints_[column].push_back(value); }
void ColumnTable::add(const std::string& column, const std::string& value) { strings_[column].push_back(value); }

void ColumnTable::write(H5Writer& out, const std::string& group) const {
  size_t rows = 0;
  bool first = true;
  auto check = [&](const std::string& column, size_t n) {
    if (!first && n != rows)
      throw std::logic_error("table '" + group + "': column '" + column + "' has " + std::to_string(n) + " rows, not " +
                             std::to_string(rows));
    rows = n;
    first = false;
  };
  for (const auto& [c, v] : doubles_) check(c, v.size());
  for (const auto& [c, v] : ints_) check(c, v.size());
  for (const auto& [c, v] : strings_) check(c, v.size());
  if (rows == 0) return;
  for (const auto& [c, v] : doubles_) out.dataset(group + "/" + c, v);
  for (const auto& [c, v] : ints_) out.dataset(group + "/" + c, v);
  for (const auto& [c, v] : strings_) out.dataset(group + "/" + c, v);
}

}  // namespace thinlayer
