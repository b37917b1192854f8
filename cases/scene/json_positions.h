#pragma once
// A JSON text parsed with the position (line, column) of every value, so that a scene file's
// schema errors can name where the bad key or value is, like its syntax errors do (SPEC §5).
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace thinlayer {

struct TextPosition {
  int line = 1, column = 1;  // both 1-based; the column counts bytes
};

// A bad input file: the message already names the file, line and column.
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Where each value of a document begins, as a tree shaped like the document: a member's node
// is keyed by its key, an element's by its index, so a key is stored once, not in the path of
// every value below it (a 15 MB key under many values took 3.7 GB as JSON pointers).
struct PositionTree {
  struct Node {
    TextPosition at;
    std::map<std::string, std::size_t> children;  // key or index -> nodes
  };
  std::vector<Node> nodes;  // nodes[0]: the document's first value
};

struct PositionedJson {
  std::string source;  // the file's name, as the user gave it: the prefix of every message
  nlohmann::json value;
  // JSON pointer ("/interface/friction", "/supports/0") → where that member's key (object
  // member) or that value (array element) begins. "" → the document's first value.
  PositionTree positions;

  TextPosition at(const std::string& pointer) const;
  // "<source>:<line>:<column>: <what>" at the position of `pointer` (or of its nearest parent
  // that has one), as an InputError.
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;
};

// Bounds (SPEC §4): nesting, entries per array or object, a key's length, and a scene file's size.
constexpr std::size_t max_json_depth = 64;
constexpr std::size_t max_json_entries = 10'000;
constexpr std::size_t max_json_key_bytes = 64;  // a scene's keys are its schema's words and its bodies' names
constexpr std::size_t max_json_bytes = 16u << 20;

// Parses `text` (nlohmann-json, strict RFC 8259: no comments, no trailing commas). Text nested
// deeper than max_json_depth or with more than max_json_entries in one array or object throws
// InputError at the first bracket or entry too many, before parsing; a key longer than
// max_json_key_bytes, at that key. A syntax
// error throws InputError "<source>:<line>:<column>: <nlohmann's description>". A key given
// twice in one object is refused too (nlohmann keeps the last one silently, which would hide a
// typo's twin).
PositionedJson parse_positioned_json(const std::string& text, const std::string& source);

// Reads and parses a file; a file that cannot be read, or larger than max_json_bytes, throws
// InputError naming it.
PositionedJson read_positioned_json(const std::string& path);

// The position of byte `offset` (0-based) in `text`.
TextPosition position_of(const std::string& text, std::size_t offset);

}  // namespace thinlayer
