#include "cases/scene/geo_scan.h"

#include <algorithm>
#include <cstdint>
#include <map>

#include "cases/scene/json_positions.h"

namespace thinlayer {

namespace {

// A token as an offset into the text, not a copy: a script of 4 MiB of ';' is 4 M tokens
// (cases/scene/scene_sources.h caps the text), 16 bytes each.
struct Token {
  enum Kind : std::uint8_t { Identifier, String, Other } kind = Other;
  std::uint32_t begin = 0, size = 0;
  std::int32_t line = 1;
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
    // What the scene would learn of the machine it runs on, and carry into messages and results.
    w["GetEnv"] = "reads the user's environment (a secret a message or a coordinate would carry)";
    w["FileExists"] = "probes the file system beyond the scene's files";
    for (const char* c : {"AbsolutePath", "CurrentDir", "CurrentDirectory", "CurrentFileName", "DirName",
                          "FixRelativePath", "GmshExecutableName"})
      w[c] = "works on where files lie on this machine (a path a result would carry); name files relative to the "
             "script, in quotes";
    for (const char* c : {"GetValue", "GetStringValue"}) w[c] = "asks the terminal for a value";
    for (const char* c : {"GetNumber", "GetString", "OnelabAction"})
      w[c] = "reads ONELAB parameters, which the command line or another program sets";
    for (const char* c : {"Today", "Cpu", "Memory", "TotalMemory"})
      w[c] = "reads the machine's clock or memory (the result would depend on the machine)";
    return w;
  }();
  return words;
}

bool is_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; }  // Gmsh.l's [\ \t\n\r\f]

class Scanner {
 public:
  Scanner(const std::string& text, const std::string& source) : text_(text), source_(source) {}

  std::vector<GeoReference> scan() {
    tokenize();
    std::vector<GeoReference> references;
    for (std::size_t i = 0; i < tokens_.size(); ++i) check(i, references);
    return references;
  }

 private:
  [[noreturn]] void refuse(int line, const std::string& what) const {
    throw InputError(source_ + ":" + std::to_string(line) + ": " + what);
  }

  // The end of the number starting at i, as Gmsh.l's longest match reads it:
  // {digit}+ ("." {digit}*)? {exp}? | {digit}* "." {digit}+ {exp}?, {exp} = [Ee][-+]?{digit}+.
  std::size_t number_end(std::size_t i) const {
    const std::size_t n = text_.size();
    while (i < n && is_digit(text_[i])) ++i;
    if (i < n && text_[i] == '.') {
      ++i;
      while (i < n && is_digit(text_[i])) ++i;
    }
    if (i < n && (text_[i] == 'e' || text_[i] == 'E')) {
      std::size_t k = i + 1;
      if (k < n && (text_[k] == '+' || text_[k] == '-')) ++k;
      if (k < n && is_digit(text_[k])) {
        while (k < n && is_digit(text_[k])) ++k;
        i = k;
      }
    }
    return i;
  }

  void add(Token::Kind kind, std::size_t begin, std::size_t size, int line) {
    tokens_.push_back({kind, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(size), line});
  }

  void tokenize() {
    if (text_.size() >= UINT32_MAX) refuse(1, "a script of 4 GiB or more");
    // Anywhere, a comment included: gmsh's comment ends at a NUL, the scan's would at the newline.
    if (const std::size_t nul = text_.find('\0'); nul != std::string::npos)
      refuse(1 + static_cast<int>(std::count(text_.begin(), text_.begin() + static_cast<std::ptrdiff_t>(nul), '\n')),
             "a NUL byte: gmsh ends a comment or a string there, so it would read this file otherwise than a text "
             "editor shows it");
    int line = 1;
    const std::size_t n = text_.size();
    for (std::size_t i = 0; i < n;) {
      const char c = text_[i];
      if (c == '\n') {
        ++line, ++i;
      } else if (c == '/' && i + 1 < n && text_[i + 1] == '/') {
        while (i < n && text_[i] != '\n') ++i;
      } else if (c == '/' && i + 1 < n && text_[i + 1] == '*') {
        const int start = line;
        const std::size_t end = text_.find("*/", i + 2);
        if (end == std::string::npos) refuse(start, "a comment that never ends");
        for (; i < end + 2; ++i) line += text_[i] == '\n';
      } else if (c == '"' || c == '\'') {  // gmsh's strings have no escapes
        const int start = line;
        const std::size_t end = text_.find(c, i + 1);
        if (end == std::string::npos) refuse(start, "a string that never ends");
        if (end - i - 1 > geo_string_max)
          refuse(start, "a string of " + std::to_string(end - i - 1) + " bytes: gmsh reads at most " +
                            std::to_string(geo_string_max) + " and the rest as statements");
        add(Token::String, i + 1, end - i - 1, start);
        for (; i <= end; ++i) line += text_[i] == '\n';
      } else if (is_alpha(c)) {
        const std::size_t start = i;
        while (i < n && (is_alpha(text_[i]) || is_digit(text_[i]))) ++i;
        add(Token::Identifier, start, i - start, line);
      } else if (is_digit(c) || (c == '.' && i + 1 < n && is_digit(text_[i + 1]))) {
        i = number_end(i);  // a number: nothing to check in it
      } else if (is_blank(c)) {
        ++i;
      } else {
        add(Token::Other, i, 1, line);
        ++i;
      }
    }
  }

  std::string text(std::size_t i) const { return text_.substr(tokens_[i].begin, tokens_[i].size); }
  bool is(std::size_t i, char c) const {
    return i < tokens_.size() && tokens_[i].kind == Token::Other && text_[tokens_[i].begin] == c;
  }

  void check(std::size_t i, std::vector<GeoReference>& references) const {
    const Token& token = tokens_[i];
    if (token.kind != Token::Identifier) return;
    const std::string word = text(i);
    if (auto it = refused_words().find(word); it != refused_words().end())
      refuse(token.line, "'" + word + "' " + it->second + ": refused in a scene's geometry");
    // "Mesh.Option" is an option; "Mesh 2;" meshes.
    if (word == "Mesh" && !is(i + 1, '.'))
      refuse(token.line, "'Mesh' " + refused_words().at("RefineMesh") + ": refused in a scene's geometry");
    if (word == "Printf") check_printf(i);
    if (word == "Include" || word == "Merge" || word == "MergeWithBoundingBox") {
      const std::string name = quoted_name(i + 1, word, token.line);
      if (!is(i + 2, ';')) refuse(token.line, "'" + word + "' takes one file name in quotes");
      references.push_back({word == "Include" ? GeoReference::Include : GeoReference::Merge, word, name, token.line});
    }
    if (word == "ShapeFromFile" || word == "ListFromFile") {
      if (!is(i + 1, '(') && !is(i + 1, '[')) refuse(token.line, "'" + word + "' takes a file name in brackets");
      const std::string name = quoted_name(i + 2, word, token.line);
      if (!is(i + 3, ')') && !is(i + 3, ']')) refuse(token.line, "'" + word + "' takes one file name in quotes");
      references.push_back({word == "ShapeFromFile" ? GeoReference::Shape : GeoReference::List, word, name, token.line});
    }
  }

  // Printf("...") > "file" and Printf("...", x) >> "file" write; Printf("...") prints.
  void check_printf(std::size_t i) const {
    if (!is(i + 1, '(')) return;  // not a Printf statement: gmsh refuses it itself
    int open = 0;
    std::size_t k = i + 1;
    for (; k < tokens_.size(); ++k) {
      if (is(k, '(')) ++open;
      if (is(k, ')') && --open == 0) break;
    }
    if (is(k + 1, '>')) refuse(tokens_[i].line, "'Printf(...) >' writes a file: refused in a scene's geometry");
  }

  std::string quoted_name(std::size_t k, const std::string& word, int line) const {
    if (k >= tokens_.size() || tokens_[k].kind != Token::String)
      refuse(line, "'" + word + "' takes a file name in quotes (a computed name cannot be checked)");
    return text(k);
  }

  const std::string& text_;
  const std::string& source_;
  std::vector<Token> tokens_;
};

}  // namespace

std::vector<GeoReference> scan_geo_text(const std::string& text, const std::string& source) {
  return Scanner(text, source).scan();
}

}  // namespace thinlayer
