#pragma once
// How far a layer scene's answer strays from the discrete model's assumptions (SPEC §1.5, "film
// admissibility"): a layer whose faces are open or slide can be pushed along by forces of order ε
// against a membrane of stiffness order ε² and travel far — the dovetail (d) film 25 at ε = 1e-8
// against the adherents' 1.3e-3, the bar's row 5 film end 70 mm along a 40 mm bar at ε = 1e-4. That
// is an answer of the discrete model, but the node-to-node pairing needs slips below the element
// size and the model is one of small strains. Two numbers say so:
//  - film_slip_over_h: the largest slip |[u]_T| on a face of the layer, over the element size along S
//    at that node (the mean of its two segments; its one segment at a bondline's end);
//  - film_strain_max: the layer's largest strain, the largest |principal strain| at a cell's centre.
// `solve` warns above one element or 1e-2; the report lists the study scenes that do.
#include <string>

#include "core/io/scene_record.h"

namespace thinlayer {

constexpr double film_slip_warning = 1.0;     // elements along S
constexpr double film_strain_warning = 1e-2;  // small strain

struct FilmAdmissibility {
  double slip_over_h = 0;     // dimensionless
  std::string slip_where;     // the interface and node (index along it) of the largest slip
  double strain_max = 0;      // dimensionless
  bool admissible() const { return slip_over_h <= film_slip_warning && strain_max <= film_strain_warning; }
};

// Of a layer-mode record: its interfaces are the layers' faces, its layer bodies named "layer" or
// "layer-<bondline>".
FilmAdmissibility film_admissibility(const SceneRecord& record);

// Stores both numbers in the record (numbers "film_slip_over_h", "film_strain_max").
void record_film_admissibility(SceneRecord& record);

// "film: largest slip … elements along S, largest strain …" of a record that holds both numbers
// (record_film_admissibility), "" of any other: the line both forms of `solve` print.
std::string film_line(const SceneRecord& record);

// One line for `solve`, or "" where the answer is admissible (or the record is not a layer scene's).
std::string film_warning(const FilmAdmissibility& film);
std::string film_warning(const SceneRecord& record);

}  // namespace thinlayer
