#pragma once
// The end cell of a bonded layer (SPEC §3 S6; studies/limit_error_estimate.md, "The ends"). Near a
// free end of a thin layer the spring law's traction is wrong over a zone of a few thicknesses: the
// layer's end face carries no traction, so the shear and the normal stress it carries must fall off
// there. Seen from the adherents (rigid at the scale t of the zone when the glue is much softer
// than they are), the zone is the inner problem of matched asymptotics: a semi-infinite strip
// 0 < y < t, x > 0 of the glue, its faces held by the adherents and moved apart by a uniform shear
// (u_x jumps by U) or stretch (u_y jumps by V), its end face x = 0 free. Far from the end the strip
// is the spring (σ_xy = μ U/t, σ_yy = (λ+2μ) V/t); the force its faces carry falls short of the
// spring's by α_T t σ_xy and α_N t σ_yy. The α depend on ν (and the plane hypothesis) alone.
//
// No closed form is known to us: they are computed here, once per ν, by the project's own Q1 finite
// elements on the strip [0, X] × [0, t] (X at least 12 t, both ends free, so each end's deficit is
// half the whole; its columns graded towards both ends), extrapolated from two grids, and cached.
// Measured (480 × 48 cells, 8 s): ν = 0.3: α_T 0.158, α_N 0.103; ν = 0.45: α_T 0.126, α_N 0.655 (the
// normal zone lengthens as the glue nears incompressibility: squeezed out at its end, it is confined
// only over the Poiseuille length t √((1−ν)/(6(1−2ν))))..
#include "core/fem/material.h"

namespace thinlayer {

struct LayerEndDeficits {
  double normal = 0;  // α_N: the normal force falls short by α_N t σ_N
  double shear = 0;   // α_T: the shear force falls short by α_T t σ_T
};

// nu in (−1, 0.5); thread-safe (a cache behind a mutex). Throws std::invalid_argument outside.
LayerEndDeficits layer_end_deficits(double nu, PlaneHypothesis plane);

// The same cell on a given grid, uncached (cells along x and through the thickness): for the
// convergence test.
LayerEndDeficits layer_end_deficits_on(double nu, PlaneHypothesis plane, int cells_along, int cells_across);

}  // namespace thinlayer
