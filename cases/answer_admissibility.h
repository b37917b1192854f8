#pragma once
// Is a solved scene's answer within the model's small-displacement assumptions? (issue 35, item 3,
// in both modes.) The model is linear: its equilibrium is written on the undeformed joint. A
// single lap whose grip is left free sideways bends under its own eccentricity and, solved
// linearly, deflected 82 mm on a 75 mm joint without a word; a plug sliding 0.68 mm across 0.5 mm
// elements in limit mode was silent where its layer mode warned (the node-to-node pairing of an
// interface needs slips below the element size). Two numbers, each with one meaning:
//  - displacement_over_size: the largest |u| of an adherent's node over that body's size (the
//    largest side of its bounding box); a warning above displacement_warning (5 %: rotations of
//    that order make the linear model's error of that order);
//  - slip_over_h (limit mode): the largest |[u]_T| on an interface over the element size along S
//    at that node (the layer mode's rule for its contact faces, cases/film_admissibility.h);
//  - strain_max: the largest |principal strain| of an adherent's cell (at its centre), and in layer
//    mode of a glue (glue_strain_max, cases/film_admissibility.h). Above small_strain_warning (1e-2,
//    SPEC §1.5's small strain, the films' rule) the load is beyond the model's range: the model is
//    geometrically and materially linear, its answer that of a linear model at this load, not the
//    joint's (30 000 N/mm on a 1.6 mm aluminium lap strains the metal 0.14 and the glue 1.21). A
//    stress beyond a metal's yield is not the model's to judge; a strain beyond small strain is.
// The displacement warning asks "a support left free?" only where the stiffness is near-singular
// for that motion: the body moves at least ten times more (over its size) than any cell of it
// strains — a rigid motion or a bending held by little. A large load strains as much as it moves.
// The films are left to the film admissibility.
#include <string>

#include "core/io/scene_record.h"

namespace thinlayer {

constexpr double displacement_warning = 0.05;  // of a body's size
constexpr double small_strain_warning = 1e-2;  // |principal strain|
constexpr double mechanism_ratio = 10;         // displacement over size against the strain: "a support left free?"

struct AnswerAdmissibility {
  double displacement_over_size = 0;
  std::string body;           // where
  double displacement = 0;    // mm, that body's largest |u|
  double size = 0;            // mm, that body's size
  bool limit = false;         // a limit-mode record: its interfaces' slips are judged
  double slip_over_h = 0;
  std::string slip_where;     // the interface and node of the largest slip
  double strain_max = 0;      // the adherents' largest |principal strain|
  std::string strain_body;    // where
};

AnswerAdmissibility answer_admissibility(const SceneRecord& record);

// Stores "displacement_over_size" (and text "displacement_body") and, in limit mode, "slip_over_h"
// (and "slip_where") in the record.
void record_answer_admissibility(SceneRecord& record);

// The warnings of a record holding those numbers: one line each, "" where none.
std::string displacement_warning_line(const SceneRecord& record);
std::string strain_warning_line(const SceneRecord& record);
std::string limit_slip_warning_line(const SceneRecord& record);

}  // namespace thinlayer
