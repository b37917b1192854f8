#include "studies/tools/format.h"

#include <cstdio>

namespace thinlayer {

std::string counts_text(const StatusCount& c) {
  return std::to_string(c.gap) + "/" + std::to_string(c.slide) + "/" + std::to_string(c.stick);
}

std::string sci(double x, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*e", decimals, x);
  return buf;
}

std::string fixed(double x, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, x);
  return buf;
}

std::string plain(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

std::string significant(double x, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
  return buffer;
}

}  // namespace thinlayer
