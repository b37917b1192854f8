#pragma once
// Writes one scene as a VTK XML UnstructuredGrid file (.vtu, ASCII) for ParaView.
//
// What the file holds (units as in the scene: mm, daN/mm², daN per unit thickness):
//   Points      the nodes of every body, z = 0;
//   Cells       VTK_QUAD (9) for a 4-node cell, VTK_TRIANGLE (5) for a 3-node one (a row
//               padded with -1, as in a mixed mesh, counts its non-negative entries);
//   PointData   "displacement" (3 components, z = 0), and for each interface <name>
//               (S, or S+ and S-) the fields of SPEC §4 on the bulk nodes at its points:
//               "on_interface_<name>" (1 on the interface, 0 elsewhere), "<name>_jump_N",
//               "<name>_jump_T", "<name>_sigma_N", "<name>_sigma_T", "<name>_length",
//               "<name>_normal" (3 components), "<name>_status" (0 gap, 1 slide, 2 stick,
//               -1 off the interface); in layer mode also "combined_status" on the points of
//               the first interface (S+), -1 elsewhere;
//   CellData    "body" (the cell's body: its name is the FieldData "body_name_<body>") and
//               "stress" (σ11, σ22, σ12 at the cell's centre, 3 components, daN/mm²);
//   FieldData   the scene's attributes, one tuple each: "scene_id" and the text attributes
//               as String arrays, numbers as Float64, integers as Int64, and each reaction
//               as "reaction_<boundary>" (2 components, [R_x, R_y]).
//
// Why the interface fields sit on the bulk nodes rather than on separate vertex cells: a
// ParaView user then colours the deformed mesh by sigma_N or status directly, and gets the
// curves along S with Threshold (on_interface_<name> = 1) + Plot Data, without a second
// set of points that every bulk array would have to pad. An interface point lies on the
// nodes of both bodies it joins (within 1e-9 of the mesh's size), and both carry its values;
// a node on no interface carries 0 (status -1) and the mask 0.
//
// An infinite scene attribute (λ̄ = inf: the exact Signorini or rigid-stick law) is written
// as the String "inf", since ASCII VTK cannot read an infinite Float64. NaN anywhere, or an
// infinite point, displacement or interface value, is an error: nothing is written.
//
// All or nothing: the text goes to a temporary file next to the target, which is renamed
// onto it; on any error the temporary file is removed and the target left as it was
// (write_text_atomically, core/io/output_target.h: through symbolic links, never onto a
// directory, FIFO or device).
#include <string>

#include "core/io/output_ownership.h"
#include "core/io/scene_record.h"

namespace thinlayer {

// Throws std::runtime_error naming the path if the scene is inconsistent (sizes, cell widths,
// node indices, an interface point on no node) or holds a NaN, or if the file cannot be written.
void write_vtu(const std::string& path, const SceneRecord& scene);
// The same, the target judged under `rules` at the moment of writing (core/io/output_ownership.h).
void write_vtu(const std::string& path, const SceneRecord& scene, const OutputRules& rules);

// Throws OutputError naming the path if a file cannot be created there (the path is a
// directory, its directory is missing or not writable). Leaves nothing behind. Lets a caller
// reject an unwritable target before a long solve.
void check_vtu_target(const std::string& path);

}  // namespace thinlayer
