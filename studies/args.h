#pragma once
// A minimal "--name value" / "--flag" command-line parser with strict checking: every
// unknown option, missing value or malformed number is a one-line error.
#include <map>
#include <set>
#include <string>
#include <vector>

namespace thinlayer {

class Args {
 public:
  // `valued` lists options that take a value, `flags` those that don't.
  Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
       const std::set<std::string>& flags);

  bool has(const std::string& name) const;
  std::string text(const std::string& name, const std::string& fallback) const;
  // Accepts "inf" for +∞; rejects NaN and trailing garbage.
  double number(const std::string& name, double fallback) const;
  int integer(const std::string& name, int fallback) const;
  const std::vector<std::string>& positional() const { return positional_; }

 private:
  std::map<std::string, std::string> values_;
  std::set<std::string> flags_set_;
  std::vector<std::string> positional_;
};

double parse_number(const std::string& option, const std::string& text);
// "a,b,c" -> the numbers, each by parse_number; an empty list or item is an error.
std::vector<double> parse_number_list(const std::string& option, const std::string& text);

}  // namespace thinlayer
