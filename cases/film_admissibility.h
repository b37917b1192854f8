#pragma once
// How far a layer scene's answer strays from the discrete model's assumptions (SPEC §1.5, "film
// admissibility"): a layer whose faces are open or slide can be pushed along by forces of order ε
// against a membrane of stiffness order ε² and travel far — the dovetail (d) film 25 at ε = 1e-8
// against the adherents' 1.3e-3, the bar's row 5 film end 70 mm along a 40 mm bar at ε = 1e-4. That
// is an answer of the discrete model, but the node-to-node pairing needs slips below the element
// size and the model is one of small strains.
//
// One meaning per number (issue 35):
//  - film_slip_over_h: the largest slip |[u]_T| on a **contact** face of a layer, over the element
//    size along S at that node (the mean of its two segments; its one segment at a bondline's end).
//    A bonded face does not slip: it is not a film's face;
//  - film_strain_max: the largest |principal strain| at a cell's centre of a **film**, a layer with
//    no bonded face (the paper's, held by contact alone);
//  - glue_strain_max: the same of a layer with a bonded face — a glue. A glued joint's glue strains
//    as its load grows (7 % at 20 MPa of mean shear on the double lap's epoxy): that is a load level
//    of a linear elastic glue ("linear elastic glue assumed; peak strain X"), not a defect of the
//    model, and never a warning.
// `solve` warns where a contact face slid more than one element or a film strained more than 1e-2;
// the report lists those scenes.
#include <set>
#include <string>

#include "core/io/scene_record.h"

namespace thinlayer {

constexpr double film_slip_warning = 1.0;     // elements along S
constexpr double film_strain_warning = 1e-2;  // small strain

// Which of a layer record's interfaces are contact faces and which of its layers are bonded to an
// adherent (by name). The default — every face in contact, no glue — is the paper's (bar, dovetail).
struct LayerFaceRoles {
  std::set<std::string> bonded_faces;   // interface names whose law is bilateral (tied)
  std::set<std::string> glued_layers;   // layer bodies with at least one bonded face
};

struct FilmAdmissibility {
  bool has_contact_face = false, has_film = false, has_glue = false;
  double slip_over_h = 0;     // dimensionless, contact faces
  std::string slip_where;     // the interface and node (index along it) of the largest slip
  double strain_max = 0;      // dimensionless, films
  double glue_strain_max = 0; // dimensionless, glues (a load level)
  bool admissible() const { return slip_over_h <= film_slip_warning && strain_max <= film_strain_warning; }
};

// Of a layer-mode record: its interfaces are the layers' faces, its layer bodies named "layer" or
// "layer-<bondline>".
FilmAdmissibility film_admissibility(const SceneRecord& record, const LayerFaceRoles& roles = {});

// Stores the numbers in the record: "film_slip_over_h" where a layer has a contact face,
// "film_strain_max" where a layer is a film, "glue_strain_max" where one is glued.
void record_film_admissibility(SceneRecord& record, const LayerFaceRoles& roles = {});

// "film: largest slip … elements along S, largest strain …; glue: linear elastic glue assumed; peak
// strain …" of a record that holds the numbers (record_film_admissibility), "" of any other: the
// line both forms of `solve` print.
std::string film_line(const SceneRecord& record);

// The element size along an interface (a chain in node order) at each node: the mean of its two
// segments, its one segment at either end (mm).
Eigen::VectorXd element_sizes_along(const InterfaceFields& f);

// The largest |principal strain| of a cell of a record at its centre (Q1 or P1).
double principal_strain(const SceneRecord& record, int cell);

// One line for `solve`, or "" where the answer is admissible (or the record is not a layer scene's).
std::string film_warning(const FilmAdmissibility& film);
std::string film_warning(const SceneRecord& record);

}  // namespace thinlayer
