#include "studies/tools/scene_store.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "core/io/bytes.h"
#include "core/io/output_target.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {

namespace {

const std::string marker = "thinlayer-scene-store 2\n";
const std::string marker_name = "thinlayer-scene-store ";  // any layout's
// The largest store file read back: a scene of the finest mesh is about 5 MB.
constexpr std::uintmax_t max_file_bytes = 1ULL << 30;

std::string checksum_bytes(const std::string& bytes) {
  const std::uint64_t sum = definition_hash(bytes);
  return std::string(reinterpret_cast<const char*>(&sum), sizeof sum);
}

}  // namespace

std::string SceneStore::path_of(const std::string& name) const {
  if (name.empty()) throw std::invalid_argument("scene store: an empty scene name");
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_'))
      throw std::invalid_argument("scene store: '" + name + "' is not a plain file name");
  return (std::filesystem::path(folder_) / (name + ".scene")).string();
}

std::optional<StoredScene> SceneStore::read(const std::string& name, std::string* damaged) const {
  const std::string path = path_of(name);
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) return std::nullopt;
  if (!std::filesystem::is_regular_file(status))
    throw ForeignStoreFile(path + ": in the scene store and not a regular file; move it away");
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  std::string bytes;
  if (!error && size <= max_file_bytes && in) bytes.assign(std::istreambuf_iterator<char>(in), {});
  if (bytes.compare(0, marker.size(), marker) != 0) {
    if (bytes.size() < marker.size() && marker.compare(0, bytes.size(), bytes) == 0 && in) {
      if (damaged) *damaged = path + ": cut short";
      return std::nullopt;
    }
    if (bytes.compare(0, marker_name.size(), marker_name) == 0) {
      if (damaged) *damaged = path + ": written in another layout of the store";
      return std::nullopt;
    }
    throw ForeignStoreFile(path + ": in the scene store and not a file thinlayer wrote there; move it away");
  }
  const std::size_t sum = sizeof(std::uint64_t);
  if (bytes.size() < marker.size() + sum ||
      bytes.compare(bytes.size() - sum, sum, checksum_bytes(bytes.substr(0, bytes.size() - sum))) != 0) {
    if (damaged) *damaged = path + ": its checksum does not match (cut short or altered)";
    return std::nullopt;
  }
  const std::string body = bytes.substr(marker.size(), bytes.size() - sum - marker.size());
  StoredScene s;
  try {
    ByteReader r(body);
    get(r, s.definition), get(r, s.solver), get(r, s.ending), get(r, s.message), get(r, s.stop), get(r, s.seconds), get(r, s.cpu_seconds), get(r, s.scene);
    if (!r.done()) throw std::runtime_error("bytes left over");
  } catch (const std::exception& e) {
    if (damaged) *damaged = path + ": unreadable (" + e.what() + ")";
    return std::nullopt;
  }
  return s;
}

void SceneStore::write(const std::string& name, const StoredScene& s) const {
  const std::string path = path_of(name);
  std::error_code error;
  std::filesystem::create_directories(folder_, error);  // several ranks may race to make it
  if (!std::filesystem::is_directory(folder_))
    throw OutputError(folder_ + ": cannot make the scene store's folder" + (error ? " (" + error.message() + ")" : ""));
  ByteWriter w;
  put(w, s.definition), put(w, s.solver), put(w, s.ending), put(w, s.message), put(w, s.stop), put(w, s.seconds), put(w, s.cpu_seconds), put(w, s.scene);
  std::string bytes = marker + w.take();
  bytes += checksum_bytes(bytes);
  write_text_atomically(path, bytes);
}

}  // namespace thinlayer
