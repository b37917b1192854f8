#pragma once
// The command line of thinlayer, declared in CLI11 (Debian's libcli11-dev, header-only).
//
// Every command (`solve`, `study`, `verify`) is a CLI11 subcommand whose options are declared
// with their type, their validator and their help text (command_solve.cpp, command_study.cpp);
// the help is generated from those declarations. CLI11 knows the grammar users expect
// (--name value, --name=value, negative numbers as values); this file adds SPEC §4's rules on
// top, each a one-line std::invalid_argument:
//   - an unknown option, a stray argument, an option given twice: refused;
//   - an option's value is never another option (`--out --quiet`);
//   - numbers are decimal: no hex, no blanks, no NaN; overflow and underflow are named.
// Why not CLI11's own text for these: its messages ("The following arguments were not
// expected: ...", "Could not convert: --eps = --json") do not say what to do, and its
// integer conversion reads "010" as octal 8 and its list delimiter drops an empty item.
#include <istream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace thinlayer {

// A decimal number ([+-]digits[.digits][e[+-]digits]) or inf; anything else, NaN, an
// overflow or an underflow throws std::invalid_argument naming the option and the text.
double parse_number(const std::string& option, const std::string& text);
int parse_integer(const std::string& option, const std::string& text);
// "a,b,c" -> the numbers, each by parse_number; an empty list or item is an error.
std::vector<double> parse_number_list(const std::string& option, const std::string& text);

// A comma-separated list of numbers as one option value ("1e-2,5e-3"), checked by
// number_list() before CLI11 converts it.
struct NumberList {
  std::vector<double> values;
};
std::istream& operator>>(std::istream& in, NumberList& list);

// Validators, run by CLI11 on an option's text before it converts it. Each message names the
// option (command_line.cpp strips the "--name: " CLI11 puts in front).
CLI::Validator decimal(const std::string& option);      // parse_number
CLI::Validator integer(const std::string& option);      // parse_integer; a transform: "010" -> "10"
CLI::Validator number_list(const std::string& option);  // parse_number_list
// The value is one of `choices`: "unknown WHAT 'x' (expected a, b or c)".
CLI::Validator one_of(const std::string& what, const std::vector<std::string>& choices);

// Parses `args` (the arguments after the command's name) into the options declared on
// `command`, SPEC §4's rules first. Throws CLI::CallForHelp when --help or -h is given, and
// std::invalid_argument (one line) for anything refused.
void parse_command(CLI::App& command, const std::vector<std::string>& args);

// Whether --NAME was given on the command line just parsed.
bool given(const CLI::App& command, const std::string& name);
// Throws std::invalid_argument unless every option given is in `allowed`: "--NAME does not
// apply to WHAT".
void require_only(const CLI::App& command, const std::set<std::string>& allowed, const std::string& what);

// The help of one command: `usage` (the usage lines), then the command's description, its
// options group by group as declared (CLI11's layout, the option's name in a 23-character
// column), then its footer.
std::shared_ptr<CLI::Formatter> help_formatter(const std::string& usage);

}  // namespace thinlayer
