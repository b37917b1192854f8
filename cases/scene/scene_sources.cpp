#include "cases/scene/scene_sources.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cases/scene/geo_scan.h"
#include "cases/scene/json_positions.h"

namespace thinlayer {

namespace {

namespace fs = std::filesystem;

// What a file is, for the message that refuses it.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO (its reader would wait for a writer)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string join(const std::vector<std::string>& parts) {
  std::string s;
  for (const std::string& p : parts) s += (s.empty() ? "" : "/") + p;
  return s;
}

std::string extension(const std::string& staged) {
  const std::size_t slash = staged.rfind('/'), dot = staged.rfind('.');
  return dot == std::string::npos || (slash != std::string::npos && dot < slash) ? "" : staged.substr(dot);
}

// gmsh's side file (Common/OpenFile.cpp, MergeFile, in 4.8 as in 4.11): after merging any file F
// (the entry gmsh opens, a Merge, the side file itself) it merges F + ".opt" if that exists.
constexpr const char* side_file_suffix = ".opt";
bool is_side_file(const std::string& staged) {
  const std::string suffix = side_file_suffix;
  return staged.size() >= suffix.size() && staged.compare(staged.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string folder_of(const std::string& staged) {
  const std::size_t slash = staged.rfind('/');
  return slash == std::string::npos ? "" : staged.substr(0, slash);
}

// Where a message about a file's own content points: "<path>:<line>: ".
std::string at_line(const std::string& path, int line) { return path + ":" + std::to_string(line) + ": "; }

class SourceReader {
 public:
  explicit SourceReader(const std::string& folder) : folder_(folder) {
    std::error_code ec;
    canonical_folder_ = fs::canonical(folder.empty() ? "." : folder, ec).string();
    if (ec) throw InputError("cannot read the scene's folder " + folder + ": " + ec.message());
  }

  SceneSources read(const std::string& name, bool mesh, const std::string& where) {
    const std::string prefix = where + ": '" + std::string(mesh ? "mesh" : "geometry") + "' " + name + ": ";
    std::string relative = name;
    if (!name.empty() && name[0] == '/') {  // an absolute name, accepted when inside the folder
      const fs::path inside = fs::path(name).lexically_normal().lexically_relative(fs::absolute(folder_).lexically_normal());
      if (inside.empty() || *inside.begin() == "..")
        throw InputError(prefix + "a file outside the scene's folder " + canonical_folder_ + " (gmsh is given that folder only)");
      relative = inside.string();
    }
    const std::string staged = resolve("", relative, prefix);
    out_.entry = staged;
    add(staged, mesh ? SceneSource::Mesh : SceneSource::Script, prefix);
    return std::move(out_);
  }

 private:
  // The staged name gmsh reaches from the folder `base` (staged) through `name`: the kernel's
  // resolution, component by component, in a staging folder without links. Every folder the
  // name passes through is made there (so "sub/../x.geo" resolves as it does here).
  std::string resolve(const std::string& base, const std::string& name, const std::string& prefix) {
    if (name.empty()) throw InputError(prefix + "an empty file name");
    if (name.find('\\') != std::string::npos)
      throw InputError(prefix + "a file name holding a backslash, which gmsh reads as a folder separator: use '/'");
    if (name[0] == '/' || (name.size() > 2 && name[1] == ':' && (name[2] == '/' || name[2] == '\\')))
      throw InputError(prefix + "an absolute file name (gmsh reads only the scene's folder): name it relative to the file "
                                "that names it");
    std::vector<std::string> stack, parts;
    if (!base.empty()) parts.push_back(base);
    parts.push_back(name);
    std::vector<std::string> components;
    for (const std::string& part : parts)
      for (std::size_t at = 0; at <= part.size();) {
        const std::size_t slash = std::min(part.find('/', at), part.size());
        components.push_back(part.substr(at, slash - at));
        at = slash + 1;
      }
    const std::string last = components.back();
    if (last.empty() || last == "." || last == "..") throw InputError(prefix + "names a folder, not a file");
    components.pop_back();
    for (const std::string& c : components) {
      if (c.empty() || c == ".") continue;
      if (c == "..") {
        if (stack.empty()) throw InputError(prefix + "a file outside the scene's folder " + canonical_folder_ + " (gmsh is given that folder only)");
        stack.pop_back();
        continue;
      }
      stack.push_back(c);
      const std::string folder = join(stack);
      if (made_.insert(folder).second) out_.folders.push_back(folder);
    }
    stack.push_back(last);
    if (is_side_file(last))
      throw InputError(prefix + "a file named '*" + std::string(side_file_suffix) + "': gmsh merges '<file>" +
                       side_file_suffix + "' as a script after every file it merges, unasked, so no file of a scene may "
                       "end in " + side_file_suffix);
    return join(stack);
  }

  std::string user_path(const std::string& staged) const {
    return folder_.empty() || folder_ == "." ? staged : (fs::path(folder_) / staged).string();
  }

  // Reads the file once (a regular file inside the folder, within its bound), checks it as a
  // `kind`, and follows what a script names.
  void add(const std::string& staged, SceneSource::Kind kind, const std::string& prefix) {
    auto [known, added] = index_.emplace(staged, out_.files.size());
    if (added) {
      if (out_.files.size() == max_source_files)
        throw InputError(prefix + "more than " + std::to_string(max_source_files) + " files read by one scene");
      out_.files.push_back({kind, user_path(staged), staged, read_bytes(staged, kind, prefix)});
    }
    if (!checked_.insert({staged, kind}).second && kind != SceneSource::Script) return;
    const std::string bytes = out_.files[known->second].bytes;  // a copy: out_.files may grow below
    const std::string path = out_.files[known->second].path;
    switch (kind) {
      case SceneSource::Script:
        return follow(staged, path, bytes, prefix);
      case SceneSource::Mesh:
        if (bytes.compare(0, 11, "$MeshFormat") != 0)
          throw InputError(at_line(path, 1) + "a mesh file that does not begin with $MeshFormat: gmsh would read it as a "
                                              "script (a scene's mesh is a gmsh .msh file, format 4.1)");
        return;
      case SceneSource::Shape:
        return check_shape(staged, path, bytes);
      case SceneSource::List:  // numbers for gmsh; scanned all the same: staged means scanned
        scan_geo_text(bytes, path);
        return;
    }
  }

  std::string read_bytes(const std::string& staged, SceneSource::Kind kind, const std::string& prefix) {
    const std::string path = user_path(staged);
    const std::string real = (fs::path(folder_.empty() ? "." : folder_) / staged).string();
    struct stat named {};
    if (::stat(real.c_str(), &named) != 0) throw InputError(prefix + "cannot read " + path + ": " + std::strerror(errno));
    std::error_code ec;
    const std::string canonical = fs::canonical(real, ec).string();
    if (ec || canonical.rfind(canonical_folder_ + "/", 0) != 0)
      throw InputError(prefix + path + " is a link to a file outside the scene's folder " + canonical_folder_ +
                       " (gmsh is given that folder only)");
    if (!S_ISREG(named.st_mode)) throw InputError(prefix + path + " is " + kind_of(named.st_mode) + ", not a regular file");
    const bool script = kind == SceneSource::Script || kind == SceneSource::List;
    const std::size_t bound = script ? max_script_bytes - script_bytes_ : kind == SceneSource::Mesh ? max_mesh_bytes : max_shape_bytes;
    auto too_large = [&] {
      return InputError(prefix +  // it names the file
                        (script ? "the scene's scripts together are larger than " + std::to_string(max_script_bytes >> 20) +
                                      " MiB (a geometry is small: the lap joint's is 2 KB)"
                                : "larger than " + std::to_string(bound >> 20) + " MiB"));
    };
    if (static_cast<std::size_t>(named.st_size) > bound) throw too_large();
    // Non-blocking: should the file have become a FIFO since the stat, the read does not wait.
    const int fd = ::open(real.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw InputError(prefix + "cannot read " + path + ": " + std::strerror(errno));
    struct stat opened {};
    if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode) || opened.st_ino != named.st_ino || opened.st_dev != named.st_dev) {
      ::close(fd);
      throw InputError(prefix + path + " changed while it was read");
    }
    std::string bytes;
    char buffer[1 << 16];
    while (true) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        const int error = errno;
        ::close(fd);
        throw InputError(prefix + "cannot read " + path + ": " + std::strerror(error));
      }
      if (n == 0) break;
      bytes.append(buffer, static_cast<std::size_t>(n));
      if (bytes.size() > bound) {
        ::close(fd);
        throw too_large();
      }
    }
    ::close(fd);
    if (script) script_bytes_ += bytes.size();
    return bytes;
  }

  // A script: scanned, and what it names followed (an include loop refused).
  void follow(const std::string& staged, const std::string& path, const std::string& bytes, const std::string& prefix) {
    for (const std::string& open : reading_)
      if (open == staged) throw InputError(prefix + "an include loop: " + path + " is already being read (" + chain() + ")");
    if (static_cast<int>(reading_.size()) == max_include_depth)
      throw InputError(prefix + "files included more than " + std::to_string(max_include_depth) + " deep (" + chain() + ")");
    if (!scanned_.insert(staged).second) return;  // read before, by another branch: nothing new
    if (!bytes.empty() && bytes[0] == '$')
      throw InputError(at_line(path, 1) + "a script that begins with '$': gmsh would read it as a mesh or a view, not as "
                                          "the script thinlayer scanned");
    const std::vector<GeoReference> references = scan_geo_text(bytes, path);
    reading_.push_back(staged);
    for (const GeoReference& r : references) {
      const std::string where = at_line(path, r.line) + "'" + r.word + "' of \"" + r.name + "\": ";
      const std::string target = resolve(folder_of(staged), r.name, where);
      add(target, kind_of_reference(r, target, where), where);
    }
    reading_.pop_back();
  }

  static SceneSource::Kind kind_of_reference(const GeoReference& r, const std::string& target, const std::string& where) {
    const std::string ext = extension(target);
    switch (r.kind) {
      case GeoReference::Include:
        return SceneSource::Script;  // gmsh parses an Include as a script, whatever its name
      case GeoReference::List:
        return SceneSource::List;
      case GeoReference::Shape:
        if (ext == ".step" || ext == ".stp" || ext == ".brep") return SceneSource::Shape;
        break;
      case GeoReference::Merge:
        if (ext == ".geo") return SceneSource::Script;
        if (ext == ".msh") return SceneSource::Mesh;
        if (ext == ".step" || ext == ".stp" || ext == ".brep") return SceneSource::Shape;
        break;
    }
    throw InputError(where + (ext.empty() ? std::string("a file without an extension") : "the extension '" + ext + "'") +
                     ", which gmsh reads by a reader thinlayer cannot check (a scene reads .geo and .msh files, and "
                     ".step, .stp or .brep shapes; the extension as written, in lower case)");
  }

  static void check_shape(const std::string& staged, const std::string& path, const std::string& bytes) {
    const std::string head = bytes.substr(0, 256);
    if (extension(staged) == ".brep" ? head.find("CASCADE Topology") == std::string::npos : head.rfind("ISO-10303-21", 0) != 0)
      throw InputError(at_line(path, 1) + (extension(staged) == ".brep"
                                              ? "not an OpenCASCADE shape (no 'CASCADE Topology' at its top)"
                                              : "not a STEP file (it does not begin with ISO-10303-21)"));
  }

  std::string chain() const {
    std::string c;
    for (const std::string& s : reading_) c += (c.empty() ? "" : " -> ") + s;
    return c;
  }

  std::string folder_, canonical_folder_;
  SceneSources out_;
  std::map<std::string, std::size_t> index_;             // staged name -> out_.files
  std::set<std::pair<std::string, SceneSource::Kind>> checked_;
  std::set<std::string> made_, scanned_;
  std::vector<std::string> reading_;  // the scripts being read, outermost first
  std::size_t script_bytes_ = 0;
};

}  // namespace

SceneSources read_scene_sources(const std::string& folder, const std::string& name, bool mesh, const std::string& where) {
  return SourceReader(folder).read(name, mesh, where);
}

}  // namespace thinlayer
