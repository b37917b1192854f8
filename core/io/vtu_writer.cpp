#include "core/io/vtu_writer.h"

#include "core/io/output_ownership.h"

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "core/io/output_target.h"

namespace thinlayer {
namespace {

constexpr int vtk_triangle = 5;
constexpr int vtk_quad = 9;

// The scene is checked and the whole text built before the file is touched, so a bad scene
// leaves nothing behind. std::runtime_error, not invalid_argument: a NaN comes from a failed
// solve rather than from the user's input (the CLI maps invalid_argument to "bad input").
[[noreturn]] void bad_scene(const std::string& path, const std::string& what) {
  throw std::runtime_error("cannot write VTU file '" + path + "': " + what);
}

[[noreturn]] void cannot_write(const std::string& path, int error) {
  throw OutputError("cannot write VTU file '" + path + "': " + std::strerror(error));
}

// Shortest text that reads back as the same double, whatever the locale.
std::string text_of(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::string finite_text(double value, const std::string& path, const std::string& what) {
  if (!std::isfinite(value)) bad_scene(path, what + " is " + (std::isnan(value) ? "NaN" : "infinite"));
  return text_of(value);
}

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// One <DataArray>; `tuples` > 0 adds NumberOfTuples, which FieldData arrays need.
std::string data_array(const std::string& type, const std::string& name, int components, const std::string& values,
                       int tuples = 0) {
  std::string xml = "<DataArray type=\"" + type + "\"";
  if (!name.empty()) xml += " Name=\"" + xml_escaped(name) + "\"";
  xml += " NumberOfComponents=\"" + std::to_string(components) + "\"";
  if (tuples > 0) xml += " NumberOfTuples=\"" + std::to_string(tuples) + "\"";
  return xml + " format=\"ascii\">\n" + values + "\n</DataArray>\n";
}

// VTK's ASCII form of a string: its bytes as numbers, ended by 0.
std::string vtk_string(const std::string& s) {
  std::string out;
  for (unsigned char c : s) out += std::to_string(c) + " ";
  return out + "0";
}

// An N×2 field as N lines "x y 0" (VTK points and vectors are 3-D).
std::string planar_vectors(const H5Writer::RowMatrixXd& v, const std::string& path, const std::string& what) {
  std::string out;
  for (Eigen::Index i = 0; i < v.rows(); ++i) {
    const std::string at = what + " of node " + std::to_string(i);
    out += finite_text(v(i, 0), path, at) + " " + finite_text(v(i, 1), path, at) + " 0\n";
  }
  return out;
}

std::string points(const SceneRecord& scene, const std::string& path) {
  return "<Points>\n" + data_array("Float64", "", 3, planar_vectors(scene.nodes, path, "position")) + "</Points>\n";
}

// The number of nodes of cell c: its non-negative entries, the rest being -1 (a mixed mesh
// pads its triangles to the table's 4 columns).
int cell_width(const SceneRecord& scene, Eigen::Index c, const std::string& path) {
  const std::string cell = "cell " + std::to_string(c);
  int width = 0;
  while (width < scene.cells.cols() && scene.cells(c, width) >= 0) ++width;
  for (Eigen::Index a = width; a < scene.cells.cols(); ++a)
    if (scene.cells(c, a) != -1) bad_scene(path, cell + " has a negative node index");
  if (width != 3 && width != 4) bad_scene(path, cell + " has " + std::to_string(width) + " nodes (expected 3 or 4)");
  for (int a = 0; a < width; ++a)
    if (scene.cells(c, a) >= scene.nodes.rows()) bad_scene(path, cell + " names a node beyond the last");
  return width;
}

std::string cells(const SceneRecord& scene, const std::string& path) {
  std::string connectivity, offsets, types;
  long long offset = 0;
  for (Eigen::Index c = 0; c < scene.cells.rows(); ++c) {
    const int width = cell_width(scene, c, path);
    for (int a = 0; a < width; ++a) connectivity += std::to_string(scene.cells(c, a)) + (a + 1 < width ? " " : "\n");
    offset += width;
    offsets += std::to_string(offset) + "\n";
    types += std::to_string(width == 4 ? vtk_quad : vtk_triangle) + "\n";
  }
  return "<Cells>\n" + data_array("Int64", "connectivity", 1, connectivity) +
         data_array("Int64", "offsets", 1, offsets) + data_array("UInt8", "types", 1, types) + "</Cells>\n";
}

// For each point of an interface, the bulk nodes at it: one per body it joins.
std::vector<std::vector<int>> nodes_at(const SceneRecord& scene, const InterfaceFields& f, const std::string& path) {
  const double size = (scene.nodes.colwise().maxCoeff() - scene.nodes.colwise().minCoeff()).norm();
  const double tolerance = 1e-9 * (size > 0 ? size : 1.0);  // round-off, far below any element (mm)
  std::vector<std::vector<int>> result(f.x.rows());
  for (Eigen::Index k = 0; k < f.x.rows(); ++k) {
    for (Eigen::Index n = 0; n < scene.nodes.rows(); ++n)
      if ((scene.nodes.row(n) - f.x.row(k)).norm() <= tolerance) result[k].push_back(static_cast<int>(n));
    if (result[k].empty())
      bad_scene(path, "point " + std::to_string(k) + " of interface '" + f.name + "' is on no node");
  }
  return result;
}

void check_sizes(const InterfaceFields& f, const std::string& path) {
  const Eigen::Index m = f.x.rows();
  const bool ok = f.x.cols() == 2 && f.normal.rows() == m && f.normal.cols() == 2 && f.length.size() == m &&
                  f.jump_N.size() == m && f.jump_T.size() == m && f.sigma_N.size() == m && f.sigma_T.size() == m &&
                  static_cast<Eigen::Index>(f.status.size()) == m;
  if (!ok) bad_scene(path, "the fields of interface '" + f.name + "' differ in size");
}

// A scalar per node: `value(k)` on the nodes of point k, `off` elsewhere.
template <typename Value>
std::string scalar_on_nodes(const std::vector<std::vector<int>>& at, Eigen::Index num_nodes, double off, Value value,
                            const std::string& path, const std::string& what) {
  std::vector<double> v(num_nodes, off);
  for (std::size_t k = 0; k < at.size(); ++k)
    for (int n : at[k]) v[n] = value(k);
  std::string out;
  for (Eigen::Index n = 0; n < num_nodes; ++n)
    out += finite_text(v[n], path, what + " at node " + std::to_string(n)) + "\n";
  return out;
}

std::string interface_arrays(const SceneRecord& scene, const InterfaceFields& f, const std::string& path) {
  check_sizes(f, path);
  const auto at = nodes_at(scene, f, path);
  const Eigen::Index n = scene.nodes.rows();
  auto scalar = [&](const std::string& type, const std::string& field, double off, auto value) {
    const std::string name = f.name + "_" + field;
    return data_array(type, name, 1, scalar_on_nodes(at, n, off, value, path, name));
  };
  H5Writer::RowMatrixXd normal = H5Writer::RowMatrixXd::Zero(n, 2);
  for (std::size_t k = 0; k < at.size(); ++k)
    for (int node : at[k]) normal.row(node) = f.normal.row(k);
  const std::string mask = "on_interface_" + f.name;
  return data_array("UInt8", mask, 1, scalar_on_nodes(at, n, 0, [](auto) { return 1.0; }, path, mask)) +
         scalar("Float64", "jump_N", 0, [&](auto k) { return f.jump_N[k]; }) +
         scalar("Float64", "jump_T", 0, [&](auto k) { return f.jump_T[k]; }) +
         scalar("Float64", "sigma_N", 0, [&](auto k) { return f.sigma_N[k]; }) +
         scalar("Float64", "sigma_T", 0, [&](auto k) { return f.sigma_T[k]; }) +
         scalar("Float64", "length", 0, [&](auto k) { return f.length[k]; }) +
         scalar("Int32", "status", -1, [&](auto k) { return f.status[k]; }) +
         data_array("Float64", f.name + "_normal", 3, planar_vectors(normal, path, f.name + "_normal"));
}

// Layer mode: the status through both faces, per point of S (the first interface's points).
std::string combined_status_array(const SceneRecord& scene, const std::string& path) {
  if (scene.combined_status.empty()) return "";
  const auto size = static_cast<Eigen::Index>(scene.combined_status.size());
  if (scene.interfaces.empty() || scene.interfaces.front().x.rows() != size)
    bad_scene(path, "combined_status does not match the points of the first interface");
  const auto at = nodes_at(scene, scene.interfaces.front(), path);
  auto status = [&](auto k) { return scene.combined_status[k]; };
  return data_array("Int32", "combined_status", 1,
                    scalar_on_nodes(at, scene.nodes.rows(), -1, status, path, "combined_status"));
}

std::string point_data(const SceneRecord& scene, const std::string& path) {
  std::string xml = "<PointData Vectors=\"displacement\">\n" +
                    data_array("Float64", "displacement", 3, planar_vectors(scene.u, path, "displacement"));
  for (const InterfaceFields& f : scene.interfaces) xml += interface_arrays(scene, f, path);
  return xml + combined_status_array(scene, path) + "</PointData>\n";
}

// Per cell: "body" (its name is the FieldData string "body_name_<body>") and "stress"
// (σ11, σ22, σ12 at the cell's centre, daN/mm²). Nothing for a record without them.
std::string cell_data(const SceneRecord& scene, const std::string& path) {
  if (scene.cell_body.empty()) return "";
  const auto cells = static_cast<std::size_t>(scene.cells.rows());
  if (scene.cell_body.size() != cells || static_cast<std::size_t>(scene.cell_stress.rows()) != cells ||
      scene.cell_stress.cols() != 3)
    bad_scene(path, "cell_body and cell_stress must have one row per cell");
  std::string body, stress;
  for (std::size_t c = 0; c < cells; ++c) {
    body += std::to_string(scene.cell_body[c]) + "\n";
    const std::string at = "stress of cell " + std::to_string(c);
    for (int k = 0; k < 3; ++k) stress += finite_text(scene.cell_stress(c, k), path, at) + (k < 2 ? " " : "\n");
  }
  return "<CellData>\n" + data_array("Int32", "body", 1, body) + data_array("Float64", "stress", 3, stress) +
         "</CellData>\n";
}

std::string field_data(const SceneRecord& scene, const std::string& path) {
  std::string xml = "<FieldData>\n" + data_array("String", "scene_id", 1, vtk_string(scene.id), 1);
  for (const auto& [name, value] : scene.text) xml += data_array("String", name, 1, vtk_string(value), 1);
  for (const auto& [name, value] : scene.numbers) {
    if (std::isnan(value)) bad_scene(path, "attribute '" + name + "' is NaN");
    xml += std::isinf(value) ? data_array("String", name, 1, vtk_string(value > 0 ? "inf" : "-inf"), 1)
                             : data_array("Float64", name, 1, text_of(value), 1);
  }
  for (const auto& [name, value] : scene.integers) xml += data_array("Int64", name, 1, std::to_string(value), 1);
  for (std::size_t b = 0; b < scene.body_names.size(); ++b)
    xml += data_array("String", "body_name_" + std::to_string(b), 1, vtk_string(scene.body_names[b]), 1);
  for (const auto& [name, r] : scene.reactions) {
    const std::string what = "reaction_" + name;
    xml += data_array("Float64", what, 2, finite_text(r.x(), path, what) + " " + finite_text(r.y(), path, what), 1);
  }
  return xml + "</FieldData>\n";
}

std::string vtu_text(const SceneRecord& scene, const std::string& path) {
  if (scene.nodes.rows() == 0 || scene.nodes.cols() != 2 || scene.u.cols() != 2 || scene.u.rows() != scene.nodes.rows())
    bad_scene(path, "nodes and u must both be N x 2, N > 0");
  if (scene.cells.cols() != 3 && scene.cells.cols() != 4) bad_scene(path, "cells must have 3 or 4 columns");
  return "<?xml version=\"1.0\"?>\n" + std::string(vtu_marker) + "\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "<UnstructuredGrid>\n" +
         field_data(scene, path) + "<Piece NumberOfPoints=\"" + std::to_string(scene.nodes.rows()) +
         "\" NumberOfCells=\"" + std::to_string(scene.cells.rows()) + "\">\n" + point_data(scene, path) +
         cell_data(scene, path) + points(scene, path) + cells(scene, path) + "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void write_vtu(const std::string& path, const SceneRecord& scene) {
  write_text_atomically(path, vtu_text(scene, path));
}

void write_vtu(const std::string& path, const SceneRecord& scene, const OutputRules& rules) {
  write_output_text(path, OutputKind::Vtu, rules, vtu_text(scene, path));
}

void check_vtu_target(const std::string& path) {
  const std::string tmp = temporary_name_beside(resolve_output_target(path));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) cannot_write(path, errno);
  ::close(fd);
  ::unlink(tmp.c_str());
}

}  // namespace thinlayer
