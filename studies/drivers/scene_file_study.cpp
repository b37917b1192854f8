#include "studies/drivers/scene_file_study.h"

#include "core/solvers/stop_verdict.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <new>
#include <stdexcept>
#include <thread>

#include "core/io/reference_tables.h"
#include "core/io/scene_id_number.h"
#include "core/solvers/stop_verdict.h"
#include "studies/drivers/scene_study_output.h"
#include "studies/tools/bisection.h"
#include "studies/tools/cauchy_fit.h"
#include "studies/tools/format.h"
#include "studies/tools/scene_distance.h"

namespace thinlayer {

namespace {

// The paper family's (γ, δ) of the scene's layers, when they all share one and no bondline has
// an engineer's glue.
std::optional<std::pair<double, double>> scene_exponents(const SceneSpec& spec) {
  std::optional<std::pair<double, double>> out;
  for (const SceneInterfaceSpec& i : spec.interfaces) {
    if (i.glue) return std::nullopt;
    if (!i.layer) continue;
    const std::pair<double, double> e{i.layer->gamma, i.layer->delta};
    if (out && *out != e) return std::nullopt;
    out = e;
  }
  return out;
}

// A thickness to `digits` significant digits: the grid's t × 0.1 is 0.020000000000000004 in
// binary, and a bisection's log midpoint 0.031622776601683798; a scene's id and the report read
// them as 0.02 and 0.0316 (the thickness solved is the rounded one, so id and scene agree).
double round_significant(double x, int digits) {
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, x);
  return std::strtod(text, nullptr);
}

std::optional<double> predicted_rate(const SceneSpec& spec) {
  const auto e = scene_exponents(spec);
  if (!e) return std::nullopt;
  for (const PredictedRate& r : load_predicted_rates())
    if (r.gamma == e->first && r.delta == e->second) return r.p;
  return std::nullopt;
}

SolverOptions solver_options(const SceneStudyOptions& o) {
  SolverOptions solver;
  solver.tolerance = o.tolerance;
  return solver;
}

// Layer scenes at the given thicknesses, `threads` at a time (each builds its own model; no
// gmsh, no shared factorisation).
std::vector<SceneFileScene> solve_layers(const SceneFileBulk& bulk, const std::vector<double>& eps,
                                         const SceneStudyOptions& options) {
  std::vector<SceneFileScene> out(eps.size());
  std::vector<std::string> errors(eps.size());
  std::atomic<std::size_t> next{0};
  std::atomic<bool> out_of_memory{false};
  std::mutex print;
  const SolverOptions solver = solver_options(options);
  auto work = [&] {
    for (std::size_t i; (i = next++) < eps.size();) {
      try {
        out[i] = solve_scene_file_layer(bulk, eps[i], SolverKind::Fast, solver);
        if (options.verbose) {
          std::lock_guard<std::mutex> lock(print);
          std::cerr << "[scene] layer eps " << eps[i] << ": " << (out[i].report.converged ? "converged" : "NOT converged")
                    << ", " << out[i].report.wall_time_s << " s\n";
        }
      } catch (const std::bad_alloc&) {
        out_of_memory = true;  // the run's failure, not this thickness's: rethrown below as it is
      } catch (const std::exception& e) {
        errors[i] = e.what();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, options.threads); ++t) pool.emplace_back(work);
  for (auto& t : pool) t.join();
  if (out_of_memory) throw std::bad_alloc();
  for (std::size_t i = 0; i < eps.size(); ++i)
    if (!errors[i].empty()) throw std::invalid_argument("layer mode at eps " + plain(eps[i]) + ": " + errors[i]);
  return out;
}

// Both modes at some thicknesses: the layer scenes, and the limit scene each is measured against
// (one for every ε of an engineer's glue, whose law depends on it; else the shared one).
struct Solved {
  std::vector<SceneFileScene> layers, limits;
};

Solved solve_pairs(SceneFileBulk& bulk, const std::vector<double>& eps, const SceneStudyOptions& options,
                   const SceneFileScene* shared_limit) {
  Solved s;
  s.layers = solve_layers(bulk, eps, options);
  if (!shared_limit)
    for (double e : eps) s.limits.push_back(solve_scene_file_limit(bulk, SolverKind::Fast, solver_options(options), e));
  return s;
}

// One rule (core/solvers/stop_verdict.h): distances only between answers whose numbers may be used;
// otherwise every distance is NaN — never fitted, never bracketed — and `why` says what stopped.
std::string not_usable(const SceneFileScene& layer, const SceneFileScene& limit) {
  std::string why;
  if (!usable(layer.report)) why += "layer mode: " + layer.report.message;
  if (!usable(limit.report)) why += (why.empty() ? "" : "; ") + std::string("limit mode: ") + limit.report.message;
  return why;
}

void set_not_used(std::map<std::string, double>& distances) {
  for (auto& [q, e] : distances) e = std::nan("");
}

SceneSample sample_of(const SceneFileBulk& bulk, double eps, const SceneFileScene& layer, const SceneFileScene& limit,
                      double d) {
  SceneSample s;
  s.eps = eps;
  s.e = scene_distance(bulk, layer.record, limit.record, &s.status_diff);
  s.verdict = verdict_distance(bulk, layer.record, limit.record, d);
  s.not_used = not_usable(layer, limit);
  if (!s.not_used.empty()) set_not_used(s.e), set_not_used(s.verdict);
  s.layer_ends = peaks_at_distance(bulk, layer.record, d);
  s.limit_ends = peaks_at_distance(bulk, limit.record, d);
  s.converged = layer.report.converged && limit.report.converged;
  s.residual = std::max(layer.report.residual.value(), limit.report.residual.value());
  s.time_s = layer.report.wall_time_s;
  s.iterations = layer.report.iterations;
  s.id = layer.record.id;
  s.limit_id = limit.record.id;
  return s;
}

void add_peaks(const SceneFileBulk& bulk, const SceneFileScene& scene, double h, std::vector<ScenePeak>& peaks) {
  const SceneRecord& r = scene.record;
  const double eps = r.text.at("mode") == "layer" ? r.numbers.at("eps") : 0.0;
  for (const BondlineField& f : bondline_fields(bulk, r))
    peaks.push_back({r.id, r.text.at("mode"), f.bondline, eps, h, bondline_peaks(f)});
}

// S3 on the samples, per verdict quantity: for each quantity and τ the bracket between samples,
// then bisection rounds (the midpoints of every open bracket solved together).
void run_validity(SceneFileBulk& bulk, const SceneFileScene* shared_limit, const SceneStudyOptions& options,
                  SceneStudyResult& r, std::vector<SceneFileScene>& extra) {
  struct Job {
    SceneValidityRow row;
    Bracket bracket;
    bool bisect = false;
  };
  std::vector<SceneSample> by_eps;  // the samples whose numbers may be used, thinnest first
  bool all_converged = r.limit_converged;
  for (const SceneSample& s : r.samples) {
    all_converged = all_converged && s.converged;
    if (s.not_used.empty()) by_eps.push_back(s);
  }
  std::sort(by_eps.begin(), by_eps.end(), [](const auto& a, const auto& b) { return a.eps < b.eps; });
  std::vector<Job> jobs;
  for (const std::string& q : verdict_quantities())
    for (double tau : options.taus) {
      Job j;
      j.row.quantity = q;
      j.row.tau = tau;
      j.row.converged = all_converged;
      // The limit law "stays within τ" up to ε: at every sampled thickness from the thinnest up to it
      // (a distance that dips back under τ above a sample beyond it is no validity range).
      int within = -1;
      while (within + 1 < static_cast<int>(by_eps.size()) && by_eps[within + 1].verdict.at(q) <= tau) ++within;
      const bool judged = std::any_of(by_eps.begin(), by_eps.end(), [&](const SceneSample& s) { return !std::isnan(s.verdict.at(q)); });
      if (by_eps.empty()) {
        j.row.status = "not_judged";
        j.row.why_not_judged = "no sample's numbers may be used (none converged nor stopped at a proven floor)";
      } else if (!judged) {  // every reaction component is fixed by statics (scene_distance.h)
        j.row.status = "not_judged";
        j.row.why_not_judged = "statically determinate (" + determinate_reactions(reaction_components(bulk.model())) +
                               "): the same in every model";
      } else if (within + 1 == static_cast<int>(by_eps.size())) {
        j.row.status = "at_least";
        j.row.eps_max = by_eps.back().eps;
        j.row.error_at_eps_max = by_eps.back().verdict.at(q);
      } else if (within < 0) {
        j.row.status = "below_range";
        j.row.eps_max = j.row.eps_beyond = by_eps.front().eps;
        j.row.error_at_eps_max = by_eps.front().verdict.at(q);
      } else {
        j.row.status = "found";
        const SceneSample &lo = by_eps[within], &hi = by_eps[within + 1];
        j.bracket = {lo.eps, lo.verdict.at(q), hi.eps, hi.verdict.at(q)};
        j.bisect = true;
      }
      jobs.push_back(j);
    }
  for (int step = 0; step < options.bisection_steps; ++step) {
    std::vector<double> round;  // each thickness once: brackets of several quantities may share a midpoint
    // Each midpoint to 3 significant digits (its scene id reads as the thickness solved).
    auto midpoint = [](const Bracket& b) { return round_significant(log_midpoint(b), 3); };
    for (const Job& j : jobs)
      if (j.bisect && std::find(round.begin(), round.end(), midpoint(j.bracket)) == round.end())
        round.push_back(midpoint(j.bracket));
    if (round.empty()) break;
    Solved solved = solve_pairs(bulk, round, options, shared_limit);
    for (Job& j : jobs) {
      if (!j.bisect) continue;
      const double mid = midpoint(j.bracket);
      const std::size_t k = static_cast<std::size_t>(std::find(round.begin(), round.end(), mid) - round.begin());
      const SceneFileScene& limit = shared_limit ? *shared_limit : solved.limits[k];
      const SceneFileScene& s = solved.layers[k];
      j.row.converged = j.row.converged && s.report.converged && limit.report.converged;
      if (!not_usable(s, limit).empty()) {  // the midpoint's numbers may not be used: the bracket stays
        j.bisect = false;
        continue;
      }
      const double e = verdict_distance(bulk, s.record, limit.record, r.peak_distance).at(j.row.quantity);
      j.bracket = narrow(j.bracket, mid, e, j.row.tau);
      ++j.row.bisection_steps;
    }
    for (auto& s : solved.layers) extra.push_back(std::move(s));
    for (auto& s : solved.limits) extra.push_back(std::move(s));
  }
  for (Job& j : jobs) {
    if (j.row.status == "found") {
      j.row.eps_max = j.bracket.eps_within;
      j.row.error_at_eps_max = j.bracket.error_within;
      j.row.eps_beyond = j.bracket.eps_beyond;
    }
    r.validity.push_back(j.row);
  }
}

// The mesh floor: both modes at a thickness far below the grid, on the scene re-meshed with the
// element size along the bondlines (and far from them) halved level by level.
void run_floor(const SceneFileBulk& bulk, double eps, const SceneStudyOptions& options, SceneStudyResult& r,
               std::vector<FloorScenes>& scenes) {
  const SceneSpec& spec = bulk.spec();
  if (options.floor_levels < 2 || spec.geometry.empty() || !spec.h_interface) return;
  for (int level = 0; level < options.floor_levels; ++level) {
    SceneSpec refined = spec;
    const double factor = std::pow(0.5, level);
    refined.h_interface = *spec.h_interface * factor;
    refined.h_far = *spec.h_far * factor;
    FloorScenes s{std::make_unique<SceneFileBulk>(refined), {}, {}};
    s.layer = solve_scene_file_layer(*s.bulk, eps, SolverKind::Fast, solver_options(options));
    s.limit = solve_scene_file_limit(*s.bulk, SolverKind::Fast, solver_options(options), eps);
    const std::string suffix = "-h" + scene_id_number(*refined.h_interface);  // apart from the study's own scenes
    s.layer.record.id += suffix;
    s.limit.record.id += suffix;
    SceneFloorRow row;
    row.h = *refined.h_interface;
    for (const SceneInterfaceNodes& S : s.bulk->interface_nodes()) row.S_nodes += static_cast<int>(S.plus.size());
    row.eps = eps;
    row.e = scene_distance(*s.bulk, s.layer.record, s.limit.record);
    row.verdict = verdict_distance(*s.bulk, s.layer.record, s.limit.record, r.peak_distance);
    row.layer_ends = peaks_at_distance(*s.bulk, s.layer.record, r.peak_distance);
    row.limit_ends = peaks_at_distance(*s.bulk, s.limit.record, r.peak_distance);
    row.converged = s.layer.report.converged && s.limit.report.converged;
    row.not_used = not_usable(s.layer, s.limit);
    if (!row.not_used.empty()) set_not_used(row.e), set_not_used(row.verdict);
    row.layer_id = s.layer.record.id;
    row.limit_id = s.limit.record.id;
    add_peaks(*s.bulk, s.limit, row.h, r.peaks);
    add_peaks(*s.bulk, s.layer, row.h, r.peaks);
    if (options.verbose)
      std::cerr << "[scene] mesh floor at h " << row.h << " mm (" << row.S_nodes << " nodes on S): "
                << (row.converged ? "converged" : "NOT converged") << "\n";
    r.floor.push_back(row);
    scenes.push_back(std::move(s));
  }
  std::vector<double> h;
  for (const SceneFloorRow& row : r.floor) h.push_back(row.h);
  for (const std::string& q : scene_distance_quantities()) {
    std::vector<double> e;
    for (const SceneFloorRow& row : r.floor) e.push_back(row.e.at(q));
    r.floor_rate[q] = h.size() >= 3 ? fit_power_law(h, e) : std::nullopt;
  }
}

// The thickness of the mesh-floor study: for the paper's family far below the grid (the floor
// proper: its ε part vanishes); for an engineer's glue its own thickness, the joint as glued (the
// floor of a glue that stiffens as it thins says nothing of it: at t → 0 both modes are rigid
// and the shear-lag zone that the mesh must resolve, of width ~ √(E_a t_a t / G_g), is gone).
double floor_thickness(const SceneFileBulk& bulk, const std::vector<double>& eps, const SceneStudyOptions& options) {
  double t = 0;
  for (const SceneInterfaceSpec& i : bulk.spec().interfaces)
    if (i.glue) t = std::max(t, i.glue->thickness);
  return t > 0 ? std::min(t, bulk.thickest_layer()) : eps.back() * options.floor_eps_factor;
}

void add_checks(const SceneSpec& spec, const SceneStudyOptions& options, SceneStudyResult& r) {
  const std::string id = "scene." + spec.name;
  r.checks.push_back({id + ".limit_converged", r.limit_converged, "limit-mode residual <= " + sci(options.tolerance, 0),
                      sci(r.limit_residual, 1), sci(options.tolerance, 0)});
  int converged = 0;
  for (const SceneSample& s : r.samples) converged += s.converged;
  r.checks.push_back({id + ".layer_converged", converged == static_cast<int>(r.samples.size()),
                      std::to_string(r.samples.size()) + " layer scenes at residual <= " + sci(options.tolerance, 0),
                      std::to_string(converged), sci(options.tolerance, 0)});
  if (r.family != "scaled") return;  // an engineer's glue changes its law with t: no monotone distance to expect
  bool decreasing = true;
  for (std::size_t i = 1; i < r.samples.size(); ++i) decreasing = decreasing && r.samples[i].e.at("u") < r.samples[i - 1].e.at("u");
  r.checks.push_back({id + ".u_distance_decreasing", decreasing, "distance u strictly decreasing as eps decreases",
                      sci(r.samples.front().e.at("u"), 2) + " at eps " + plain(r.samples.front().eps) + " ... " +
                          sci(r.samples.back().e.at("u"), 2) + " at eps " + plain(r.samples.back().eps),
                      "0"});
  // As the dovetail's S2 check: the rate of u from the layer model's Cauchy differences (SPEC §3
  // S2 item 1: the mesh floor cancels) against the asymptotics' prediction for the scene's (γ, δ),
  // where the prediction exists (studies/convergence_rates.md). (Until issue 27 the floored fit
  // e ≈ e_∞ + C ε^p was checked; where the floor is 1e4 times the ε part, as on the dovetail's
  // grid below 1e-3, that fit cannot resolve p: 1.21-1.26 on the bonded-law scenes whose Cauchy
  // rate is 1.00 ± 0.00. It is still printed and stored.)
  // Since issue 36 the rate is read where the grid ends — the last three differences, their local
  // slopes settled (SPEC §3 S2 item 3) — not fitted through the whole grid: a whole-grid fit averages
  // in the range where another term still weighs (the bonded laws' (b) contact/bonded: 0.66 through
  // 1e-3 ... 1e-6, whose O(ε) remainder dominates above 1e-4, 0.44 on the tail; studies/convergence_rates.md).
  if (r.p_predicted) {
    const CauchyTail& tail = r.cauchy_tail.at("u");
    const auto& f = tail.fit;
    const bool pass = f && tail.settled && std::abs(f->p - *r.p_predicted) <= options.rate_tolerance;
    std::string got = rate_text(f) + " (last three differences; local slopes";
    const std::size_t n = tail.local_slopes.size();
    for (std::size_t k = n > 2 ? n - 2 : 0; k < n; ++k) got += " " + fixed(tail.local_slopes[k], 2);
    got += tail.settled ? ", settled)" : ", NOT settled: extend the grid)";
    r.checks.push_back({id + ".rate", pass,
                        "p(u, the last three Cauchy differences, local slopes settled within 0.1) = " +
                            plain(*r.p_predicted) + " +- " + plain(options.rate_tolerance),
                        got, plain(options.rate_tolerance)});
  }
}

// d of the peaks at a distance from the bondline ends (SceneStudyOptions::peak_distance).
void choose_peak_distance(const SceneFileBulk& bulk, const std::vector<double>& eps, const SceneStudyOptions& options,
                          SceneStudyResult& r) {
  if (options.peak_distance > 0) {
    r.peak_distance = options.peak_distance;
    r.peak_distance_reason = "given (--peak-distance)";
    return;
  }
  double t = 0;
  for (const SceneInterfaceSpec& i : bulk.spec().interfaces)
    if (i.glue) t = std::max(t, i.glue->thickness);
  const bool engineer = t > 0;
  if (!engineer) t = eps.front();
  // The element size along the bondlines: the scene's mesh_size, or the mean segment of its bondlines.
  double h = bulk.spec().h_interface.value_or(0.0);
  if (!(h > 0)) {
    double length = 0;
    int segments = 0;
    for (const Interface& S : bulk.limit_interfaces(0, false))
      for (std::size_t k = 1; k < S.nodes.size(); ++k, ++segments) length += (S.nodes[k].x - S.nodes[k - 1].x).norm();
    h = segments ? length / segments : 0.0;
  }
  r.peak_distance = std::max(t, 2 * h);
  r.peak_distance_reason = std::string("the larger of ") + (engineer ? "the glue's own thickness" : "the thickest eps of the grid") +
                           " (" + plain(t) + " mm) and two elements of the study's mesh (2 x " + plain(h) + " mm)";
}

}  // namespace

std::vector<double> scene_study_grid(const SceneFileBulk& bulk, const SceneStudyOptions& options) {
  const SceneSpec& spec = bulk.spec();
  std::vector<double> eps = spec.eps;
  if (eps.empty() && spec.engineer_glue_only()) {
    double t = 0;
    for (const SceneInterfaceSpec& i : spec.interfaces)
      if (i.glue) t = std::max(t, i.glue->thickness);
    for (double factor : {5.0, 2.0, 1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01})
      if (factor * t <= bulk.thickest_layer()) eps.push_back(round_significant(factor * t, 12));
  }
  if (eps.empty()) eps = options.eps;
  std::sort(eps.rbegin(), eps.rend());
  eps.erase(std::unique(eps.begin(), eps.end()), eps.end());
  return eps;
}

SceneStudyResult run_scene_study(SceneFileBulk& bulk, const SceneStudyOptions& options, H5Writer* out) {
  const SceneSpec& spec = bulk.spec();
  if (!spec.has_layer())
    throw std::invalid_argument("scene '" + spec.name + "' gives limit laws only ('law'): it has no layer mode to study");
  const std::vector<double> eps = scene_study_grid(bulk, options);
  if (eps.size() < 3) throw std::invalid_argument("the convergence study needs at least 3 thicknesses (the joint holds " +
                                                  std::to_string(eps.size()) + " of the grid)");
  for (double e : eps) check_layer_mode(bulk, e);

  SceneStudyResult r;
  r.family = bulk.has_engineer_glue() ? "engineer" : "scaled";
  r.p_predicted = predicted_rate(spec);
  choose_peak_distance(bulk, eps, options, r);
  // The paper's family: one limit scene for every ε; an engineer's glue: one per ε.
  std::optional<SceneFileScene> shared;
  if (r.family == "scaled") shared = solve_scene_file_limit(bulk, SolverKind::Fast, solver_options(options));
  Solved solved = solve_pairs(bulk, eps, options, shared ? &*shared : nullptr);
  const auto limit_of = [&](std::size_t i) -> const SceneFileScene& { return shared ? *shared : solved.limits[i]; };

  r.limit_id = limit_of(0).record.id;
  r.limit_converged = true;
  for (std::size_t i = 0; i < eps.size(); ++i) {
    r.limit_converged = r.limit_converged && limit_of(i).report.converged;
    r.limit_residual = std::max(r.limit_residual, limit_of(i).report.residual.value());
  }
  const double h = spec.h_interface.value_or(0.0);
  for (std::size_t i = 0; i < eps.size(); ++i) {
    r.samples.push_back(sample_of(bulk, eps[i], solved.layers[i], limit_of(i), r.peak_distance));
    add_peaks(bulk, solved.layers[i], h, r.peaks);
    if (!shared || i == 0) add_peaks(bulk, limit_of(i), h, r.peaks);
  }
  for (const std::string& q : scene_distance_quantities()) {
    std::vector<double> e;
    for (const SceneSample& s : r.samples) e.push_back(s.e.at(q));
    r.fit[q] = fit_power_law(eps, e);
    r.floor_fit[q] = fit_power_law_with_floor(eps, e);
  }
  // The layer model's own differences along ε: the mesh floor cancels (SPEC §3 S2, item 1).
  for (std::size_t i = 0; i + 1 < eps.size(); ++i) {
    auto d = scene_distance(bulk, solved.layers[i].record, solved.layers[i + 1].record);
    if (!usable(solved.layers[i].report) || !usable(solved.layers[i + 1].report)) set_not_used(d);
    for (const std::string& q : scene_distance_quantities()) r.cauchy[q].push_back(d.at(q));
  }
  for (const std::string& q : scene_distance_quantities()) {
    r.cauchy_fit[q] = fit_cauchy_differences(eps, r.cauchy.at(q));
    r.cauchy_tail[q] = fit_cauchy_tail(eps, r.cauchy.at(q));
  }

  // The classical closed forms at the glue's own thickness (an engineer's glue: the sample nearest it).
  if (r.family == "engineer") {
    const double t = floor_thickness(bulk, eps, options);
    for (std::size_t i = 0; i < eps.size(); ++i)
      if (std::abs(std::log(eps[i] / t)) < std::abs(std::log(eps[r.nominal] / t))) r.nominal = i;
    r.closed_forms = joint_closed_forms(bulk, limit_of(r.nominal).record);
  }

  print_scene_study(bulk, r, options);
  std::vector<FloorScenes> floor_scenes;
  run_floor(bulk, floor_thickness(bulk, eps, options), options, r, floor_scenes);
  print_scene_floor(r);

  std::vector<SceneFileScene> extra;
  print_scene_ends(r);
  if (options.validity) {
    run_validity(bulk, shared ? &*shared : nullptr, options, r, extra);
    print_scene_validity(r, options.bisection_steps);
  }
  add_checks(spec, options, r);
  if (out) {
    std::vector<const SceneFileScene*> scenes;
    if (shared) scenes.push_back(&*shared);
    for (const SceneFileScene& s : solved.limits) scenes.push_back(&s);
    for (const SceneFileScene& s : solved.layers) scenes.push_back(&s);
    for (const SceneFileScene& s : extra) scenes.push_back(&s);
    write_scene_study(*out, bulk, r, options, scenes, floor_scenes);
  }
  return r;
}

}  // namespace thinlayer
