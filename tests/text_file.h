#pragma once
// Test helper: a whole file as a string ("" if it cannot be read; the caller's assertions say
// what was expected in it).
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

inline std::string read_text_file(const std::filesystem::path& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}
