#pragma once
// Writes one HDF5 result file, all or nothing.
//
// The file's first 512 bytes are an HDF5 user block holding the marker "thinlayer-results\n"
// (core/io/output_ownership.h): whether an existing file is thinlayer's is read from those raw
// bytes, never by parsing it with HDF5 (h5py and HDF5 read the file as usual: the superblock
// follows the block).
//
// The data go to a temporary file next to the target (`<target>.tmp.<pid>.<n>`); commit()
// closes it and renames it onto the target, which is atomic on POSIX file systems. A writer
// destroyed without commit() (for instance while an exception unwinds) deletes the temporary
// file, so a reader never sees a half-written result; so does SIGINT/SIGTERM once
// install_signal_cleanup() is set (core/io/output_target.h). A symbolic link at the path is
// followed (its target is replaced, the link stays); a path that is a directory, a FIFO or a
// device is refused.
//
// Object paths are absolute or relative to the root ("/" is the root, "a/b" means "/a/b").
// Missing parent groups are created. Writing an object or attribute that already exists
// throws: a result file is written once, and a duplicate name is a bug in the caller.
//
// Stored types: doubles as IEEE float64, int datasets as int32, integer attributes as int64,
// strings as variable-length UTF-8 (h5py returns attributes as `str`; string datasets as
// `bytes` unless read through `.asstr()`). NaN and Inf are written as given.
//
// Every failure throws OutputError (an output that cannot be written: exit status 2) naming
// the file and the object, in one line; a full disk found at the close included. HDF5's own
// error printing is off (h5_common.h: start_hdf5).
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "core/io/output_ownership.h"
#include "core/io/output_target.h"

namespace thinlayer {

class H5Writer {
 public:
  using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  using RowMatrixXi = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  // Throws OutputError, creating nothing, if the target's directory is missing or not
  // writable, or the target is not a regular file.
  explicit H5Writer(const std::string& path);
  ~H5Writer();
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;

  // Closes the file and moves it onto the target path. No other call is allowed afterwards.
  // Under replace_only_under, the target is judged by those rules first (OutputError, the
  // target untouched, the file abandoned).
  void commit();
  // The rules the commit and write_beside judge their targets by at the moment they write
  // (core/io/output_ownership.h: a file saved at an output's path during a run is not replaced).
  void replace_only_under(OutputRules rules);
  // A text file of `kind` beside this one (its folder), written atomically under the same rules.
  void write_beside(const std::string& name, OutputKind kind, const std::string& text) const;
  // Folders made for this file (deepest first): removed, if empty, when the file is abandoned,
  // so that a failed run leaves no empty output folder behind (SPEC §4); on a signal too (the
  // handler of core/io/output_target.h removes them, if empty, until the commit).
  void remove_if_abandoned(std::vector<std::string> folders);
  const std::string& path() const { return path_; }

  void group(const std::string& path);

  // Scalar attributes on the group or dataset at object_path (a missing group is created).
  void attr(const std::string& object_path, const std::string& name, double value);
  void attr(const std::string& object_path, const std::string& name, const std::string& value);
  // A list of names as a 1-D string attribute (h5py: an array of str), never joined by commas:
  // a name may hold one.
  void attr(const std::string& object_path, const std::string& name, const std::vector<std::string>& values);
  template <std::integral T>
  void attr(const std::string& object_path, const std::string& name, T value) {
    if constexpr (std::is_unsigned_v<T> && sizeof(T) >= sizeof(long long)) {
      if (value > static_cast<T>(std::numeric_limits<long long>::max()))
        throw OutputError("attribute '" + name + "' on '" + object_path + "' in '" +
                                 path_ + "' does not fit in int64");
    }
    attr_int64(object_path, name, static_cast<long long>(value));
  }

  // 2-D datasets: a rows x cols matrix appears in h5py with shape (rows, cols).
  void dataset(const std::string& path, const Eigen::Ref<const RowMatrixXd>& values);
  void dataset(const std::string& path, const Eigen::Ref<const RowMatrixXi>& values);
  void dataset(const std::string& path, const double* data, std::size_t rows, std::size_t cols);
  void dataset(const std::string& path, const int* data, std::size_t rows, std::size_t cols);
  // 1-D datasets.
  void dataset(const std::string& path, const std::vector<double>& values);
  void dataset(const std::string& path, const std::vector<int>& values);
  void dataset(const std::string& path, const std::vector<std::string>& values);
  // A 1-D dataset with its units ("" for none) and what it holds: how the studies describe a column.
  template <typename T>
  void described_dataset(const std::string& path, const std::vector<T>& values, const std::string& units,
                         const std::string& description) {
    dataset(path, values);
    if (!units.empty()) attr(path, "units", units);
    attr(path, "description", description);
  }

 private:
  void attr_int64(const std::string& object_path, const std::string& name, long long value);
  std::int64_t file() const;  // the open file's id; throws after commit()

  std::string path_;
  std::string target_;  // path_ with its symbolic links followed
  std::string tmp_path_;
  std::int64_t file_ = -1;  // hid_t, kept as its underlying type so <hdf5.h> stays private
  bool committed_ = false;
  std::vector<std::string> folders_;
  std::optional<OutputRules> rules_;
  int folder_removal_ = -1;  // folders_ in the signal handler's table
};

}  // namespace thinlayer
