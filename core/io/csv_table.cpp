#include "core/io/csv_table.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace thinlayer {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream ss(line);
  std::string field;
  while (std::getline(ss, field, ',')) {
    const auto first = field.find_first_not_of(" \t\r");
    const auto last = field.find_last_not_of(" \t\r");
    fields.push_back(first == std::string::npos ? "" : field.substr(first, last - first + 1));
  }
  // getline yields no field after a trailing comma, but "a,b," has three fields.
  const auto end = line.find_last_not_of(" \t\r");
  if (end != std::string::npos && line[end] == ',') fields.push_back("");
  return fields;
}

}  // namespace

CsvTable CsvTable::read(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read reference table '" + path + "'");
  CsvTable table;
  table.path_ = path;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos) continue;
    auto fields = split(line);
    if (table.header_.empty()) {
      table.header_ = std::move(fields);
      continue;
    }
    if (fields.size() != table.header_.size())
      throw std::runtime_error(path + ":" + std::to_string(line_number) + ": expected " +
                               std::to_string(table.header_.size()) + " fields, got " + std::to_string(fields.size()));
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < fields.size(); ++i) row[table.header_[i]] = fields[i];
    table.rows_.push_back(std::move(row));
  }
  if (table.header_.empty()) throw std::runtime_error("reference table '" + path + "' has no header");
  return table;
}

const std::string& CsvTable::text(int row, const std::string& column) const {
  if (row < 0 || row >= rows()) throw std::out_of_range(path_ + ": no row " + std::to_string(row));
  auto it = rows_[row].find(column);
  if (it == rows_[row].end()) throw std::runtime_error(path_ + ": no column '" + column + "'");
  return it->second;
}

double CsvTable::number(int row, const std::string& column) const {
  const std::string& s = text(row, column);
  size_t used = 0;
  double value = 0;
  try {
    value = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != s.size() || s.empty() || !std::isfinite(value))
    throw std::runtime_error(path_ + ": column '" + column + "' row " + std::to_string(row + 1) + ": not a number: '" + s + "'");
  return value;
}

int CsvTable::integer(int row, const std::string& column) const {
  const double v = number(row, column);
  if (std::abs(v) > 1e9 || v != std::floor(v))
    throw std::runtime_error(path_ + ": column '" + column + "' row " + std::to_string(row + 1) + ": not an integer");
  return static_cast<int>(v);
}

}  // namespace thinlayer
