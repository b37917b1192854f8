#include "core/io/units.h"

#include <map>

namespace thinlayer {

std::string unit_of(const std::string& name, const std::string& force_unit) {
  std::string unit = unit_of(name);
  if (force_unit == "daN") return unit;
  // Another force unit: the same numbers in N and MPa (a scene file's "units": "mm-N").
  for (std::size_t at; (at = unit.find("daN/mm^2")) != std::string::npos;) unit.replace(at, 8, "MPa");
  for (std::size_t at; (at = unit.find("daN")) != std::string::npos;) unit.replace(at, 3, force_unit);
  return unit;
}

std::string unit_of(const std::string& name) {
  static const std::map<std::string, std::string> units = {
      // scene attributes
      {"eps", "mm"},
      {"h_interface", "mm"},
      {"h_far", "mm"},
      {"lambda_bar", "daN/mm^3"},
      {"mu_bar", "daN/mm^3"},
      {"lambda_eps", "daN/mm^2"},
      {"mu_eps", "daN/mm^2"},
      {"friction", "1"},
      {"gamma", "1"},
      {"delta", "1"},
      {"load_scale", "1"},
      {"mesh_distortion", "1 (fraction of the element size)"},
      {"residual", "1 (relative)"},
      {"residual_interface", "1 (relative)"},
      {"residual_bulk", "1 (relative)"},
      {"tolerance", "1 (relative)"},
      {"status_tolerance", "1 (relative)"},
      {"condition_estimate", "1"},
      {"layer_max_aspect_ratio", "1"},
      {"layer_min_angle_deg", "degree"},
      {"wall_time_s", "s"},
      {"setup_time_s", "s"},
      {"meshing_time_s", "s"},
      {"law_thickness", "mm"},
      {"characteristic_length", "mm"},
      // datasets
      {"nodes", "mm"},
      {"u", "mm"},
      {"x", "mm"},
      {"normal", "1 (unit vector)"},
      {"length", "mm (tributary length)"},
      {"jump_N", "mm"},
      {"jump_T", "mm"},
      {"sigma_N", "daN/mm^2"},
      {"sigma_T", "daN/mm^2"},
      {"cell_stress", "daN/mm^2"},
      {"reactions", "daN/mm (per mm of thickness)"},
      {"residual_per_body", "1 (relative)"},
      {"residual_per_interface", "1 (relative)"},
      {"residual_floor_per_body", "1 (relative)"},
      {"residual_floor_per_interface", "1 (relative)"},
      {"film_slip_over_h", "1 (elements along S)"},
      {"film_strain_max", "1 (strain)"},
      {"residual_nodal_floor_per_body", "1 (relative)"},
  };
  auto it = units.find(name);
  return it == units.end() ? "" : it->second;
}

}  // namespace thinlayer
