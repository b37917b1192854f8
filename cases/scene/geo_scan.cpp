#include "cases/scene/geo_scan.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "cases/scene/json_positions.h"

namespace thinlayer {

namespace {

namespace fs = std::filesystem;

struct Token {
  enum Kind { Identifier, String, Other } kind = Other;
  std::string text;
  int line = 1;
};

// The refused identifiers and why (gmsh 4.8's Parser/Gmsh.y: the commands it runs on a
// tSTRING, and the lexer's keywords of Parser/Gmsh.l).
const std::map<std::string, std::string>& refused_words() {
  static const std::map<std::string, std::string> words = [] {
    std::map<std::string, std::string> w;
    for (const char* c : {"System", "SystemCall", "NonBlockingSystemCall", "OnelabRun"}) w[c] = "runs a command";
    w["Plugin"] = "runs a gmsh plugin (some write files)";
    w["Sleep"] = "stalls the run";
    for (const char* c : {"Save", "Print", "CreateDir", "SendToServer"}) w[c] = "writes a file";
    w["Exit"] = "ends the process without a word";
    w["Abort"] = "stops reading the geometry half-way";
    for (const char* c : {"RefineMesh", "RecombineMesh", "OptimizeMesh", "AdaptMesh", "SetOrder", "PartitionMesh",
                          "RelocateMesh", "RenumberMeshNodes", "RenumberMeshElements", "ClassifySurfaces",
                          "CreateTopology", "CreateGeometry", "Homology", "Cohomology", "Betti", "Remesh"})
      w[c] = "meshes inside the script (thinlayer meshes the geometry itself, with the scene's mesh_size)";
    for (const char* c : {"General", "Solver", "PostProcessing", "View"})
      w[c] = "sets gmsh's process-wide options (only Geometry.* and Mesh.* are allowed in a scene's geometry)";
    for (const char* c : {"SetNumber", "SetString"}) w[c] = "sets ONELAB parameters, which can name solvers to run";
    for (const char* c : {"S2N", "StringToName"}) w[c] = "builds a name at run time, which could spell any command";
    return w;
  }();
  return words;
}

// The extensions gmsh reads as meshes or CAD shapes, not as scripts.
bool is_data_file(const fs::path& path) {
  static const std::set<std::string> data = {".msh", ".step", ".stp", ".brep", ".iges", ".igs", ".stl", ".unv",
                                             ".med", ".mesh", ".vtk", ".bdf", ".nas", ".inp", ".xao"};
  std::string extension = path.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return data.count(extension) > 0;
}

class GeoScanner {
 public:
  GeoScanner(std::string folder) : folder_(fs::weakly_canonical(fs::absolute(folder))) {}

  void scan(const fs::path& file, int depth) {
    if (depth > 16) throw InputError(file.string() + ": files included 16 deep (an include loop?)");
    const fs::path canonical = fs::weakly_canonical(fs::absolute(file));
    read_.insert(canonical.string());
    if (!scanned_.insert(canonical).second) return;
    const std::vector<Token> tokens = tokenize(file);
    for (std::size_t i = 0; i < tokens.size(); ++i) check(file, tokens, i, depth);
  }

 private:
  [[noreturn]] static void refuse(const fs::path& file, int line, const std::string& what) {
    throw InputError(file.string() + ":" + std::to_string(line) + ": " + what);
  }

  static std::vector<Token> tokenize(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError("cannot read geometry file " + file.string());
    std::ostringstream text_stream;
    text_stream << in.rdbuf();
    const std::string text = text_stream.str();
    std::vector<Token> tokens;
    int line = 1;
    auto identifier_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (std::size_t i = 0; i < text.size();) {
      const char c = text[i];
      if (c == '\n') {
        ++line, ++i;
      } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
        while (i < text.size() && text[i] != '\n') ++i;
      } else if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
        const int start = line;
        std::size_t end = text.find("*/", i + 2);
        if (end == std::string::npos) refuse(file, start, "a comment that never ends");
        for (; i < end + 2; ++i) line += text[i] == '\n';
      } else if (c == '"' || c == '\'') {  // gmsh's strings have no escapes
        const int start = line;
        const std::size_t end = text.find(c, i + 1);
        if (end == std::string::npos) refuse(file, start, "a string that never ends");
        tokens.push_back({Token::String, text.substr(i + 1, end - i - 1), start});
        for (; i <= end; ++i) line += text[i] == '\n';
      } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
        const std::size_t start = i;
        while (i < text.size() && identifier_char(text[i])) ++i;
        tokens.push_back({Token::Identifier, text.substr(start, i - start), line});
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++i;
      } else {
        tokens.push_back({Token::Other, std::string(1, c), line});
        ++i;
      }
    }
    return tokens;
  }

  static bool is(const std::vector<Token>& t, std::size_t i, const std::string& text) {
    return i < t.size() && t[i].kind == Token::Other && t[i].text == text;
  }

  void check(const fs::path& file, const std::vector<Token>& t, std::size_t i, int depth) {
    const Token& token = t[i];
    if (token.kind != Token::Identifier) return;
    const std::string& word = token.text;
    if (auto it = refused_words().find(word); it != refused_words().end())
      refuse(file, token.line, "'" + word + "' " + it->second + ": refused in a scene's geometry");
    // "Mesh.Option" is an option; "Mesh 2;" meshes.
    if (word == "Mesh" && !is(t, i + 1, "."))
      refuse(file, token.line, "'Mesh' " + refused_words().at("RefineMesh") + ": refused in a scene's geometry");
    if (word == "Printf") check_printf(file, t, i);
    if (word == "Include" || word == "Merge" || word == "MergeWithBoundingBox") {
      const fs::path included = checked_path(file, t, i + 1, word);
      if (!is(t, i + 2, ";")) refuse(file, token.line, "'" + word + "' takes one file name in quotes");
      if (word == "Include" || !is_data_file(included)) scan(included, depth + 1);
      read_.insert(included.string());
    }
    if (word == "ShapeFromFile" || word == "ListFromFile") {
      if (!is(t, i + 1, "(") && !is(t, i + 1, "[")) refuse(file, token.line, "'" + word + "' takes a file name in brackets");
      read_.insert(checked_path(file, t, i + 2, word).string());
    }
  }

  // Printf("...") > "file" and Printf("...", x) >> "file" write; Printf("...") prints.
  static void check_printf(const fs::path& file, const std::vector<Token>& t, std::size_t i) {
    if (!is(t, i + 1, "(")) return;  // not a Printf statement: gmsh refuses it itself
    int open = 0;
    std::size_t k = i + 1;
    for (; k < t.size(); ++k) {
      if (is(t, k, "(")) ++open;
      if (is(t, k, ")") && --open == 0) break;
    }
    if (is(t, k + 1, ">")) refuse(file, t[i].line, "'Printf(...) >' writes a file: refused in a scene's geometry");
  }

  // The file named by the string token t[k], resolved as gmsh does (FixRelativePath: against
  // the folder of the file that names it); refused unless it lies in the scene's folder.
  fs::path checked_path(const fs::path& file, const std::vector<Token>& t, std::size_t k, const std::string& word) const {
    const int line = t[k - 1].line;
    if (k >= t.size() || t[k].kind != Token::String)
      refuse(file, line, "'" + word + "' takes a file name in quotes (a computed name cannot be checked)");
    const fs::path named = t[k].text;
    const fs::path resolved = named.is_absolute() ? named : fs::absolute(file).parent_path() / named;
    const fs::path canonical = fs::weakly_canonical(resolved);
    const std::string inside = folder_.string() + "/";
    if (canonical.string().rfind(inside, 0) != 0)
      refuse(file, line, "'" + word + "' of " + t[k].text + ", a file outside the scene's folder " + folder_.string() +
                             ": refused in a scene's geometry");
    return canonical;
  }

  fs::path folder_;
  std::set<fs::path> scanned_;
  std::set<std::string> read_;  // every file the geometry reads

 public:
  const std::set<std::string>& files_read() const { return read_; }
};

}  // namespace

std::vector<std::string> scan_geo(const std::string& geo, const std::string& scene_folder) {
  GeoScanner scanner(scene_folder);
  scanner.scan(geo, 0);
  return {scanner.files_read().begin(), scanner.files_read().end()};
}

}  // namespace thinlayer
