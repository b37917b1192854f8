#include "studies/cli/summary_json.h"

#include "core/io/output_ownership.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/io/output_ownership.h"

namespace thinlayer {

namespace {

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string number(double x) {
  if (!std::isfinite(x)) return "null";  // JSON has no NaN or Inf
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

}  // namespace

std::string summary_json(const std::vector<Check>& checks, const std::map<std::string, double>& timings) {
  std::ostringstream j;
  int failed = 0;
  for (const Check& c : checks) failed += !c.pass;
  j << "{\n  \"layout\": " << quoted(summary_layout_name) << ",\n  \"pass\": " << (failed == 0 ? "true" : "false") << ",\n  \"failed\": " << failed << ",\n  \"checks\": [\n";
  for (size_t i = 0; i < checks.size(); ++i) {
    const Check& c = checks[i];
    j << "    {\"id\": " << quoted(c.id) << ", \"pass\": " << (c.pass ? "true" : "false")
      << ", \"expected\": " << quoted(c.expected) << ", \"got\": " << quoted(c.got)
      << ", \"tolerance\": " << quoted(c.tolerance) << "}" << (i + 1 < checks.size() ? "," : "") << "\n";
  }
  j << "  ],\n  \"timings\": {";
  size_t i = 0;
  for (const auto& [name, seconds] : timings)
    j << (i++ ? ", " : "") << quoted(name) << ": " << number(seconds);
  j << "}\n}\n";
  return j.str();
}

}  // namespace thinlayer
