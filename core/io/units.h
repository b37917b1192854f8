#pragma once
// The unit of each quantity thinlayer writes (SPEC §4: "a units attribute on every dataset
// and numeric attribute that has one"). Units: mm and daN (the dovetail's length unit is its
// characteristic length L = 1, written as mm like the bar's); forces are per unit thickness
// (plane problems), so a force is in daN/mm and a stress in daN/mm^2.
#include <string>

namespace thinlayer {

// The unit of a scene attribute or dataset by its name ("eps" -> "mm", "sigma_N" ->
// "daN/mm^2"); "1" for a dimensionless ratio; empty for a count, a code or a text.
std::string unit_of(const std::string& name);
// The same in another force unit (a scene file's "units": "mm-N": N, and MPa for daN/mm^2).
std::string unit_of(const std::string& name, const std::string& force_unit);

// The status codes of every `status` and `combined_status` dataset (SPEC §1.2).
constexpr const char* status_legend = "0 gap, 1 slide, 2 stick";

// On which body the interface forces act and with which sign (SPEC §1.2, §4): the force
// per unit length the minus side exerts on the plus body is -sigma_N n + sigma_T t, with n
// the unit normal from the minus into the plus side and t = (n_y, -n_x).
constexpr const char* force_convention =
    "traction on the plus body = -sigma_N n + sigma_T t (n: unit normal from the minus into the plus side, "
    "t = (n_y, -n_x)); sigma_N <= 0 is compression; jump_N = n.(u_minus - u_plus) > 0 is interpenetration, "
    "jump_T = t.(u_plus - u_minus)";

}  // namespace thinlayer
