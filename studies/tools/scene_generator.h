#pragma once
// S5's seeded scene generator (SPEC §3 S5, issue 25): layer-mode scenes drawn off every fixed grid,
// so that a solver is judged on scenes it was not tuned on. One seed, one scene, always the same
// (std::mt19937_64 and a fixed sequence of draws; no distribution objects, whose output the C++
// standard leaves to the library).
//
// The draws:
//  - the case: the dovetail 60 % (Table 2's nine cases half of the time, else γ ∈ [0, 2), δ ∈ [0, 1.95]),
//    the bar 20 % (Table 3's six rows), a shipped scene file 20 % (cases/lap_joint, cases/double_lap,
//    cases/stepped_lap);
//  - ε log-uniform from 1e-8 to the thickest the case allows (dovetail 0.1, the bar's documented
//    1 mm (bar::thickest_layer), a scene file's own limit);
//  - the dovetail: f uniform in [0, 1], the element size along S log-uniform in [h_min, h_max],
//    2…4 elements through the layer;
//  - the bar: 16…128 elements along AD (log-uniform), 2…4 elements through the layer, the load scale
//    log-uniform in [0.1, 10] (the bar's own f = 1; its loads are tractions, so their scale moves the
//    answer's size, not its shape: a check of the solver's scaling);
//  - a scene file: as shipped (its faces, glue, mesh), ε drawn.
// The dovetail's load is an imposed displacement and its layer starts closed: its answer is linear
// in the load's scale, so no load scale is drawn for it.
#include <string>

#include "cases/dovetail/dovetail.h"

namespace thinlayer {

struct GeneratorRanges {
  double h_min = 0.003, h_max = 0.05;  // dovetail: element size along S (L = 1 units)
  int bar_nx_max = 128;                // bar: elements along AD, 16 … this
};

struct GeneratedScene {
  enum class Kind { Dovetail, Bar, SceneFile };
  int seed = 0;
  Kind kind = Kind::Dovetail;
  double eps = 0;             // layer thickness (dovetail: L = 1 units; bar and scene files: mm)
  int layer_elements = 2;
  // dovetail
  char law_case = 0;          // 'a'..'i', or 0 for drawn exponents
  dovetail::Exponents exponents;
  double friction = 0.5;
  double h_interface = 0.025;
  // bar
  int bar_row = 1;
  int bar_nx = 32;
  double load_scale = 1;
  // scene file (relative to the cases folder), and its ε as a fraction of the thickest it allows
  std::string scene_file;
  double eps_fraction = 1;

  // Everything above in one line, e.g. "seed 12: dovetail case f, eps 2.0e-07, f 0.67, h 0.0379, 3 across".
  std::string describe() const;
};

GeneratedScene generate_scene(int seed, const GeneratorRanges& ranges = {});

}  // namespace thinlayer
