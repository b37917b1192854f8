#pragma once
// Values as bytes and back: put(w, x) appends x to a ByteWriter; get(r, x) reads it back in
// the same order from a ByteReader. Numbers travel as their exact bit patterns (the reader is
// the same binary on the same machine: another MPI rank, or the meshing child of
// core/mesh/meshing_child.h), so what is read back equals what was written, bit for bit.
// Numbers, enums, strings, vectors, arrays, maps and Eigen matrices here; each struct that
// travels has its own pair next to it (studies/parallel/result_bytes.h, core/mesh/mesh_bytes.h).
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

namespace thinlayer {

class ByteWriter {
 public:
  void raw(const void* data, std::size_t n) { bytes_.append(static_cast<const char*>(data), n); }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::string& bytes) : bytes_(bytes) {}
  void raw(void* data, std::size_t n) {
    if (n > bytes_.size() - at_) throw std::runtime_error("bytes: read past the end (a put/get mismatch)");
    std::memcpy(data, bytes_.data() + at_, n);
    at_ += n;
  }
  bool done() const { return at_ == bytes_.size(); }
  std::size_t remaining() const { return bytes_.size() - at_; }
  // A count read back: each of its items takes at least `item_bytes`, so a count beyond what is
  // left is a broken answer (a meshing child's, say), refused before anything is allocated.
  void check_count(std::uint64_t count, std::size_t item_bytes) const {
    if (item_bytes > 0 && count > remaining() / item_bytes)
      throw std::runtime_error("bytes: a count of " + std::to_string(count) + " beyond the bytes left (a put/get mismatch)");
  }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

// Numbers, enums and bools: their bytes.
template <class T>
  requires std::is_arithmetic_v<T> || std::is_enum_v<T>
void put(ByteWriter& w, T x) { w.raw(&x, sizeof x); }
template <class T>
  requires std::is_arithmetic_v<T> || std::is_enum_v<T>
void get(ByteReader& r, T& x) { r.raw(&x, sizeof x); }

void put(ByteWriter& w, const std::string& s);
void get(ByteReader& r, std::string& s);

template <class T>
void put(ByteWriter& w, const std::vector<T>& v) {
  put(w, static_cast<std::uint64_t>(v.size()));
  for (const T& x : v) put(w, x);
}
template <class T>
void get(ByteReader& r, std::vector<T>& v) {
  std::uint64_t n = 0;
  get(r, n);
  r.check_count(n, 1);
  v.assign(n, T{});
  for (T& x : v) get(r, x);
}

template <class T, std::size_t N>
void put(ByteWriter& w, const std::array<T, N>& a) {
  for (const T& x : a) put(w, x);
}
template <class T, std::size_t N>
void get(ByteReader& r, std::array<T, N>& a) {
  for (T& x : a) get(r, x);
}

template <class K, class V>
void put(ByteWriter& w, const std::map<K, V>& m) {
  put(w, static_cast<std::uint64_t>(m.size()));
  for (const auto& [k, v] : m) put(w, k), put(w, v);
}
template <class K, class V>
void get(ByteReader& r, std::map<K, V>& m) {
  std::uint64_t n = 0;
  get(r, n);
  r.check_count(n, 2);
  m.clear();
  for (std::uint64_t i = 0; i < n; ++i) {
    K k;
    V v;
    get(r, k), get(r, v);
    m.emplace(std::move(k), std::move(v));
  }
}

// Eigen matrices and vectors of any fixed or dynamic size: rows, cols, then the coefficients.
template <class M>
  requires std::is_base_of_v<Eigen::DenseBase<M>, M>
void put(ByteWriter& w, const M& m) {
  put(w, static_cast<std::int64_t>(m.rows())), put(w, static_cast<std::int64_t>(m.cols()));
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) put(w, m(i, j));
}
template <class M>
  requires std::is_base_of_v<Eigen::DenseBase<M>, M>
void get(ByteReader& r, M& m) {
  std::int64_t rows = 0, cols = 0;
  get(r, rows), get(r, cols);
  if (rows < 0 || cols < 0 || (M::RowsAtCompileTime != Eigen::Dynamic && rows != M::RowsAtCompileTime) ||
      (M::ColsAtCompileTime != Eigen::Dynamic && cols != M::ColsAtCompileTime))
    throw std::runtime_error("bytes: a matrix of the wrong size (a put/get mismatch)");
  r.check_count(static_cast<std::uint64_t>(rows), 1);
  if (rows > 0) r.check_count(static_cast<std::uint64_t>(cols), static_cast<std::size_t>(rows) * sizeof(typename M::Scalar));
  m.resize(rows, cols);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) get(r, m(i, j));
}

}  // namespace thinlayer
