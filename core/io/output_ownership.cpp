#include "core/io/output_ownership.h"

#include <cstring>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include "core/io/output_target.h"

namespace thinlayer {

namespace {

// The first `n` bytes of a file.
std::string head(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string text(n, '\0');
  in.read(text.data(), static_cast<std::streamsize>(n));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

// Raw bytes, never HDF5: a damaged file must not be parsed here (it crashed HDF5's H5Aread).
bool is_results_file(const std::string& path) {
  return head(path, std::strlen(results_marker)) == results_marker;
}

// summary.json is a few KB; nlohmann parses at most this much of a file, and never crashes.
constexpr std::size_t max_summary_bytes = 1u << 20;

bool is_summary(const std::string& path) {
  const std::string text = head(path, max_summary_bytes + 1);
  if (text.size() > max_summary_bytes) return false;
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return false;
  if (j.contains("layout")) return j["layout"] == summary_layout_name;
  return j.contains("checks") && j["checks"].is_array() && j.contains("timings") && j["timings"].is_object();
}

bool is_own(const std::string& path, OutputKind kind) {
  switch (kind) {
    case OutputKind::Results:
      return is_results_file(path);
    case OutputKind::Vtu: {
      const std::string top = head(path, 256);
      const std::size_t line = top.find('\n');
      return line != std::string::npos && top.compare(line + 1, std::string(vtu_marker).size(), vtu_marker) == 0;
    }
    case OutputKind::Csv:
      return head(path, std::string(csv_marker).size()) == csv_marker;
    case OutputKind::Summary:
      return is_summary(path);
  }
  return false;
}

const char* kind_name(OutputKind kind) {
  switch (kind) {
    case OutputKind::Results:
      return "a thinlayer results file";
    case OutputKind::Vtu:
      return "a VTU file thinlayer wrote";
    case OutputKind::Csv:
      return "a CSV file thinlayer wrote";
    case OutputKind::Summary:
      return "a summary.json thinlayer wrote";
  }
  return "";
}

}  // namespace

void check_replaceable(const std::string& path, OutputKind kind, const std::vector<InputFile>& inputs, bool force) {
  const std::string target = resolve_output_target(path);
  struct stat out {};
  if (::stat(target.c_str(), &out) != 0) return;  // nothing there to lose
  for (const InputFile& input : inputs) {
    struct stat in {};
    if (::stat(input.path.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino)
      throw OutputError("cannot write '" + path + "': it is " + input.what + " (" + input.path +
                        "), an input of this run; choose another name");
  }
  if (!force && !is_own(target, kind))
    throw OutputError("cannot write '" + path + "': it exists and is not " + kind_name(kind) +
                      (kind == OutputKind::Results ? " (give --force to replace it; a results file written before "
                                                     "thinlayer marked its files needs it once)"
                                                   : " (give --force to replace it)"));
}

std::string output_identity(const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path target = fs::absolute(resolve_output_target(path));
  std::error_code ec;
  const fs::path folder = fs::weakly_canonical(target.parent_path(), ec);
  return ((ec ? target.parent_path() : folder) / target.filename()).lexically_normal().string();
}

void check_distinct_outputs(const std::vector<OutputFile>& outputs, const std::vector<InputFile>& inputs) {
  namespace fs = std::filesystem;
  std::vector<std::pair<std::string, const OutputFile*>> seen;
  for (const OutputFile& out : outputs) {
    if (out.path.empty()) continue;
    const std::string identity = output_identity(out.path);
    for (const auto& [other, first] : seen)
      if (other == identity)
        throw OutputError("cannot write '" + out.path + "': " + first->what + " and " + out.what + " name the same file (" +
                          identity + "); choose another name");
    for (const InputFile& input : inputs) {
      std::error_code ec;
      if (fs::weakly_canonical(fs::absolute(input.path), ec).string() == identity && !ec)
        throw OutputError("cannot write '" + out.path + "': it is " + input.what + " (" + input.path +
                          "), an input of this run; choose another name");
    }
    seen.push_back({identity, &out});
  }
}

void write_output_text(const std::string& path, OutputKind kind, const OutputRules& rules, const std::string& text) {
  check_replaceable(path, kind, rules.inputs, rules.force);
  write_text_atomically(path, text, [&] { check_replaceable(path, kind, rules.inputs, rules.force); });
}

}  // namespace thinlayer
