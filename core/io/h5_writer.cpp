#include "core/io/h5_writer.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <type_traits>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include <hdf5.h>

#include "core/io/h5_common.h"
#include "core/io/output_ownership.h"
#include "core/io/output_target.h"

namespace thinlayer {
namespace {

using h5::at;
using h5::Handle;

// Every failure of a write is an output that cannot be written (exit status 2, SPEC §4).
template <typename Id>
Id check(Id id, const std::string& what) {
  return h5::check<OutputError>(id, what);
}

// "/a//b/" -> {"a", "b"}; "/" -> {}.
std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    if (end > start) parts.push_back(path.substr(start, end - start));
    start = end + 1;
  }
  return parts;
}

// Opens the object at `path`; missing groups along the way, the last one included, are
// created. Walking one link at a time is what lets "/a/b" be created when "/a" is missing.
Handle open_or_create(hid_t file, const std::string& path, const std::string& file_name) {
  Handle object(check(H5Oopen(file, "/", H5P_DEFAULT), "cannot open " + at("/", file_name)),
                H5Oclose);
  std::string prefix;
  for (const std::string& name : split_path(path)) {
    if (H5Iget_type(object.get()) != H5I_GROUP)
      throw OutputError(at(prefix, file_name) + " exists and is not a group");
    prefix += "/" + name;
    const htri_t found = check(H5Lexists(object.get(), name.c_str(), H5P_DEFAULT),
                               "cannot look up " + at(prefix, file_name));
    const hid_t next =
        found > 0 ? H5Oopen(object.get(), name.c_str(), H5P_DEFAULT)
                  : H5Gcreate2(object.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    object = Handle(check(next, "cannot open or create group " + at(prefix, file_name)),
                    H5Oclose);
  }
  return object;
}

Handle open_or_create_group(hid_t file, const std::string& path, const std::string& file_name) {
  Handle group = open_or_create(file, path, file_name);
  if (H5Iget_type(group.get()) != H5I_GROUP)
    throw OutputError(at(path, file_name) + " exists and is not a group");
  return group;
}

Handle utf8_string_type() {
  Handle type(check(H5Tcopy(H5T_C_S1), "cannot create a string type"), H5Tclose);
  check(H5Tset_size(type.get(), H5T_VARIABLE), "cannot create a string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "cannot create a string type");
  return type;
}

// C strings end at the first NUL, so HDF5 would silently truncate such a string.
void require_no_nul(const std::string& value, const std::string& what) {
  if (value.find('\0') != std::string::npos)
    throw OutputError(what + ": string contains a NUL character");
}

// Writes a new rank-1 or rank-2 dataset from contiguous row-major `data`.
void write_dataset(hid_t file, const std::string& path, const std::string& file_name,
                   const std::vector<hsize_t>& dims, hid_t file_type, hid_t mem_type,
                   const void* data) {
  std::vector<std::string> parts = split_path(path);
  if (parts.empty()) throw OutputError("invalid dataset path " + at(path, file_name));
  const std::string name = parts.back();
  parts.pop_back();
  std::string parent_path;
  for (const std::string& part : parts) parent_path += "/" + part;
  const std::string what = "dataset " + at(path, file_name);

  Handle parent = open_or_create_group(file, parent_path, file_name);
  if (check(H5Lexists(parent.get(), name.c_str(), H5P_DEFAULT), "cannot look up " + what) > 0)
    throw OutputError(what + " already exists");
  Handle space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr),
                     "cannot create dataspace for " + what),
               H5Sclose);
  Handle dataset(check(H5Dcreate2(parent.get(), name.c_str(), file_type, space.get(),
                                  H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                       "cannot create " + what),
                 H5Dclose);
  // An empty dataset has nothing to write, and `data` may then be null.
  if (H5Sget_simple_extent_npoints(space.get()) > 0)
    check(H5Dwrite(dataset.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "cannot write " + what);
}

// A scalar attribute (`dims` empty) or a 1-D one of dims[0] values.
void write_attr(hid_t file, const std::string& object_path, const std::string& name,
                const std::string& file_name, hid_t file_type, hid_t mem_type,
                const void* value, const std::vector<hsize_t>& dims = {}) {
  const std::string what = "attribute '" + name + "' on " + at(object_path, file_name);
  Handle object = open_or_create(file, object_path, file_name);
  if (check(H5Aexists(object.get(), name.c_str()), "cannot look up " + what) > 0)
    throw OutputError(what + " already exists");
  Handle space(check(dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims.data(), nullptr),
                     "cannot create dataspace for " + what),
               H5Sclose);
  Handle attr(check(H5Acreate2(object.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT,
                               H5P_DEFAULT),
                    "cannot create " + what),
              H5Aclose);
  if (dims.empty() || dims[0] > 0) check(H5Awrite(attr.get(), mem_type, value), "cannot write " + what);
}

// The user block before HDF5's superblock: the smallest HDF5 allows.
constexpr hsize_t user_block_bytes = 512;

hid_t create_file(const std::string& tmp_path, const std::string& file_name) {
  const std::string what = "cannot create HDF5 file for '" + file_name + "'";
  Handle access(check(H5Pcreate(H5P_FILE_ACCESS), what), H5Pclose);
  // By default H5Fclose "succeeds" while an object is still open and flushes the file only
  // when that object closes, i.e. after the rename. The "semi" degree makes it an error.
  check(H5Pset_fclose_degree(access.get(), H5F_CLOSE_SEMI), what);
  Handle creation(check(H5Pcreate(H5P_FILE_CREATE), what), H5Pclose);
  check(H5Pset_userblock(creation.get(), user_block_bytes), what);
  return check(H5Fcreate(tmp_path.c_str(), H5F_ACC_TRUNC, creation.get(), access.get()), what);
}

// The marker in the user block (HDF5 leaves it as zeros), then the whole file to disk: without
// the fsync, a crash soon after the rename can leave an empty target on some file systems.
void mark_and_flush(const std::string& tmp_path, const std::string& file_name) {
  std::string block = std::string(results_marker) +
                      "(an HDF5 file, its superblock at byte 512: thinlayer marks its results here)\n";
  block.resize(user_block_bytes, '\0');
  const int fd = ::open(tmp_path.c_str(), O_WRONLY | O_CLOEXEC);
  const bool ok = fd >= 0 && ::pwrite(fd, block.data(), block.size(), 0) == static_cast<ssize_t>(block.size()) &&
                  ::fsync(fd) == 0;
  const int error = errno;
  if (fd >= 0) ::close(fd);
  if (!ok) throw OutputError("cannot write '" + file_name + "': " + std::strerror(error));
}

}  // namespace

H5Writer::H5Writer(const std::string& path)
    : path_(path), target_(resolve_output_target(path)), tmp_path_(temporary_name_beside(target_)) {
  h5::start_hdf5();
  // Creating the file ourselves first gets the system's reason (missing directory, no
  // permission) for the message; HDF5 would bury it in its error stack.
  register_temporary(tmp_path_);
  const int fd = ::open(tmp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int error = errno;
    unregister_temporary(tmp_path_);
    throw OutputError("cannot write '" + path_ + "': " + std::strerror(error));
  }
  ::close(fd);
  try {
    file_ = create_file(tmp_path_, path_);
  } catch (const std::exception& e) {
    std::error_code ec;
    std::filesystem::remove(tmp_path_, ec);
    unregister_temporary(tmp_path_);
    throw OutputError(e.what());
  }
}

H5Writer::~H5Writer() {
  if (file_ >= 0) H5Fclose(file_);
  std::error_code ec;
  if (!committed_) std::filesystem::remove(tmp_path_, ec);
  unregister_temporary(tmp_path_);
  if (!committed_)
    for (const std::string& folder : folders_) ::rmdir(folder.c_str());  // only if empty: never the user's files
  unregister_removals(folder_removal_);
}

void H5Writer::remove_if_abandoned(std::vector<std::string> folders) {
  std::vector<Removal> removals;
  for (const std::string& folder : folders) removals.push_back({Removal::Folder, folder});
  unregister_removals(folder_removal_);
  folder_removal_ = register_removals(removals);
  folders_ = std::move(folders);
}

void H5Writer::commit() {
  const hid_t file_id = file();
  file_ = -1;  // whatever happens next, the destructor must not close it again
  check(H5Fclose(file_id), "cannot close '" + path_ + "'");
  mark_and_flush(tmp_path_, path_);
  if (rules_) check_replaceable(path_, OutputKind::Results, rules_->inputs, rules_->force);
  std::error_code ec;
  // Onto the end of any chain of symbolic links: the links stay, the file they name is replaced.
  std::filesystem::rename(tmp_path_, target_, ec);
  if (ec) throw OutputError("cannot write '" + path_ + "': " + ec.message());
  committed_ = true;
  unregister_removals(folder_removal_);  // the folders now hold the file
  folder_removal_ = -1;
}

void H5Writer::replace_only_under(OutputRules rules) { rules_ = std::move(rules); }

void H5Writer::write_beside(const std::string& name, OutputKind kind, const std::string& text) const {
  const std::string folder = std::filesystem::path(path_).parent_path().string();
  const std::string path = (folder.empty() ? std::string(".") : folder) + "/" + name;
  if (!rules_) return write_text_atomically(path, text);
  // Written only while this file itself may still be: a results file refused at its commit then
  // leaves no new file beside it.
  check_replaceable(path_, OutputKind::Results, rules_->inputs, rules_->force);
  write_output_text(path, kind, *rules_, text);
}

std::int64_t H5Writer::file() const {
  if (file_ < 0) throw OutputError("'" + path_ + "' is already committed or closed");
  return file_;
}

void H5Writer::group(const std::string& path) { open_or_create_group(file(), path, path_); }

void H5Writer::attr(const std::string& object_path, const std::string& name, double value) {
  write_attr(file(), object_path, name, path_, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void H5Writer::attr_int64(const std::string& object_path, const std::string& name,
                          long long value) {
  write_attr(file(), object_path, name, path_, H5T_STD_I64LE, H5T_NATIVE_LLONG, &value);
}

void H5Writer::attr(const std::string& object_path, const std::string& name,
                    const std::string& value) {
  require_no_nul(value, "attribute '" + name + "' on " + at(object_path, path_));
  Handle type = utf8_string_type();
  const char* c_string = value.c_str();  // a variable-length string is passed by pointer
  write_attr(file(), object_path, name, path_, type.get(), type.get(), &c_string);
}

void H5Writer::attr(const std::string& object_path, const std::string& name,
                    const std::vector<std::string>& values) {
  std::vector<const char*> c_strings;
  for (const std::string& value : values) {
    require_no_nul(value, "attribute '" + name + "' on " + at(object_path, path_));
    c_strings.push_back(value.c_str());
  }
  Handle type = utf8_string_type();
  write_attr(file(), object_path, name, path_, type.get(), type.get(), c_strings.data(), {values.size()});
}

void H5Writer::dataset(const std::string& path, const double* data, std::size_t rows,
                       std::size_t cols) {
  write_dataset(file(), path, path_, {rows, cols}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data);
}

void H5Writer::dataset(const std::string& path, const int* data, std::size_t rows,
                       std::size_t cols) {
  write_dataset(file(), path, path_, {rows, cols}, H5T_STD_I32LE, H5T_NATIVE_INT, data);
}

// A Ref may view a block of a wider matrix, whose rows are not adjacent in memory; HDF5
// needs them adjacent, so such a block is copied first.
void H5Writer::dataset(const std::string& path, const Eigen::Ref<const RowMatrixXd>& values) {
  if (values.outerStride() != values.cols()) {
    const RowMatrixXd copy = values;
    return dataset(path, copy.data(), copy.rows(), copy.cols());
  }
  dataset(path, values.data(), values.rows(), values.cols());
}

void H5Writer::dataset(const std::string& path, const Eigen::Ref<const RowMatrixXi>& values) {
  if (values.outerStride() != values.cols()) {
    const RowMatrixXi copy = values;
    return dataset(path, copy.data(), copy.rows(), copy.cols());
  }
  dataset(path, values.data(), values.rows(), values.cols());
}

void H5Writer::dataset(const std::string& path, const std::vector<double>& values) {
  write_dataset(file(), path, path_, {values.size()}, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                values.data());
}

void H5Writer::dataset(const std::string& path, const std::vector<int>& values) {
  write_dataset(file(), path, path_, {values.size()}, H5T_STD_I32LE, H5T_NATIVE_INT,
                values.data());
}

void H5Writer::dataset(const std::string& path, const std::vector<std::string>& values) {
  std::vector<const char*> c_strings;
  c_strings.reserve(values.size());
  for (const std::string& value : values) {
    require_no_nul(value, "dataset " + at(path, path_));
    c_strings.push_back(value.c_str());
  }
  Handle type = utf8_string_type();
  write_dataset(file(), path, path_, {values.size()}, type.get(), type.get(), c_strings.data());
}

}  // namespace thinlayer
