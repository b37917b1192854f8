#include "core/io/csv_writer.h"

#include <sstream>

namespace thinlayer {

std::string csv_text(const std::string& field) {
  std::string f = field;
  if (!f.empty() && (f[0] == '=' || f[0] == '+' || f[0] == '-' || f[0] == '@' || f[0] == '\t' || f[0] == '\r'))
    f.insert(f.begin(), '\'');
  if (f.find_first_of(",\"\r\n") == std::string::npos) return f;
  std::string quoted = "\"";
  for (char c : f) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

CsvRow& CsvRow::add(const std::string& field) {
  if (!first_) fields_ += ',';
  fields_ += field;
  first_ = false;
  return *this;
}

CsvRow& CsvRow::text(const std::string& field) { return add(csv_text(field)); }

CsvRow& CsvRow::number(double value, int precision) {
  std::ostringstream s;
  s.precision(precision);
  s << value;
  return add(s.str());
}

CsvRow& CsvRow::integer(long long value) { return add(std::to_string(value)); }

}  // namespace thinlayer
