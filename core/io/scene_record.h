#pragma once
// One solved scene in the output schema of SPEC §4 (/scenes/<id> in an HDF5 file).
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/fem/model.h"
#include "core/io/h5_writer.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

// Fields along one interface, SPEC §1.2 signs.
struct InterfaceFields {
  std::string name;
  H5Writer::RowMatrixXd x, normal;                  // M×2, mm and unit
  Eigen::VectorXd length;                           // tributary length, mm
  Eigen::VectorXd jump_N, jump_T;                   // mm
  Eigen::VectorXd sigma_N, sigma_T;                 // daN/mm²
  std::vector<int> status;                          // 0 gap, 1 slide, 2 stick
  // Mesh node index (row of SceneRecord::nodes) of each interface node on its plus and minus
  // side; -1 on the minus side for the rigid foundation. Filled by record_scene.
  std::vector<int> node_plus, node_minus;
  StatusCount counts() const;
};

struct SceneRecord {
  std::string id;
  std::map<std::string, std::string> text;        // case, mode, law_case, plane, element, solver, ...
  std::map<std::string, double> numbers;          // eps, gamma, delta, lambda_bar, mu_bar, friction, ...
  std::map<std::string, long long> integers;      // iterations, converged, mesh descriptors, ...
  H5Writer::RowMatrixXd nodes;                    // N×2, all bodies, mm
  H5Writer::RowMatrixXi cells;                    // 4 (Q1) or 3 (P1) node indices per cell
  H5Writer::RowMatrixXd u;                        // N×2, mm
  std::vector<std::string> body_names;            // the model's bodies, in order
  std::vector<int> cell_body;                     // per cell: its body's index in body_names
  H5Writer::RowMatrixXd cell_stress;              // per cell: σ11, σ22, σ12 at its centre, daN/mm²
  std::vector<InterfaceFields> interfaces;
  std::map<std::string, Eigen::Vector2d> reactions;  // daN per unit thickness
  // Layer mode: the status of each point of S through both faces (empty in limit mode).
  std::vector<int> combined_status;
  // SPEC §1.5: the residual of each body and each interface (dimensionless), with their names.
  std::vector<double> residual_per_body, residual_per_interface;
  std::vector<double> residual_floor_per_body;  // Residual::per_body_floor: round-off's share
  std::vector<double> residual_nodal_floor_per_body;  // Residual::per_body_nodal_floor
  std::vector<std::string> interface_names;  // (the bodies: body_names above)
  // The force unit of every number above ("daN": daN and daN/mm^2; "N": N and MPa, a scene file's
  // "units": "mm-N"); the units written with them say which.
  std::string force_unit = "daN";
};

// Interface fields of a solution: jumps g = B u + g_D, stresses σ = r / ℓ, statuses with the
// given relative tolerance (SPEC §1.2), one entry per interface of the problem.
std::vector<InterfaceFields> interface_fields(const ContactProblem& problem, const SolveReport& report,
                                              double status_tolerance);

// Everything the solve produced: mesh, displacement, interfaces, reactions, and the solver's
// attributes (solver, iterations, residual, converged, wall_time_s, ...). Case attributes
// (case, mode, law_case, eps, ...) are the caller's to add.
SceneRecord record_scene(const std::string& id, const Model& model, const ContactProblem& problem,
                         const SolveReport& report, double status_tolerance);

// The Coulomb coefficients a fast solve went through before the scene's own f
// (SolverOptions::friction_path holds their multipliers of f): the text attribute
// "friction_path" = "f1,f2,...,f". Nothing when the path is empty.
void record_friction_path(SceneRecord& scene, const std::vector<double>& multipliers, double friction);

// /scenes/<id>: every attribute and dataset above, each numeric one with a unit (units.h)
// as a `units` attribute on a dataset and a `<name>_units` attribute beside an attribute;
// the status legend on every status dataset; the force sign convention on each interface.
void write_scene(H5Writer& file, const SceneRecord& scene);

}  // namespace thinlayer
