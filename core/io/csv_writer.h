#pragma once
// CSV as RFC 4180 writes it, safe to open in a spreadsheet (SPEC §4: a bondline group named
// `=HYPERLINK(1),x` was written raw, 15 fields under 14 headers and a formula).
//
//   CsvRow row;
//   row.text(scene_id).text(bondline).number(s);  // one field each
//   out << row.line();                            // the fields, then "\n"
//
// A text field is quoted when it holds a comma, a double quote, CR or LF (its quotes doubled),
// and neutralised when a spreadsheet would read it as a formula: a field beginning with '=',
// '+', '-', '@', TAB or CR gets a leading apostrophe (OWASP's advice), shown as text. Numbers
// are written as numbers (a negative one begins with '-' and stays a number). Lines end with
// "\n" (RFC 4180 says CRLF; every reader takes LF, and the file's comment lines are thinlayer's).
#include <string>

namespace thinlayer {

// One text field, quoted and neutralised as above.
std::string csv_text(const std::string& field);

class CsvRow {
 public:
  CsvRow& text(const std::string& field);
  CsvRow& number(double value, int precision = 10);
  CsvRow& integer(long long value);
  // The fields joined by commas, and "\n".
  std::string line() const { return fields_ + "\n"; }

 private:
  CsvRow& add(const std::string& field);
  std::string fields_;
  bool first_ = true;
};

}  // namespace thinlayer
