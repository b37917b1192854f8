#include "studies/cli/args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <CLI/CLI.hpp>

namespace thinlayer {

namespace {

bool is_decimal(const std::string& text) {
  static const std::regex decimal(R"([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?)");
  return std::regex_match(text, decimal);
}

bool is_infinity(const std::string& text) {
  return text == "inf" || text == "+inf" || text == "-inf" || text == "infinity";
}

// CLI11 hands an option the next argument even when that is another option; a value that
// starts with '-' must be a number.
void require_value(const std::string& name, const std::string& value) {
  if (value.empty()) throw std::invalid_argument("option --" + name + ": empty value");
  if (value[0] == '-' && !is_decimal(value) && !is_infinity(value))
    throw std::invalid_argument("option --" + name + " needs a value, got the option '" + value + "'");
}

void refuse_extra(const std::string& extra) {
  if (extra.size() > 1 && extra[0] == '-' && !is_decimal(extra))
    throw std::invalid_argument("unknown option " + extra + " (see --help)");
  throw std::invalid_argument("unexpected argument '" + extra + "'");
}

}  // namespace

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& valued,
           const std::set<std::string>& flags) {
  CLI::App app;
  app.set_help_flag();  // --help is answered before parsing, with the hand-written text
  app.allow_extras();   // refused below, with the project's message
  std::map<std::string, CLI::Option*> options;
  for (const std::string& name : valued)
    options[name] = app.add_option("--" + name, values_[name])->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  for (const std::string& name : flags) options[name] = app.add_flag("--" + name)->disable_flag_override();
  std::vector<std::string> reversed(argv.rbegin(), argv.rend());  // CLI11 takes them last first
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw std::invalid_argument(e.what());
  }
  // In the order given: `--eps --out o.h5` is about --eps, not o.h5.
  for (const std::string& arg : argv) {
    const std::string name = arg.rfind("--", 0) == 0 ? arg.substr(2, arg.find('=') - 2) : "";
    auto it = options.find(name);
    if (it == options.end() || given_.count(name)) continue;
    if (it->second->count() > 1)
      throw std::invalid_argument("option --" + name + " is given " + std::to_string(it->second->count()) +
                                  " times (give it once)");
    given_.insert(name);
    if (valued.count(name)) require_value(name, values_[name]);
  }
  if (!app.remaining().empty()) refuse_extra(app.remaining().front());
  for (auto it = values_.begin(); it != values_.end();) it = given_.count(it->first) ? std::next(it) : values_.erase(it);
}

bool Args::has(const std::string& name) const { return given_.count(name) > 0; }

std::string Args::text(const std::string& name, const std::string& fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

double parse_number(const std::string& option, const std::string& text) {
  const std::string what = "option --" + option + ": ";
  if (is_infinity(text)) return text[0] == '-' ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  if (!is_decimal(text)) {
    const bool nan = text.find("nan") != std::string::npos || text.find("NaN") != std::string::npos ||
                     text.find("NAN") != std::string::npos;
    throw std::invalid_argument(what + (nan ? "not a number (NaN)" : "not a decimal number") + ": '" + text + "'");
  }
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE && std::isinf(v))
    throw std::invalid_argument(what + "'" + text + "' overflows (the largest number is about 1.8e308)");
  // glibc also reports ERANGE for a subnormal result: it has lost digits, so it is refused too.
  if (errno == ERANGE)
    throw std::invalid_argument(what + "'" + text + "' underflows (the smallest normal number is about 2.2e-308)");
  return v;
}

int parse_integer(const std::string& option, const std::string& text) {
  static const std::regex integer(R"([+-]?[0-9]+)");
  if (!std::regex_match(text, integer)) throw std::invalid_argument("option --" + option + ": not an integer: '" + text + "'");
  errno = 0;
  const long long v = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v > std::numeric_limits<int>::max() || v < std::numeric_limits<int>::min())
    throw std::invalid_argument("option --" + option + ": '" + text + "' is out of range");
  return static_cast<int>(v);
}

double Args::number(const std::string& name, double fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : parse_number(name, it->second);
}

int Args::integer(const std::string& name, int fallback) const {
  auto it = values_.find(name);
  return it == values_.end() ? fallback : parse_integer(name, it->second);
}

std::vector<double> parse_number_list(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) values.push_back(parse_number(option, item));
  if (values.empty() || text.back() == ',')
    throw std::invalid_argument("option --" + option + ": expected a comma-separated list of numbers, got '" + text + "'");
  return values;
}

void require_only(const Args& args, const std::set<std::string>& allowed, const std::string& what) {
  for (const std::string& name : args.given())
    if (!allowed.count(name)) throw std::invalid_argument("--" + name + " does not apply to " + what);
}

}  // namespace thinlayer
