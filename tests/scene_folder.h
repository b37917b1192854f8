#pragma once
// Test helpers for scene files: a temporary folder removed at the end of the test, and numbers
// written with every digit (so a scene file says exactly what the test computed).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

struct SceneFolder {
  std::filesystem::path path;
  SceneFolder() {
    path = std::filesystem::temp_directory_path() /
           ("thinlayer-scene-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path);
  }
  ~SceneFolder() { std::filesystem::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path / name) << text;
    return (path / name).string();
  }
  // A scene of two files, NAME.geo and NAME.json (which names NAME.geo); the scene file's path.
  std::string write_scene(const std::string& name, const std::string& geo, const std::string& json) const {
    write(name + ".geo", geo);
    return write(name + ".json", json);
  }
};

inline std::string full_digits(double x) {
  char s[40];
  std::snprintf(s, sizeof s, "%.17g", x);
  return s;
}
