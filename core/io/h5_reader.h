#pragma once
// Reads HDF5 result files (those of H5Writer, or any other) back, read-only.
//
// Paths are absolute or relative to the root, as for H5Writer. Numbers are converted by
// HDF5 on reading: an integer dataset or attribute can be read as doubles, but a floating-
// point one is not silently truncated to an integer (that throws). Attributes may be on
// groups or datasets and must hold a single value.
//
// Every failure throws std::runtime_error naming the file and the object. HDF5's own error
// printing is turned off for the constructing thread (HDF5 keeps that setting per thread).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace thinlayer {

class H5Reader {
 public:
  // Throws if the file is missing, unreadable, or not an HDF5 file.
  explicit H5Reader(const std::string& path);
  ~H5Reader();
  H5Reader(const H5Reader&) = delete;
  H5Reader& operator=(const H5Reader&) = delete;

  const std::string& path() const { return path_; }

  // Whether a group or dataset exists at `path` ("/" always does).
  bool exists(const std::string& path) const;
  // Names of the groups and datasets directly inside a group, sorted.
  std::vector<std::string> children(const std::string& group_path) const;

  double attr_double(const std::string& path, const std::string& name) const;
  long long attr_int(const std::string& path, const std::string& name) const;
  std::string attr_string(const std::string& path, const std::string& name) const;
  // A string attribute of any shape, its values in row-major order.
  std::vector<std::string> attr_strings(const std::string& path, const std::string& name) const;

  // All values in row-major order; `shape`, if given, receives the dimensions (for an
  // N x 2 dataset, {N, 2}; empty for a scalar dataset).
  std::vector<double> read_doubles(const std::string& path,
                                   std::vector<std::size_t>* shape = nullptr) const;
  std::vector<long long> read_ints(const std::string& path,
                                   std::vector<std::size_t>* shape = nullptr) const;
  // Fixed- or variable-length strings, flattened in row-major order.
  std::vector<std::string> read_strings(const std::string& path,
                                        std::vector<std::size_t>* shape = nullptr) const;

 private:
  std::string path_;
  std::int64_t file_ = -1;  // hid_t, kept as its underlying type so <hdf5.h> stays private
};

}  // namespace thinlayer
