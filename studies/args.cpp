#include "studies/args.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace thinlayer {

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
           const std::set<std::string>& flags) {
  for (size_t i = 0; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a.rfind("--", 0) != 0) {
      positional_.push_back(a);
      continue;
    }
    const std::string name = a.substr(2);
    if (flags.count(name)) {
      flags_set_.insert(name);
    } else if (valued.count(name)) {
      if (i + 1 >= argv.size()) throw std::invalid_argument("option --" + name + " needs a value");
      values_[name] = argv[++i];
    } else {
      throw std::invalid_argument("unknown option " + a + " (see --help)");
    }
  }
}

bool Args::has(const std::string& name) const { return values_.count(name) || flags_set_.count(name); }

std::string Args::text(const std::string& name, const std::string& fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

double parse_number(const std::string& option, const std::string& text) {
  if (text == "inf" || text == "+inf" || text == "infinity") return std::numeric_limits<double>::infinity();
  size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || std::isnan(v))
    throw std::invalid_argument("option --" + option + ": not a number: '" + text + "'");
  return v;
}

double Args::number(const std::string& name, double fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : parse_number(name, it->second);
}

int Args::integer(const std::string& name, int fallback) const {
  const double v = number(name, fallback);
  if (v != std::floor(v) || std::abs(v) > 1e9) throw std::invalid_argument("option --" + name + ": not an integer");
  return static_cast<int>(v);
}

std::vector<double> parse_number_list(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) values.push_back(parse_number(option, item));
  if (values.empty() || text.back() == ',')
    throw std::invalid_argument("option --" + option + ": expected a comma-separated list of numbers, got '" + text + "'");
  return values;
}

}  // namespace thinlayer
