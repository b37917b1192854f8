#include "studies/cli/command_line.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace thinlayer {

namespace {

bool is_decimal(const std::string& text) {
  static const std::regex decimal(R"([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?)");
  return std::regex_match(text, decimal);
}

bool is_infinity(const std::string& text) {
  return text == "inf" || text == "+inf" || text == "-inf" || text == "infinity";
}

// A value that starts with '-' must be a number: otherwise it is the next option, and the
// option before it was given no value.
void require_value(const std::string& name, const std::string& value) {
  if (value.empty()) throw std::invalid_argument("option --" + name + ": empty value");
  if (value[0] == '-' && !is_decimal(value) && !is_infinity(value))
    throw std::invalid_argument("option --" + name + " needs a value, got the option '" + value + "'");
}

void refuse_extra(const std::string& extra) {
  if (extra.size() > 1 && extra[0] == '-' && !is_decimal(extra))
    throw std::invalid_argument("unknown option " + extra.substr(0, extra.find('=')) + " (see --help)");
  throw std::invalid_argument("unexpected argument '" + extra + "'");
}

// "--name" or "--name=value" → name; anything else → "".
std::string option_name(const std::string& arg) {
  if (arg.size() <= 2 || arg.rfind("--", 0) != 0) return "";
  return arg.substr(2, arg.find('=') - 2);
}

// SPEC §4's rules before CLI11 reads the arguments: every option once, every value a value.
// Returns the arguments with each option's value joined to it ("--eps=-1e-3"), so that CLI11
// never has to guess whether "-inf" is a value or an option.
std::vector<std::string> checked_arguments(const CLI::App& command, const std::vector<std::string>& args) {
  for (const std::string& arg : args)
    if (arg == "--help" || arg == "-h") throw CLI::CallForHelp();
  std::map<std::string, int> times;
  for (const std::string& arg : args)
    if (const std::string name = option_name(arg); !name.empty() && command.get_option_no_throw("--" + name)) ++times[name];
  std::vector<std::string> out;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const std::string name = option_name(arg);
    const CLI::Option* option = name.empty() ? nullptr : command.get_option_no_throw("--" + name);
    if (!option) {  // a positional argument, or an unknown option: CLI11 and refuse_extra decide
      out.push_back(arg);
      continue;
    }
    if (times[name] > 1)
      throw std::invalid_argument("option --" + name + " is given " + std::to_string(times[name]) + " times (give it once)");
    const bool joined = arg.find('=') != std::string::npos;
    if (option->get_expected_max() == 0) {  // a flag
      if (joined) throw std::invalid_argument("option --" + name + " takes no value");
      out.push_back(arg);
      continue;
    }
    if (!joined && i + 1 == args.size()) throw std::invalid_argument("option --" + name + " needs a value");
    const std::string value = joined ? arg.substr(arg.find('=') + 1) : args[++i];
    require_value(name, value);
    out.push_back("--" + name + "=" + value);
  }
  return out;
}

// CLI11 writes a validator's message as "--name: message" (": message" for a positional);
// ours already name the option.
std::string without_option_prefix(const CLI::ParseError& e) {
  const std::string what = e.what();
  const std::size_t colon = what.find(": ");
  if (dynamic_cast<const CLI::ValidationError*>(&e) && colon != std::string::npos &&
      what.substr(0, colon).find(' ') == std::string::npos)
    return what.substr(colon + 2);
  return what;
}

// Wraps a check that throws std::invalid_argument into a CLI11 validator.
template <class Check>
CLI::Validator validator(Check check) {
  return CLI::Validator(
      [check](std::string& text) -> std::string {
        try {
          check(text);
          return "";
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      "");  // no description: CLI11 would append it to the option's value name in the help
}

class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::string usage) : usage_(std::move(usage)) { column_width(23); }

  std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode mode) const override {
    std::string out = usage_ + "\n";
    if (!app->get_description().empty()) out += "\n" + app->get_description() + "\n";
    std::string options = make_groups(app, mode) + make_subcommands(app, mode);
    while (!options.empty() && options.back() == '\n') options.pop_back();  // CLI11 ends some groups with blank lines
    out += "\n" + options + "\n";
    if (!app->get_footer().empty()) out += "\n" + app->get_footer() + "\n";
    return out;
  }
  // "Group:" and its options (CLI11 puts a blank line before and between groups: one is enough).
  std::string make_group(std::string group, bool positional, std::vector<const CLI::Option*> options) const override {
    std::string out = group + ":\n";
    for (const CLI::Option* option : options) out += make_option(option, positional);
    return out;
  }
  // The option's value as named in its declaration, nothing else (no "=default", "REQUIRED").
  std::string make_option_opts(const CLI::Option* option) const override {
    return option->get_type_name().empty() ? "" : " " + option->get_type_name();
  }
  // A command in the list of commands: the first line of its description.
  std::string make_subcommand(const CLI::App* sub) const override {
    std::ostringstream out;
    const std::string description = sub->get_description();
    CLI::detail::format_help(out, sub->get_name(), description.substr(0, description.find('\n')), column_width_);
    return out.str();
  }

 private:
  std::string usage_;
};

}  // namespace

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

std::vector<double> parse_number_list(const std::string& option, const std::string& text) {
  std::vector<double> values;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) values.push_back(parse_number(option, item));
  if (values.empty() || text.back() == ',')
    throw std::invalid_argument("option --" + option + ": expected a comma-separated list of numbers, got '" + text + "'");
  return values;
}

std::istream& operator>>(std::istream& in, NumberList& list) {
  std::string text;
  std::getline(in, text, '\0');
  list.values = parse_number_list("", text);  // number_list() has checked it, with the option's name
  return in;
}

CLI::Validator decimal(const std::string& option) {
  return validator([option](const std::string& text) { parse_number(option, text); });
}

CLI::Validator integer(const std::string& option) {
  // CLI11 converts integers with strtoll(…, 0): "010" would be octal 8. Ours is decimal.
  return validator([option](std::string& text) { text = std::to_string(parse_integer(option, text)); });
}

CLI::Validator number_list(const std::string& option) {
  return validator([option](const std::string& text) { parse_number_list(option, text); });
}

CLI::Validator one_of(const std::string& what, const std::vector<std::string>& choices) {
  return validator([what, choices](const std::string& text) {
    for (const std::string& c : choices)
      if (text == c) return;
    std::string expected;
    for (std::size_t k = 0; k < choices.size(); ++k)
      expected += (k == 0 ? "" : k + 1 == choices.size() ? " or " : ", ") + choices[k];
    throw std::invalid_argument("unknown " + what + " '" + text + "' (expected " + expected + ")");
  });
}

void parse_command(CLI::App& command, const std::vector<std::string>& args) {
  std::vector<std::string> checked = checked_arguments(command, args);
  std::vector<std::string> reversed(checked.rbegin(), checked.rend());  // CLI11 takes them last first
  try {
    command.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    throw;
  } catch (const CLI::ParseError& e) {
    throw std::invalid_argument(without_option_prefix(e));
  }
  if (!command.remaining().empty()) refuse_extra(command.remaining().front());
}

bool given(const CLI::App& command, const std::string& name) {
  const CLI::Option* option = command.get_option_no_throw("--" + name);
  return option && option->count() > 0;
}

void require_only(const CLI::App& command, const std::set<std::string>& allowed, const std::string& what) {
  for (const CLI::Option* option : command.get_options())
    for (const std::string& name : option->get_lnames())
      if (option->count() > 0 && !allowed.count(name)) throw std::invalid_argument("--" + name + " does not apply to " + what);
}

std::shared_ptr<CLI::Formatter> help_formatter(const std::string& usage) { return std::make_shared<HelpFormatter>(usage); }

}  // namespace thinlayer
