#pragma once
// The command line of one thinlayer command: "--name value" options and "--flag" flags,
// parsed by CLI11 (Debian's libcli11-dev, header-only). Why CLI11: it is a maintained,
// packaged parser that already knows the grammar users expect (--name=value, counting
// repeated options, telling options from negative numbers), so the project keeps only its
// own rules on top (SPEC §4), each a one-line std::invalid_argument:
//   - an unknown option, a stray argument, an option given twice: refused;
//   - an option's value is never another option (`--out --quiet`);
//   - numbers are decimal: no hex, no blanks, no NaN; overflow and underflow are named.
// The help texts stay hand-written (main.cpp, command_*.cpp): they carry the physics and the
// units, which CLI11's generated help would not.
#include <map>
#include <set>
#include <string>
#include <vector>

namespace thinlayer {

class Args {
 public:
  // `valued` lists options that take a value, `flags` those that don't (names without "--").
  Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
       const std::set<std::string>& flags);

  bool has(const std::string& name) const;
  std::string text(const std::string& name, const std::string& fallback) const;
  // Strict decimal (parse_number); "inf" for +∞.
  double number(const std::string& name, double fallback) const;
  // Decimal digits only, within int.
  int integer(const std::string& name, int fallback) const;
  // Every option and flag given, without "--".
  const std::set<std::string>& given() const { return given_; }

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> given_;
};

// A decimal number ([+-]digits[.digits][e[+-]digits]) or inf; anything else, NaN, an
// overflow or an underflow throws std::invalid_argument naming the option and the text.
double parse_number(const std::string& option, const std::string& text);
int parse_integer(const std::string& option, const std::string& text);
// "a,b,c" -> the numbers, each by parse_number; an empty list or item is an error.
std::vector<double> parse_number_list(const std::string& option, const std::string& text);

// Throws std::invalid_argument unless every option given is in `allowed`: "--NAME does not
// apply to WHAT".
void require_only(const Args& args, const std::set<std::string>& allowed, const std::string& what);

}  // namespace thinlayer
