#include "core/io/scene_id_number.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>

namespace thinlayer {

std::string scene_id_number(double x) {
  // The ids' long-standing form (%g, as a default ostream prints) wherever it reads back exactly,
  // so that existing ids do not change; else the shortest exact text.
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  if (std::strtod(buffer, nullptr) == x) return buffer;
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
}

}  // namespace thinlayer
