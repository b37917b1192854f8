#pragma once
// Small helpers shared by the HDF5 writer and reader (private to core/io; includes <hdf5.h>).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include <hdf5.h>

namespace thinlayer::h5 {

static_assert(std::is_same_v<hid_t, std::int64_t>, "the HDF5 wrappers store hid_t as std::int64_t");

// Owns one HDF5 identifier and releases it with the matching H5?close function.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close) : id_(id), close_(close) {}
  Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), close_(other.close_) {}
  Handle& operator=(Handle&& other) noexcept {
    std::swap(id_, other.id_);
    std::swap(close_, other.close_);
    return *this;
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  hid_t get() const { return id_; }

 private:
  hid_t id_;
  Closer close_;
};

// Before the first HDF5 call of the process (H5Writer's and H5Reader's constructors): HDF5's
// own error printing off (a failure is our one-line message, not HDF5's stack on stderr), and
// no clean-up of HDF5 at exit. Why the latter: after a failed H5Fclose (a full disk) the file
// stays half-open, and the library's exit handler closing it again crashed in H5F__close_cb
// (exit 139). Every file thinlayer writes is closed or abandoned (its temporary removed)
// before exit, so the exit handler has nothing to do that the process's end does not.
inline void start_hdf5() {
  static const bool started = [] {
    H5dont_atexit();
    H5open();
    return true;
  }();
  (void)started;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // per thread where HDF5 is thread-safe
}

// With automatic printing off, the innermost entry of HDF5's error stack is the only place
// that says what actually went wrong (e.g. "object 'x' doesn't exist"). A system call's
// failure is told as HDF5's multi-line record ("file write failed: time = ..., errno = 28,
// error message = 'No space left on device', ..."): its error message is the reason.
inline std::string hdf5_reason() {
  std::string reason;
  auto innermost = [](unsigned n, const H5E_error2_t* error, void* out) -> herr_t {
    if (n == 0 && error->desc != nullptr) *static_cast<std::string*>(out) = error->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, &reason);
  const std::string system = "error message = '";
  if (const std::size_t at = reason.find(system); at != std::string::npos) {
    const std::size_t start = at + system.size();
    reason = reason.substr(0, reason.find(':')) + ": " + reason.substr(start, reason.find('\'', start) - start);
  }
  for (char& c : reason)
    if (c == '\n' || c == '\r') c = ' ';
  return reason;
}

// HDF5 reports failure as a negative id or status: thrown as an `Error` (the writer's are
// OutputError, core/io/output_target.h).
template <typename Error = std::runtime_error, typename Id>
Id check(Id id, const std::string& what) {
  if (id < 0) {
    const std::string reason = hdf5_reason();
    throw Error(what + (reason.empty() ? "" : ": " + reason));
  }
  return id;
}

// "'/a/b' in 'out.h5'", the object named in every error message.
inline std::string at(const std::string& object, const std::string& file_name) {
  return "'" + object + "' in '" + file_name + "'";
}

}  // namespace thinlayer::h5
