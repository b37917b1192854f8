#include "cases/scene/scene_spec.h"

#include "cases/scene/scene_checks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>

namespace thinlayer {

namespace {

using nlohmann::json;

const char* type_name(const json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  return "an object";
}

// A key as a JSON pointer token (RFC 6901: '~' → "~0", '/' → "~1").
std::string pointer_token(const std::string& key) {
  std::string s;
  for (char c : key) s += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return s;
}

// One JSON object of the scene file: its allowed keys, and typed access that fails at the
// key's position.
class ObjectReader {
 public:
  ObjectReader(const PositionedJson& doc, std::string pointer, std::string what, std::set<std::string> allowed)
      : doc_(doc), pointer_(std::move(pointer)), what_(std::move(what)) {
    const json& v = value_at(pointer_);
    if (!v.is_object()) doc_.fail(pointer_, what_ + " must be an object, not " + type_name(v));
    for (const auto& [key, _] : v.items())
      if (!allowed.count(key)) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        doc_.fail(child(key), "unknown key '" + key + "' in " + what_ + " (expected one of: " + list + ")");
      }
  }

  bool has(const std::string& key) const { return object().contains(key); }
  std::string child(const std::string& key) const { return pointer_ + "/" + pointer_token(key); }
  std::string where(const std::string& key) const {
    const TextPosition p = doc_.at(child(key));
    return doc_.source + ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
  }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const { doc_.fail(child(key), message); }
  [[noreturn]] void fail_here(const std::string& message) const { doc_.fail(pointer_, message); }

  const json& require(const std::string& key) const {
    if (!has(key)) doc_.fail(pointer_, what_ + " has no '" + key + "'");
    return object().at(key);
  }
  std::string text(const std::string& key) const {
    const json& v = require(key);
    if (!v.is_string()) fail(key, "'" + key + "' in " + what_ + " must be a string, not " + type_name(v));
    if (v.get<std::string>().empty()) fail(key, "'" + key + "' in " + what_ + " is empty");
    return v.get<std::string>();
  }
  // A finite number in [lo, hi] (hi may be excluded), or +inf as the string "inf" where allowed.
  double number(const std::string& key, double lo, double hi, bool hi_open = false, bool inf_allowed = false) const {
    return number_value(require(key), child(key), "'" + key + "' in " + what_, lo, hi, hi_open, inf_allowed);
  }
  double number_value(const json& v, const std::string& pointer, const std::string& name, double lo, double hi,
                      bool hi_open = false, bool inf_allowed = false) const {
    double x = 0;
    if (inf_allowed && v.is_string() && v.get<std::string>() == "inf") return std::numeric_limits<double>::infinity();
    if (!v.is_number())
      doc_.fail(pointer, name + " must be a number" + (inf_allowed ? std::string(" or \"inf\"") : "") + ", not " +
                             type_name(v));
    x = v.get<double>();
    if (!std::isfinite(x)) doc_.fail(pointer, name + " overflows a double");
    if (x < lo || x > hi || (hi_open && x == hi))
      doc_.fail(pointer, name + " must be in [" + num(lo) + ", " + num(hi) + (hi_open ? ")" : "]") + ", got " + num(x));
    return x;
  }
  const json& object() const { return value_at(pointer_); }
  const PositionedJson& doc() const { return doc_; }

 private:
  static std::string num(double x) {
    if (std::isinf(x)) return "inf";
    std::ostringstream s;
    s << x;
    return s.str();
  }
  const json& value_at(const std::string& pointer) const { return doc_.value.at(json::json_pointer(pointer)); }

  const PositionedJson& doc_;
  std::string pointer_, what_;
};

constexpr double inf = std::numeric_limits<double>::infinity();

constexpr double modulus_max = 1e12;  // daN/mm²: far above any solid (diamond ~ 5e4)

std::string resolve(const std::string& folder, const std::string& path) {
  const std::filesystem::path p(path);
  return p.is_absolute() ? path : (std::filesystem::path(folder) / p).string();
}

void read_geometry(const ObjectReader& root, SceneSpec& s) {
  if (root.has("geometry") == root.has("mesh")) root.fail_here("the scene needs exactly one of 'geometry' (.geo) and 'mesh' (.msh)");
  const std::string key = root.has("geometry") ? "geometry" : "mesh";
  const std::string path = resolve(s.folder, root.text(key));
  const std::string extension = std::filesystem::path(path).extension().string();
  if (key == "geometry" && extension != ".geo") root.fail(key, "'geometry' must name a gmsh .geo file, got " + path);
  if (key == "mesh" && extension != ".msh") root.fail(key, "'mesh' must name a gmsh .msh file, got " + path);
  if (!std::filesystem::is_regular_file(path)) root.fail(key, key + " file " + path + " does not exist");
  (key == "geometry" ? s.geometry : s.mesh) = path;
  s.geometry_where = root.where(key);
  if (root.has("mesh_size")) {
    if (key == "mesh") root.fail("mesh_size", "'mesh_size' applies to a 'geometry' only (a .msh is used as is)");
    const ObjectReader size(root.doc(), root.child("mesh_size"), "mesh_size", {"interface", "far"});
    s.h_interface = size.number("interface", 0, inf);
    s.h_far = size.number("far", 0, inf);
    if (!(*s.h_interface > 0) || !(*s.h_far > 0)) size.fail_here("mesh sizes must be > 0");
    if (*s.h_far < *s.h_interface) size.fail("far", "'far' must be >= 'interface'");
  }
}

SceneBodySpec read_body(const PositionedJson& doc, const std::string& name, const std::string& pointer) {
  const ObjectReader b(doc, pointer, "body '" + name + "'", {"group", "lambda", "mu", "E", "nu"});
  SceneBodySpec body;
  body.name = name;
  body.group = b.text("group");
  body.group_where = b.where("group");
  const bool lame = b.has("lambda") || b.has("mu"), young = b.has("E") || b.has("nu");
  if (lame == young) b.fail_here("body '" + name + "' needs either 'lambda' and 'mu' or 'E' and 'nu'");
  if (young) {
    const double E = b.number("E", 0, modulus_max), nu = b.number("nu", -1, 0.5, /*hi_open=*/true);
    if (!(E > 0) || !(nu > -1)) b.fail_here("body '" + name + "' needs E > 0 and -1 < nu < 0.5");
    const LameModuli m = lame_from_young(E, nu);
    body.lambda = m.lambda;
    body.mu = m.mu;
    return body;
  }
  body.lambda = b.number("lambda", -modulus_max, modulus_max);
  body.mu = b.number("mu", 0, modulus_max);
  if (!(body.mu > 0) || !(body.lambda + body.mu > 0)) b.fail_here("body '" + name + "' needs mu > 0 and lambda + mu > 0");
  return body;
}

// A name that becomes part of an HDF5 path or a scene id: letters, digits, '-', '_', '.'.
bool plain_name(const std::string& name) {
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) return false;
  return !name.empty();
}

FaceHold read_face(const ObjectReader& faces, const std::string& key) {
  if (!faces.has(key)) return FaceHold::Contact;
  const std::string v = faces.text(key);
  if (v != "bonded" && v != "contact")
    faces.fail(key, "'" + key + "' in faces must be \"bonded\" or \"contact\", got \"" + v + "\"");
  return v == "bonded" ? FaceHold::Bonded : FaceHold::Contact;
}

SceneInterfaceSpec read_interface(const SceneSpec& s, const PositionedJson& doc, const std::string& pointer,
                                  const std::string& what, const std::string& where) {
  const ObjectReader i(doc, pointer, what, {"group", "plus", "minus", "friction", "faces", "layer", "glue", "law", "make_room"});
  SceneInterfaceSpec f;
  f.where = where;
  f.group = i.text("group");
  f.group_where = i.where("group");
  f.plus = i.text("plus");
  f.minus = i.text("minus");
  if (s.body_index(f.plus) < 0) i.fail("plus", "'plus' names no body of 'bodies': " + f.plus);
  if (s.body_index(f.minus) < 0) i.fail("minus", "'minus' names no body of 'bodies': " + f.minus);
  if (f.plus == f.minus) i.fail("minus", "'plus' and 'minus' are the same body");
  if (i.has("faces")) {
    const ObjectReader faces(doc, i.child("faces"), "faces", {"plus", "minus"});
    f.faces.plus = read_face(faces, "plus");
    f.faces.minus = read_face(faces, "minus");
  }
  if (i.has("make_room")) {  // the direction the plus body moves in to make room for the layer
    const json& v = i.object().at("make_room");
    if (!v.is_array() || v.size() != 2)
      i.fail("make_room", "'make_room' must be a direction [dx, dy] (the plus body moves along it to make room for the layer)");
    const std::string p = i.child("make_room");
    const double dx = i.number_value(v[0], p + "/0", "'make_room' x", -1e6, 1e6);
    const double dy = i.number_value(v[1], p + "/1", "'make_room' y", -1e6, 1e6);
    const double norm = std::hypot(dx, dy);
    if (!(norm > 0)) i.fail("make_room", "'make_room' must be a nonzero direction [dx, dy]");
    f.make_room = std::array<double, 2>{dx / norm, dy / norm};
    f.make_room_where = i.where("make_room");
  }
  // Both faces bonded: no contact anywhere, so no friction (a "friction" given is not used).
  if (i.has("friction") || !f.faces.both_bonded()) f.friction = i.number("friction", 0, 1e6);
  const int given = i.has("layer") + i.has("glue") + i.has("law");
  if (given != 1) i.fail_here(what + " needs exactly one of 'layer', 'glue' and 'law'");
  if (i.has("layer")) {
    const ObjectReader l(doc, i.child("layer"), "layer", {"gamma", "delta", "lambda_g", "mu_g"});
    SceneLayerSpec layer;
    layer.gamma = l.number("gamma", 0, 100);
    layer.delta = l.number("delta", 0, 2, /*hi_open=*/true);
    layer.lambda_g = l.number("lambda_g", 0, modulus_max);
    layer.mu_g = l.number("mu_g", 0, modulus_max);
    if (!(layer.mu_g > 0)) l.fail("mu_g", "'mu_g' must be > 0 (the layer needs a shear stiffness)");
    f.layer = layer;
  } else if (i.has("glue")) {
    const ObjectReader g(doc, i.child("glue"), "glue", {"E", "nu", "thickness"});
    SceneGlueSpec glue;
    glue.E = g.number("E", 0, modulus_max);
    if (!(glue.E > 0)) g.fail("E", "'E' must be > 0");
    glue.nu = g.number("nu", -1, 0.5, /*hi_open=*/true);
    if (!(glue.nu > -1)) g.fail("nu", "'nu' must be in (-1, 0.5)");
    glue.thickness = g.number("thickness", 0, 1e6);
    if (!(glue.thickness > 0)) g.fail("thickness", "'thickness' must be > 0 (mm)");
    f.glue = glue;
  } else {
    const ObjectReader l(doc, i.child("law"), "law", {"lambda_bar", "mu_bar"});
    f.lambda_bar = l.number("lambda_bar", 0, inf, false, true);
    f.mu_bar = l.number("mu_bar", 0, inf, false, true);
  }
  return f;
}

void read_interfaces(const ObjectReader& root, SceneSpec& s) {
  if (root.has("interface") == root.has("interfaces"))
    root.fail_here("the scene needs exactly one of 'interface' (one bondline) and 'interfaces' (a list of them)");
  if (root.has("interface")) {
    s.interfaces.push_back(read_interface(s, root.doc(), root.child("interface"), "interface", root.where("interface")));
    return;
  }
  s.interface_list = true;
  const json& list = root.object().at("interfaces");
  if (!list.is_array() || list.empty())
    root.fail("interfaces", "'interfaces' must be an array of at least one bondline, not " + std::string(type_name(list)));
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string p = root.child("interfaces") + "/" + std::to_string(k);
    const TextPosition at = root.doc().at(p);
    SceneInterfaceSpec f = read_interface(s, root.doc(), p, "interface " + std::to_string(k),
                                          root.doc().source + ":" + std::to_string(at.line) + ":" + std::to_string(at.column));
    // Its group names its results (interface/<group>/S): one path component of a plain name.
    const ObjectReader i(root.doc(), p, "interface", {"group", "plus", "minus", "friction", "faces", "layer", "glue", "law", "make_room"});
    if (!plain_name(f.group))
      i.fail("group", "a bondline's group names its results (interface/<group>/S): letters, digits, '-', '_' and '.' only");
    for (const SceneInterfaceSpec& other : s.interfaces)
      if (other.group == f.group) i.fail("group", "bondline group '" + f.group + "' is listed twice");
    f.name = f.group;
    s.interfaces.push_back(f);
  }
}

std::optional<double> component(const ObjectReader& r, const nlohmann::json& v, const std::string& pointer) {
  if (v.is_null()) return std::nullopt;
  return r.number_value(v, pointer, "a component of 'u'", -1e6, 1e6);
}

void read_supports(const ObjectReader& root, SceneSpec& s) {
  if (!root.has("supports")) return;
  const json& list = root.object().at("supports");
  if (!list.is_array()) root.fail("supports", "'supports' must be an array, not " + std::string(type_name(list)));
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string p = root.child("supports") + "/" + std::to_string(k);
    const ObjectReader r(root.doc(), p, "support " + std::to_string(k), {"group", "u"});
    SceneSupportSpec sup;
    sup.group = r.text("group");
    sup.where = r.where("group");
    const json& u = r.require("u");
    if (!u.is_array() || u.size() != 2) r.fail("u", "'u' must be an array of two components (a number in mm, or null: free)");
    sup.u = {component(r, u[0], r.child("u") + "/0"), component(r, u[1], r.child("u") + "/1")};
    if (!sup.u[0] && !sup.u[1]) r.fail("u", "'u' leaves both components free: that support holds nothing");
    s.supports.push_back(sup);
  }
}

void read_loads(const ObjectReader& root, SceneSpec& s) {
  if (!root.has("loads")) return;
  const json& list = root.object().at("loads");
  if (!list.is_array()) root.fail("loads", "'loads' must be an array, not " + std::string(type_name(list)));
  const std::string stress = s.units.stress(), force = s.units.force + "/mm";
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string p = root.child("loads") + "/" + std::to_string(k);
    const ObjectReader r(root.doc(), p, "load " + std::to_string(k), {"group", "traction", "pressure", "force"});
    SceneLoadSpec load;
    load.group = r.text("group");
    load.where = r.where("group");
    if (r.has("traction") + r.has("pressure") + r.has("force") != 1)
      r.fail_here("load " + std::to_string(k) + " needs exactly one of 'traction' [tx, ty] (" + stress + "), 'pressure' p (" +
                  stress + ", compressive positive) and 'force' [Fx, Fy] (" + force + ")");
    if (r.has("pressure")) {
      load.kind = LoadKind::Pressure;
      load.pressure = r.number("pressure", -1e9, 1e9);
      s.loads.push_back(load);
      continue;
    }
    const std::string key = r.has("traction") ? "traction" : "force";
    load.kind = key == "traction" ? LoadKind::Traction : LoadKind::Force;
    const json& t = r.require(key);
    if (!t.is_array() || t.size() != 2)
      r.fail(key, "'" + key + "' must be an array of two numbers (" + (key == "traction" ? stress : force) + ")");
    for (int c = 0; c < 2; ++c)
      load.vector[c] = r.number_value(t[c], r.child(key) + "/" + std::to_string(c), "a component of '" + key + "'", -1e9, 1e9);
    s.loads.push_back(load);
  }
}

void read_units(const ObjectReader& root, SceneSpec& s) {
  if (!root.has("units")) return;
  const json& v = root.object().at("units");
  if (v.is_string()) {
    const std::string u = v.get<std::string>();
    if (u != "mm-daN" && u != "mm-N") root.fail("units", "'units' must be \"mm-daN\" (the default) or \"mm-N\", got \"" + u + "\"");
    s.units.force = u == "mm-N" ? "N" : "daN";
    return;
  }
  // The earlier object form, {"length": "mm", "force": "daN" | "N"}.
  const ObjectReader u(root.doc(), root.child("units"), "units", {"length", "force"});
  if (u.has("length") && u.text("length") != "mm") u.fail("length", "only \"mm\" lengths are supported");
  if (u.has("force")) {
    const std::string f = u.text("force");
    if (f != "daN" && f != "N") u.fail("force", "'force' must be \"daN\" or \"N\"");
    s.units.force = f;
  }
}

void read_options(const ObjectReader& root, SceneSpec& s) {
  if (root.has("element")) {
    const std::string e = root.text("element");
    if (e != "Q1" && e != "P1") root.fail("element", "'element' must be \"Q1\" or \"P1\", got \"" + e + "\"");
    s.element = e == "Q1" ? ElementType::Q1 : ElementType::P1;
  }
  if (root.has("plane")) {
    const std::string p = root.text("plane");
    if (p != "strain" && p != "stress") root.fail("plane", "'plane' must be \"strain\" or \"stress\", got \"" + p + "\"");
    s.plane = p == "strain" ? PlaneHypothesis::Strain : PlaneHypothesis::Stress;
  }
  if (root.has("characteristic_length")) {
    s.characteristic_length = root.number("characteristic_length", 0, 1e9);
    if (!(*s.characteristic_length > 0)) root.fail("characteristic_length", "'characteristic_length' must be > 0 (mm)");
  }
  if (root.has("eps")) {
    const json& list = root.object().at("eps");
    if (!list.is_array() || list.size() < 3) root.fail("eps", "'eps' must be an array of at least 3 thicknesses (mm)");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const double e = root.number_value(list[k], root.child("eps") + "/" + std::to_string(k), "an 'eps'", 0, 1e6);
      if (!(e > 0)) root.fail("eps", "every 'eps' must be > 0");
      s.eps.push_back(e);
    }
  }
  if (root.has("layer_elements")) {
    const json& v = root.object().at("layer_elements");
    if (!v.is_number_integer() || v.get<long long>() < 2 || v.get<long long>() > 64)
      root.fail("layer_elements", "'layer_elements' must be an integer in [2, 64]");
    s.layer_elements = static_cast<int>(v.get<long long>());
  }
}

}  // namespace

int SceneSpec::body_index(const std::string& n) const {
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].name == n) return static_cast<int>(b);
  return -1;
}

bool SceneSpec::has_layer() const {
  for (const SceneInterfaceSpec& i : interfaces)
    if (i.has_layer_mode()) return true;
  return false;
}

bool SceneSpec::engineer_glue_only() const {
  bool any = false;
  for (const SceneInterfaceSpec& i : interfaces) {
    if (i.layer) return false;
    any = any || i.glue.has_value();
  }
  return any;
}

Glue SceneInterfaceSpec::glue_model() const {
  if (layer) return Glue::scaled(layer->gamma, layer->delta, layer->lambda_g, layer->mu_g);
  if (glue) return Glue::engineer(glue->E, glue->nu, glue->thickness);
  throw std::invalid_argument(label() + " gives a limit law only ('law'): it has no layer");
}

std::string SceneInterfaceSpec::label() const { return name.empty() ? "the interface" : "bondline '" + name + "'"; }

const char* to_string(LoadKind kind) {
  return kind == LoadKind::Traction ? "traction" : kind == LoadKind::Pressure ? "pressure" : "force";
}

SceneSpec scene_spec_from_json(const PositionedJson& doc, const std::string& folder) {
  const ObjectReader root(doc, "", "the scene",
                          {"name", "geometry", "mesh", "mesh_size", "element", "plane", "units", "bodies", "interface",
                           "interfaces", "supports", "loads", "eps", "layer_elements", "characteristic_length"});
  SceneSpec s;
  s.file = doc.source;
  s.folder = folder;
  s.name = root.text("name");
  // The name becomes HDF5 group and scene names (/studies/scene/<name>, <name>-limit-fast).
  if (!plain_name(s.name))
    root.fail("name", "'name' may hold letters, digits, '-', '_' and '.' only (it names groups in the results file)");
  read_units(root, s);
  read_options(root, s);
  read_geometry(root, s);
  const json& bodies = root.require("bodies");
  if (!bodies.is_object() || bodies.empty()) root.fail("bodies", "'bodies' must be an object naming at least one body");
  // nlohmann's objects are sorted by key; the file's order is the order of the positions.
  std::vector<std::pair<TextPosition, std::string>> order;
  for (const auto& [name, _] : bodies.items()) order.push_back({doc.at("/bodies/" + pointer_token(name)), name});
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
    return a.first.line != b.first.line ? a.first.line < b.first.line : a.first.column < b.first.column;
  });
  for (const auto& [pos, name] : order) {
    if (name.rfind("layer", 0) == 0)
      root.fail("bodies", "a body's name may not begin with 'layer' (the names of the layer mode's layers): " + name);
    SceneBodySpec body = read_body(doc, name, "/bodies/" + pointer_token(name));
    body.where = doc.source + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
    s.bodies.push_back(body);
  }
  read_interfaces(root, s);
  read_supports(root, s);
  read_loads(root, s);
  check_scene_spec(s, doc);  // names, materials, repeated groups (cases/scene/scene_checks.h)
  return s;
}

SceneSpec read_scene_spec(const std::string& path) {
  const PositionedJson doc = read_positioned_json(path);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  return scene_spec_from_json(doc, folder.empty() ? "." : folder.string());
}

}  // namespace thinlayer
