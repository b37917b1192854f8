#include "core/io/h5_reader.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

#include <hdf5.h>

#include "core/io/h5_common.h"

namespace thinlayer {
namespace {

using h5::at;
using h5::check;
using h5::Handle;

// HDF5 resolves relative paths from the root, except "", which it rejects.
const char* object_name(const std::string& path) { return path.empty() ? "/" : path.c_str(); }

void require_class(hid_t type, std::initializer_list<H5T_class_t> accepted,
                   const std::string& what, const std::string& expected) {
  const H5T_class_t type_class = H5Tget_class(type);
  if (std::find(accepted.begin(), accepted.end(), type_class) == accepted.end())
    throw std::runtime_error(what + " is not " + expected);
}

struct OpenDataset {
  Handle dataset;
  Handle type;
  std::vector<std::size_t> shape;
  std::size_t size;  // number of values
};

OpenDataset open_dataset(hid_t file, const std::string& path, const std::string& file_name) {
  const std::string what = "dataset " + at(path, file_name);
  Handle dataset(check(H5Dopen2(file, object_name(path), H5P_DEFAULT), "cannot open " + what),
                 H5Dclose);
  Handle type(check(H5Dget_type(dataset.get()), "cannot read " + what), H5Tclose);
  Handle space(check(H5Dget_space(dataset.get()), "cannot read " + what), H5Sclose);
  const int rank = check(H5Sget_simple_extent_ndims(space.get()), "cannot read " + what);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check(H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr), "cannot read " + what);
  const hssize_t size = check(H5Sget_simple_extent_npoints(space.get()), "cannot read " + what);
  return {std::move(dataset), std::move(type), {dims.begin(), dims.end()},
          static_cast<std::size_t>(size)};
}

// A numeric dataset, converted by HDF5 to `native` (T's type) if its class is one of `accepted`.
template <typename T>
std::vector<T> read_numbers(hid_t file, const std::string& path, const std::string& file_name, hid_t native,
                            std::initializer_list<H5T_class_t> accepted, const std::string& expected,
                            std::vector<std::size_t>* shape) {
  const std::string what = "dataset " + at(path, file_name);
  OpenDataset d = open_dataset(file, path, file_name);
  require_class(d.type.get(), accepted, what, expected);
  std::vector<T> values(d.size);
  if (!values.empty())
    check(H5Dread(d.dataset.get(), native, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "cannot read " + what);
  if (shape != nullptr) *shape = d.shape;
  return values;
}

struct OpenAttr {
  Handle attr;
  Handle type;
};

OpenAttr open_scalar_attr(hid_t file, const std::string& path, const std::string& name,
                          const std::string& file_name) {
  const std::string what = "attribute '" + name + "' on " + at(path, file_name);
  Handle object(check(H5Oopen(file, object_name(path), H5P_DEFAULT),
                      "cannot open " + at(path, file_name)),
                H5Oclose);
  Handle attr(check(H5Aopen(object.get(), name.c_str(), H5P_DEFAULT), "cannot open " + what),
              H5Aclose);
  Handle space(check(H5Aget_space(attr.get()), "cannot read " + what), H5Sclose);
  if (H5Sget_simple_extent_npoints(space.get()) != 1)
    throw std::runtime_error(what + " is not a single value");
  Handle type(check(H5Aget_type(attr.get()), "cannot read " + what), H5Tclose);
  return {std::move(attr), std::move(type)};
}

// Reads `count` strings of string type `type` through `read(buffer)`. Variable-length
// strings arrive as char pointers allocated by HDF5, fixed-length ones as NUL-padded
// blocks of H5Tget_size bytes each.
template <typename Read>
std::vector<std::string> read_string_values(hid_t type, std::size_t count, Read read) {
  std::vector<std::string> values;
  values.reserve(count);
  if (H5Tis_variable_str(type) > 0) {
    std::vector<char*> buffer(count, nullptr);
    read(buffer.data());
    for (char* value : buffer) {
      values.emplace_back(value != nullptr ? value : "");
      H5free_memory(value);
    }
  } else {
    const std::size_t size = H5Tget_size(type);
    std::vector<char> buffer(count * size);
    read(buffer.data());
    for (std::size_t i = 0; i < count; ++i) {
      const char* begin = buffer.data() + i * size;
      values.emplace_back(begin, std::find(begin, begin + size, '\0'));
    }
  }
  return values;
}

}  // namespace

H5Reader::H5Reader(const std::string& path) : path_(path) {
  h5::start_hdf5();
  // Opening the file ourselves first gets the system's reason (missing, no permission) for
  // the message; HDF5 would bury it in its error stack.
  const int fd = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("cannot read '" + path_ + "': " + std::strerror(errno));
  ::close(fd);
  if (H5Fis_hdf5(path_.c_str()) <= 0)
    throw std::runtime_error("cannot read '" + path_ + "': not an HDF5 file");
  file_ = check(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                "cannot read '" + path_ + "'");
}

H5Reader::~H5Reader() { H5Fclose(file_); }

bool H5Reader::exists(const std::string& path) const {
  // H5Lexists fails, rather than answering false, when a parent is missing; so go down one
  // link at a time.
  std::string prefix;
  std::size_t start = 0;
  while (start < path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string::npos) end = path.size();
    if (end > start) {
      prefix.append("/").append(path, start, end - start);
      if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    }
    start = end + 1;
  }
  return true;
}

std::vector<std::string> H5Reader::children(const std::string& group_path) const {
  const std::string what = "group " + at(group_path, path_);
  Handle group(check(H5Gopen2(file_, object_name(group_path), H5P_DEFAULT), "cannot open " + what),
               H5Gclose);
  std::vector<std::string> names;
  // A generic lambda converts to whichever link-info callback type this HDF5 version has.
  auto collect = [](hid_t, const char* name, const auto*, void* out) -> herr_t {
    try {
      static_cast<std::vector<std::string>*>(out)->push_back(name);
      return 0;
    } catch (...) {
      return -1;  // an exception must not unwind through HDF5's C frames
    }
  };
  check(H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names),
        "cannot list " + what);
  std::sort(names.begin(), names.end());
  return names;
}

double H5Reader::attr_double(const std::string& path, const std::string& name) const {
  const std::string what = "attribute '" + name + "' on " + at(path, path_);
  OpenAttr a = open_scalar_attr(file_, path, name, path_);
  require_class(a.type.get(), {H5T_FLOAT, H5T_INTEGER}, what, "a number");
  double value = 0.0;
  check(H5Aread(a.attr.get(), H5T_NATIVE_DOUBLE, &value), "cannot read " + what);
  return value;
}

long long H5Reader::attr_int(const std::string& path, const std::string& name) const {
  const std::string what = "attribute '" + name + "' on " + at(path, path_);
  OpenAttr a = open_scalar_attr(file_, path, name, path_);
  require_class(a.type.get(), {H5T_INTEGER}, what, "an integer");
  long long value = 0;
  check(H5Aread(a.attr.get(), H5T_NATIVE_LLONG, &value), "cannot read " + what);
  return value;
}

std::string H5Reader::attr_string(const std::string& path, const std::string& name) const {
  const std::string what = "attribute '" + name + "' on " + at(path, path_);
  OpenAttr a = open_scalar_attr(file_, path, name, path_);
  require_class(a.type.get(), {H5T_STRING}, what, "a string");
  auto read = [&](void* buffer) {
    check(H5Aread(a.attr.get(), a.type.get(), buffer), "cannot read " + what);
  };
  return read_string_values(a.type.get(), 1, read).front();
}

std::vector<std::string> H5Reader::attr_strings(const std::string& path, const std::string& name) const {
  const std::string what = "attribute '" + name + "' on " + at(path, path_);
  Handle object(check(H5Oopen(file_, object_name(path), H5P_DEFAULT), "cannot open " + at(path, path_)), H5Oclose);
  Handle attr(check(H5Aopen(object.get(), name.c_str(), H5P_DEFAULT), "cannot open " + what), H5Aclose);
  Handle space(check(H5Aget_space(attr.get()), "cannot read " + what), H5Sclose);
  const hssize_t count = check(H5Sget_simple_extent_npoints(space.get()), "cannot read " + what);
  Handle type(check(H5Aget_type(attr.get()), "cannot read " + what), H5Tclose);
  require_class(type.get(), {H5T_STRING}, what, "a string");
  if (count == 0) return {};
  auto read = [&](void* buffer) { check(H5Aread(attr.get(), type.get(), buffer), "cannot read " + what); };
  return read_string_values(type.get(), static_cast<std::size_t>(count), read);
}

std::vector<double> H5Reader::read_doubles(const std::string& path,
                                           std::vector<std::size_t>* shape) const {
  return read_numbers<double>(file_, path, path_, H5T_NATIVE_DOUBLE, {H5T_FLOAT, H5T_INTEGER}, "numeric", shape);
}

std::vector<long long> H5Reader::read_ints(const std::string& path,
                                           std::vector<std::size_t>* shape) const {
  return read_numbers<long long>(file_, path, path_, H5T_NATIVE_LLONG, {H5T_INTEGER}, "an integer dataset", shape);
}

std::vector<std::string> H5Reader::read_strings(const std::string& path,
                                                std::vector<std::size_t>* shape) const {
  const std::string what = "dataset " + at(path, path_);
  OpenDataset d = open_dataset(file_, path, path_);
  require_class(d.type.get(), {H5T_STRING}, what, "a string dataset");
  auto read = [&](void* buffer) {
    if (d.size > 0)
      check(H5Dread(d.dataset.get(), d.type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer),
            "cannot read " + what);
  };
  std::vector<std::string> values = read_string_values(d.type.get(), d.size, read);
  if (shape != nullptr) *shape = d.shape;
  return values;
}

}  // namespace thinlayer
