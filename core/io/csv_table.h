#pragma once
// Small CSV tables for reference data: '#' starts a comment line, the first other line is
// the header, fields are separated by commas (no quoting needed by our files).
#include <map>
#include <string>
#include <vector>

namespace thinlayer {

class CsvTable {
 public:
  // Throws std::runtime_error naming the file and line on a missing file or a malformed row.
  static CsvTable read(const std::string& path);

  int rows() const { return static_cast<int>(rows_.size()); }
  const std::string& text(int row, const std::string& column) const;
  double number(int row, const std::string& column) const;
  int integer(int row, const std::string& column) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::string> header_;
  std::vector<std::map<std::string, std::string>> rows_;
};

}  // namespace thinlayer
