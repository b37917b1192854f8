#pragma once
// The engineer's validity map (SPEC §3 S3; issue 36): over the glue's thickness t/L and stiffness
// E_g/E_a (and its Poisson ratio ν_g), how far is the finite spring law of a glue at its own
// thickness from the meshed layer of that glue, on a user's joint? And SPEC §3 S6 judged on it: how
// far did the limit-mode estimate say it was?
//
// Each cell (studies/tools/map_cell.h) solves the layer, the finite law and its first-order answer
// on the scene's mesh (h) and on half its element size (h/2): the distances that the mesh moves —
// the mesh floor — are kept apart. A quantity of a cell is *resolved* where the mesh moves it by less
// than half: e(h/2) > 2 |e(h) − e(h/2)| (a floor shrinking like h is |e(h) − e(h/2)| at h/2, so the
// part that does not shrink, the model's, is at least as large). The map is read at h/2.
//
// Also judged on it, SPEC §1.3's paper's rule (3 % / 30x): the cells where it would pick a 0 or ∞
// law instead of the finite one, and the distance to the layer that choice costs there.
//
// The cells are independent: one SceneBatch (studies/parallel/scene_batch.h) spreads them over the
// MPI ranks and, within a rank, its threads. Every cell is kept: one that a solve refused or that did
// not converge is written, drawn and counted as such.
#include <string>
#include <vector>

#include "cases/scene/scene_file_scenes.h"
#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"
#include "studies/tools/map_cell.h"

namespace thinlayer {

// n values from a to b, geometric (a and b included).
std::vector<double> geometric_grid(double a, double b, int n);

struct ValidityMapOptions {
  // SPEC §3 S3's ranges: t/L 1e-3 ... 1e-1 (3 per decade), E_g/E_a 1e-4 ... 1e-1 (2 per decade).
  std::vector<double> t_over_L = geometric_grid(1e-3, 1e-1, 7);
  std::vector<double> E_ratio = geometric_grid(1e-4, 1e-1, 7);
  std::vector<double> nu = {0.3, 0.45};
  // d of the peaks at a distance from each bondline end (mm); 0: the larger of the grid's thickest
  // glue and two elements of the scene's mesh (as the scene studies choose it).
  double peak_distance = 0;
  bool floor = true;        // also at half the element size (a scene given as "geometry" with "mesh_size")
  double tolerance = 1e-10;
  int threads = 1;          // cells solved at once on each rank
  bool verbose = true;
  double factor = 2;        // S6: the estimate within this factor of the measured distance, where resolved
};

struct ValidityMapResult {
  std::string scene;
  double L = 0, E_a = 0;             // mm, stress unit
  double d = 0;                      // mm
  std::string d_reason;
  double h = 0, h_fine = 0;          // mm (h_fine 0: no floor level)
  std::vector<MapCell> cells;        // ν outermost, then E_g/E_a, then t/L
  double wall_time_s = 0;
  int ranks = 1, threads = 1;
  std::vector<Check> checks;
};

// Per cell and quantity, what the driver judges, at h/2 (at h where there is no floor level).
//  - above the mesh floor ("resolved"): the mesh moves the distance by less than half,
//    e(h/2) > 2 |e(h) − e(h/2)| (a floor shrinking like h is |e(h) − e(h/2)| at h/2), and the mesh has
//    at least 4 elements over the joint's shear-lag length (else the law's lumped springs and the
//    layer's band discretise the bondline's stresses differently at both levels alike, which halving
//    h does not show: the double lap's stiff thin glues, ℓ_s 0.24 mm against h/2 = 0.125 mm);
//  - the estimate it is judged against: SPEC 3 S6's, with its end cells, where the mesh resolves the
//    layer's end zone (h/2 ≤ 3 t: the zone is a few t long — its deficits 0.13 … 0.66 t, the
//    Poiseuille length of a ν = 0.45 glue about t); else the same without them
//    (MapCellLevel::interior), which is what a layer meshed with elements much longer than its end
//    zone shows (the measured distance grows towards the full estimate under refinement: the double
//    lap at t = 0.2 mm, reactions 1.17e-3, 1.37e-3, 1.50e-3 at h = 0.25, 0.125, 0.0625 against 1.7e-3).
struct MapJudgement {
  bool converged = false;   // every scene of the cell reached the tolerance (both levels)
  double measured = 0, floor = 0;
  double estimate = 0, interior = 0;  // S6's, and without its end cells
  bool ends_resolved = false;         // h/2 ≤ 3t: judged against `estimate`, else against `interior`
  bool resolved = false;              // above the mesh floor (both criteria)
  bool within = false;                // the estimate judged within the factor of measured
  double judged() const { return ends_resolved ? estimate : interior; }
  // Order one: the layer's distance to the first-order answer u₁ (to u₁ without its end cells where the
  // mesh does not resolve the end zone, as the estimate), its own mesh floor |e₁(h) − e₁(h/2)|, and its
  // ratio to the order-0 distance `measured` (0 where measured is 0).
  double order1 = 0, order1_floor = 0;
  bool order1_resolved = false;       // e₁(h/2) > 2 |e₁(h) − e₁(h/2)|: the mesh moves it by less than half
  double order1_ratio() const { return measured > 0 ? order1 / measured : 0.0; }
};
MapJudgement judge(const MapCell& cell, const std::string& quantity, double factor);

// Runs the map on `bulk` (a scene with a layer mode), prints its tables and writes
// /studies/validity_map/<name>/ to `out` and, beside `out`'s file, validity_map_<name>.csv. Checks
// (ids "validity_map.<name>.*"): every cell converged at both levels; the estimate within `factor` of
// the measured distance at every resolved cell, for the adherents' displacements.
ValidityMapResult run_validity_map(SceneFileBulk& bulk, const ValidityMapOptions& options, H5Writer* out);

}  // namespace thinlayer
