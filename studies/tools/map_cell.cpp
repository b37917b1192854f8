#include "studies/tools/map_cell.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "core/solvers/stop_verdict.h"
#include "studies/tools/limit_error_estimate.h"
#include "studies/tools/scene_distance.h"

namespace thinlayer {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The verdict's quantities at d and S2's stress norms, of `record` against `limit`. The reactions
// as S6's estimate measures them (one vector, reaction_distance), so that the map compares like with
// like; NaN (not judged) where statics fixes every component (reaction_components): their distance
// is round-off, no estimate is judged on it.
std::map<std::string, double> distances(const SceneFileBulk& bulk, const SceneRecord& record, const SceneRecord& limit,
                                        double d) {
  std::map<std::string, double> e = verdict_distance(bulk, record, limit, d);
  bool fixed = true;
  for (const ReactionComponent& c : reaction_components(bulk.model())) fixed = fixed && c.determinate;
  e["reactions"] = fixed ? std::nan("") : reaction_distance(record, limit);
  const std::map<std::string, double> s2 = scene_distance(bulk, record, limit);
  e["sigma_N"] = s2.at("sigma_N");
  e["sigma_T"] = s2.at("sigma_T");
  return e;
}

// The finite spring law of each bondline's glue at its own thickness t (SPEC §1.3), stated here.
std::vector<InterfaceLaw> finite_laws(const SceneFileBulk& bulk, double t) {
  std::vector<InterfaceLaw> laws;
  for (std::size_t i = 0; i < bulk.spec().interfaces.size(); ++i) {
    const SceneInterfaceSpec& b = bulk.spec().interfaces[i];
    if (!b.glue) {  // a law only: its own
      laws.push_back(bulk.limit_law(static_cast<int>(i), t));
      continue;
    }
    const LameModuli m = lame_from_young(b.glue->E, b.glue->nu);
    laws.push_back(layer_limit_law(m.lambda / t, m.mu / t, b.faces, b.friction));
  }
  return laws;
}

std::string case_letters(const std::vector<InterfaceLaw>& laws) {
  std::string s;
  for (const InterfaceLaw& l : laws) s += (s.empty() ? "" : ",") + std::string(1, l.table1_case());
  return s;
}

// "" where the solve converged; else "<which>: <why it stopped>; " (its message).
std::string not_used_because(const SolveReport& report, const std::string& which) {
  return report.converged ? "" : which + ": " + report.message + "; ";
}

bool same_law(const InterfaceLaw& a, const InterfaceLaw& b) {
  return a.lambda_bar == b.lambda_bar && a.mu_bar == b.mu_bar && a.bilateral == b.bilateral && a.friction == b.friction;
}

// One mesh level: the layer, the finite law with its first-order answer, and (rule) the paper's rule.
MapCellLevel solve_level(const SceneFileBulk& meshed, const SceneSpec& spec, double t, double d, double tolerance,
                         bool rule, MapCell& cell) {
  MapCellLevel level;
  level.h = spec.h_interface.value_or(0.0);
  SolverOptions options;
  options.tolerance = tolerance;
  try {
    SceneFileBulk bulk(meshed, spec);
    const std::vector<InterfaceLaw> laws = finite_laws(bulk, t);
    auto start = std::chrono::steady_clock::now();
    const SceneFileScene layer = solve_scene_file_layer(bulk, t, SolverKind::Fast, options);
    level.layer_time_s = seconds_since(start);
    LimitSolveExtras extras;
    extras.laws = laws;
    extras.first_order = true;
    extras.first_order_interior = true;
    start = std::chrono::steady_clock::now();
    const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, options, t, default_status_tolerance, false, extras);
    level.limit_time_s = seconds_since(start) - limit.first_order.time_s;
    level.estimate_time_s = limit.first_order.time_s;
    level.layer_residual = layer.report.residual.value();
    level.limit_residual = limit.report.residual.value();
    level.converged = layer.report.converged && limit.report.converged;
    level.failure = not_used_because(layer.report, "layer mode") + not_used_because(limit.report, "finite law");
    // One rule (core/solvers/stop_verdict.h): a distance only between answers whose numbers may be used.
    if (usable(layer.report) && usable(limit.report)) {
      level.measured = distances(bulk, layer.record, limit.record, d);
      if (limit.first_order.record) {
        level.estimate = distances(bulk, *limit.first_order.record, limit.record, d);
        level.order1 = distances(bulk, layer.record, *limit.first_order.record, d);
      }
      if (limit.first_order.interior) {
        level.interior = distances(bulk, *limit.first_order.interior, limit.record, d);
        level.order1_interior = distances(bulk, layer.record, *limit.first_order.interior, d);
      }
    }
    cell.law_case = case_letters(laws);
    std::vector<InterfaceLaw> rules;
    bool differs = false;
    for (std::size_t i = 0; i < laws.size(); ++i) {
      rules.push_back(bulk.classified_law(static_cast<int>(i), t));
      differs = differs || !same_law(rules.back(), laws[i]);
    }
    cell.rule_case = case_letters(rules);
    if (rule && differs) {
      const SceneFileScene classified = solve_scene_file_limit(bulk, SolverKind::Fast, options, t, default_status_tolerance, true);
      cell.rule_solved = true;
      cell.rule_converged = classified.report.converged && layer.report.converged;
      cell.rule_failure = not_used_because(classified.report, "the rule's law") + not_used_because(layer.report, "layer mode");
      // Measured against the layer (the reference): the rule's law may carry nothing at all (a μ̄ = 0
      // law on a joint loaded in shear), which no distance relative to its own answer could say. Not
      // where either answer is unusable (a μ̄ = 0 law on a force-loaded joint is singular).
      if (usable(classified.report) && usable(layer.report))
        cell.rule_measured = distances(bulk, classified.record, layer.record, d);
    }
  } catch (const std::exception& e) {
    level.failure = e.what();
  }
  return level;
}

}  // namespace

const std::vector<std::string>& map_quantities() {
  static const std::vector<std::string> q = {"reactions", "u", "peel_at_d", "shear_at_d", "sigma_N", "sigma_T"};
  return q;
}

double map_adherent_modulus(const SceneFileBulk& bulk) {
  const AdherentData a = bulk.reference(0);
  return a.mu_m * (3 * a.lambda_m + 2 * a.mu_m) / (a.lambda_m + a.mu_m);
}

SceneSpec map_cell_spec(const SceneFileBulk& meshed, const MapCellSpec& cell) {
  if (!(cell.t_over_L > 0) || !(cell.E_ratio > 0) || !(cell.nu > -1 && cell.nu < 0.5))
    throw std::invalid_argument("a validity map cell needs t/L > 0, E_g/E_a > 0 and -1 < nu_g < 0.5");
  SceneSpec spec = meshed.spec();
  const double E = cell.E_ratio * map_adherent_modulus(meshed), t = cell.t_over_L * meshed.characteristic_length();
  for (SceneInterfaceSpec& i : spec.interfaces) {
    if (!i.has_layer_mode()) continue;  // a law only stays one
    i.layer.reset();
    i.glue = SceneGlueSpec{E, cell.nu, t};
  }
  return spec;
}

MapCell solve_map_cell(const SceneFileBulk& coarse, const SceneFileBulk* fine, const MapCellSpec& c, double d,
                       double tolerance) {
  MapCell cell;
  cell.spec = c;
  cell.E = c.E_ratio * map_adherent_modulus(coarse);
  cell.thickness = c.t_over_L * coarse.characteristic_length();
  const AdherentData a = coarse.reference(0);
  const double nu_a = a.lambda_m / (2 * (a.lambda_m + a.mu_m));
  const double E_plane = coarse.spec().plane == PlaneHypothesis::Strain ? map_adherent_modulus(coarse) / (1 - nu_a * nu_a)
                                                                       : map_adherent_modulus(coarse);
  cell.shear_lag = std::sqrt(E_plane * coarse.characteristic_length() * cell.thickness / lame_from_young(cell.E, c.nu).mu);
  cell.coarse = solve_level(coarse, map_cell_spec(coarse, c), cell.thickness, d, tolerance, fine == nullptr, cell);
  if (fine) cell.fine = solve_level(*fine, map_cell_spec(*fine, c), cell.thickness, d, tolerance, true, cell);
  return cell;
}

}  // namespace thinlayer
