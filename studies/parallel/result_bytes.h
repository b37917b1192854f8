#pragma once
// Scene results as bytes, so that a scene solved on one MPI rank can be handed to the others
// (studies/parallel/scene_batch.h). Numbers travel as their exact bit patterns (all ranks run the same
// binary on the same kind of machine), so a result read back equals the one written, bit for
// bit: that is what makes a spread study's file identical to a one-process run's.
//
// put(w, x) appends x; get(r, x) reads it back in the same order. Every type a study hands
// over has one overload pair here. A field added to one of these structs must be added to its
// pair too, or a spread study's file silently lacks it (tests/test_scene_batch.cpp round-trips
// them; the CTest mpi_two_ranks_convergence compares the files).
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "core/io/scene_record.h"
#include "core/mesh/layer_band.h"
#include "core/solvers/solve_report.h"
#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "cases/layer_scene.h"

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
    if (n > bytes_.size() - at_) throw std::runtime_error("result bytes: read past the end (a put/get mismatch)");
    std::memcpy(data, bytes_.data() + at_, n);
    at_ += n;
  }
  bool done() const { return at_ == bytes_.size(); }

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
  v.assign(n, T{});
  for (T& x : v) get(r, x);
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
  m.resize(rows, cols);
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) get(r, m(i, j));
}

void put(ByteWriter& w, const StatusCount& c);
void get(ByteReader& r, StatusCount& c);
void put(ByteWriter& w, const LayerCounts& c);
void get(ByteReader& r, LayerCounts& c);
void put(ByteWriter& w, const MeshQuality& q);
void get(ByteReader& r, MeshQuality& q);
void put(ByteWriter& w, const SolveReport& s);
void get(ByteReader& r, SolveReport& s);
void put(ByteWriter& w, const InterfaceFields& f);
void get(ByteReader& r, InterfaceFields& f);
void put(ByteWriter& w, const SceneRecord& s);
void get(ByteReader& r, SceneRecord& s);
void put(ByteWriter& w, const BarScene& s);
void get(ByteReader& r, BarScene& s);
void put(ByteWriter& w, const BarLayerScene& s);
void get(ByteReader& r, BarLayerScene& s);
void put(ByteWriter& w, const DovetailScene& s);
void get(ByteReader& r, DovetailScene& s);

}  // namespace thinlayer
