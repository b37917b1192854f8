#include "cases/scene/json_positions.h"

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <vector>

namespace thinlayer {

namespace {

// Walks the text as nlohmann's lexer reads it, and counts how far it has read: the SAX events
// carry no position, but they fire in reading order, so "how far" tells where they are.
class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* p, const char* base, std::size_t* read) : p_(p), base_(base), read_(read) {}
  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    ++p_;
    *read_ = static_cast<std::size_t>(p_ - base_);
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& o) const { return p_ == o.p_; }
  bool operator!=(const CountingIterator& o) const { return p_ != o.p_; }

 private:
  const char* p_;
  const char* base_;
  std::size_t* read_;
};

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Positions of byte offsets, computed forward from the last one: the events come in reading
// order, so the text is walked once (position_of from the start each time was quadratic).
class PositionCursor {
 public:
  explicit PositionCursor(const std::string& text) : text_(text) {}
  TextPosition at(std::size_t offset) {
    if (offset < offset_) offset_ = 0, position_ = {};
    for (; offset_ < offset && offset_ < text_.size(); ++offset_) {
      if (text_[offset_] == '\n') {
        ++position_.line;
        position_.column = 1;
      } else {
        ++position_.column;
      }
    }
    return position_;
  }

 private:
  const std::string& text_;
  std::size_t offset_ = 0;
  TextPosition position_;
};

// Records the position of every key and array element, and refuses duplicate keys.
class PositionRecorder : public nlohmann::json_sax<nlohmann::json> {
 public:
  PositionRecorder(const std::string& text, const std::size_t* read, PositionedJson& out)
      : text_(text), read_(read), out_(out), cursor_(text) {}

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  // SPEC §4's strict numbers: an underflow is named, never read as 0 (nlohmann refuses an
  // overflow itself).
  bool number_float(number_float_t x, const string_t& text) override {
    const std::size_t start = next_token(last_end_, stack_.empty() || !stack_.back().object ? "[," : ":");
    if (x == 0 && text.find_first_of("123456789") < text.find_first_of("eE"))
      return refuse(start, "the number " + text + " underflows a double");
    // As on the command line: a subnormal has lost digits (glibc's ERANGE), so it is refused too.
    if (std::fpclassify(x) == FP_SUBNORMAL)
      return refuse(start, "the number " + text + " underflows a double (the smallest normal number is about 2.2e-308)");
    return value();
  }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    value();
    stack_.push_back({true, 0, current_, {}});
    return true;
  }
  bool key(string_t& k) override {
    Frame& f = stack_.back();
    const std::size_t start = next_token(last_end_, "{,");
    if (k.size() > max_json_key_bytes)
      return refuse(start, "a key of " + std::to_string(k.size()) + " bytes (a key, a body's name among them, is at most " +
                               std::to_string(max_json_key_bytes) + ")");
    if (!f.keys.insert(k).second) return refuse(start, "key '" + k + "' given twice");
    current_ = add_node(f.node, k, start);
    last_end_ = *read_;
    pending_key_ = true;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override {
    value();
    stack_.push_back({false, 0, current_, {}});
    return true;
  }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) override {
    error_byte_ = byte;
    error_ = e.what();
    return false;
  }

  const std::string& refusal() const { return refusal_; }
  TextPosition refusal_at() const { return refusal_at_; }
  const std::string& error() const { return error_; }
  std::size_t error_byte() const { return error_byte_; }

 private:
  struct Frame {
    bool object = false;
    int index = 0;
    std::size_t node = 0;  // the container's node in out_.positions
    std::set<std::string> keys;
  };

  bool refuse(std::size_t at, const std::string& why) {
    refusal_ = why;
    refusal_at_ = cursor_.at(at);
    return false;
  }

  std::size_t add_node(std::size_t parent, const std::string& key, std::size_t offset) {
    std::vector<PositionTree::Node>& nodes = out_.positions.nodes;
    nodes.push_back({cursor_.at(offset), {}});
    nodes[parent].children[key] = nodes.size() - 1;
    return nodes.size() - 1;
  }

  // The first byte at or after `from` that is neither blank nor one of `separators`: the start
  // of the next token (the lexer may have read one byte past a number, a separator included).
  std::size_t next_token(std::size_t from, const char* separators) const {
    std::size_t i = from;
    while (i < text_.size() && (is_blank(text_[i]) || std::string(separators).find(text_[i]) != std::string::npos)) ++i;
    return i;
  }

  // A value starts: an array element gets its own node and position; a member value has its
  // key's.
  bool value() {
    if (stack_.empty()) {
      out_.positions.nodes.assign(1, {cursor_.at(next_token(0, "")), {}});
      current_ = 0;
    } else if (!stack_.back().object) {
      Frame& f = stack_.back();
      current_ = add_node(f.node, std::to_string(f.index++), next_token(last_end_, "[,"));
    } else if (!pending_key_) {
      return false;  // cannot happen in valid JSON
    }
    pending_key_ = false;
    last_end_ = *read_;
    return true;
  }

  bool close() {
    stack_.pop_back();
    last_end_ = *read_;
    return true;
  }

  const std::string& text_;
  const std::size_t* read_;
  PositionedJson& out_;
  PositionCursor cursor_;
  std::vector<Frame> stack_;
  std::size_t current_ = 0;  // the node of the value being read
  std::size_t last_end_ = 0;
  bool pending_key_ = false;
  std::string refusal_, error_;
  TextPosition refusal_at_;
  std::size_t error_byte_ = 0;
};

std::string where(const std::string& source, TextPosition p) {
  return source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column) + ": ";
}

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 3,
// column 5: " prefix (the position is given our way, in front).
std::string syntax_message(const std::string& what) {
  if (const std::size_t s = what.find("syntax error"); s != std::string::npos) return what.substr(s);
  if (what.rfind("[json.exception.", 0) == 0) return what.substr(what.find("] ") + 2);
  return what;
}

// SPEC §4's bounds, checked on the raw text before nlohmann builds anything: its parser keeps a
// frame per open bracket and the position recorder a JSON pointer per value, so 100 000 nested
// brackets took 44 s and ended in std::bad_alloc (20 000: 842 MB), and 20 000 bodies ran for
// minutes. One pass, strings skipped; the error at the first bracket or entry too many.
void check_bounds(const std::string& text, const std::string& source) {
  std::vector<std::size_t> commas;  // per open bracket: the commas at its level so far
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {  // a string: skip it, and its escaped quotes
      for (++i; i < text.size() && text[i] != '"'; ++i)
        if (text[i] == '\\') ++i;
    } else if (c == '[' || c == '{') {
      if (commas.size() == max_json_depth)
        throw InputError(where(source, position_of(text, i)) + "nested deeper than " + std::to_string(max_json_depth) +
                         " levels (a scene file needs a few)");
      commas.push_back(0);
    } else if ((c == ']' || c == '}') && !commas.empty()) {
      commas.pop_back();
    } else if (c == ',' && !commas.empty() && ++commas.back() == max_json_entries) {
      throw InputError(where(source, position_of(text, i + 1)) + "more than " + std::to_string(max_json_entries) +
                       " entries in one list or object");
    }
  }
}

}  // namespace

TextPosition position_of(const std::string& text, std::size_t offset) { return PositionCursor(text).at(offset); }

TextPosition PositionedJson::at(const std::string& pointer) const {
  if (positions.nodes.empty()) return {};
  // The pointer's tokens (RFC 6901: "~1" is '/', "~0" is '~'), followed as far as they go: the
  // nearest parent that has a position answers.
  std::size_t node = 0;
  for (std::size_t at = pointer.empty() ? std::string::npos : 1; at != std::string::npos && at <= pointer.size();) {
    const std::size_t slash = pointer.find('/', at);
    const std::string raw = pointer.substr(at, slash == std::string::npos ? std::string::npos : slash - at);
    std::string token;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (raw[i] == '~' && i + 1 < raw.size() && (raw[i + 1] == '0' || raw[i + 1] == '1')) {
        token += raw[i + 1] == '0' ? '~' : '/';
        ++i;
      } else {
        token += raw[i];
      }
    }
    const auto child = positions.nodes[node].children.find(token);
    if (child == positions.nodes[node].children.end()) break;
    node = child->second;
    at = slash == std::string::npos ? std::string::npos : slash + 1;
  }
  return positions.nodes[node].at;
}

void PositionedJson::fail(const std::string& pointer, const std::string& what) const {
  throw InputError(where(source, at(pointer)) + what);
}

PositionedJson parse_positioned_json(const std::string& text, const std::string& source) {
  check_bounds(text, source);
  PositionedJson out;
  out.source = source;
  std::size_t read = 0;
  PositionRecorder recorder(text, &read, out);
  const CountingIterator first(text.data(), text.data(), &read), last(text.data() + text.size(), text.data(), &read);
  if (!nlohmann::json::sax_parse(first, last, &recorder)) {
    if (!recorder.refusal().empty()) throw InputError(where(source, recorder.refusal_at()) + recorder.refusal());
    // nlohmann counts the byte it stopped at from 1.
    const std::size_t byte = recorder.error_byte() > 0 ? recorder.error_byte() - 1 : 0;
    throw InputError(where(source, position_of(text, byte)) + syntax_message(recorder.error()));
  }
  out.value = nlohmann::json::parse(text);  // cannot fail: the same text passed above
  return out;
}

PositionedJson read_positioned_json(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError("scene file " + path + " does not exist");
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError("scene file " + path + " is not a regular file");
  if (std::filesystem::file_size(path, ec) > max_json_bytes)
    throw InputError("scene file " + path + " is larger than " + std::to_string(max_json_bytes >> 20) +
                     " MiB (a scene file names its geometry: it is small)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read scene file " + path);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read scene file " + path);
  return parse_positioned_json(text.str(), path);
}

}  // namespace thinlayer
