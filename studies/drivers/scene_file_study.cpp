#include "studies/drivers/scene_file_study.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "core/io/column_table.h"
#include "core/io/reference_tables.h"
#include "studies/tools/bisection.h"
#include "studies/tools/scene_distance.h"
#include "studies/tools/format.h"

namespace thinlayer {

namespace {

std::optional<double> predicted_rate(const SceneSpec& spec) {
  if (!spec.has_layer()) return std::nullopt;
  for (const PredictedRate& r : load_predicted_rates())
    if (r.gamma == spec.interface.layer->gamma && r.delta == spec.interface.layer->delta) return r.p;
  return std::nullopt;
}

// Layer scenes at the given thicknesses, `threads` at a time (each builds its own model; no
// gmsh, no shared factorisation).
std::vector<SceneFileScene> solve_layers(const SceneFileBulk& bulk, const std::vector<double>& eps,
                                         const SceneStudyOptions& options) {
  std::vector<SceneFileScene> out(eps.size());
  std::vector<std::string> errors(eps.size());
  std::atomic<std::size_t> next{0};
  std::mutex print;
  SolverOptions solver;
  solver.tolerance = options.tolerance;
  auto work = [&] {
    for (std::size_t i; (i = next++) < eps.size();) {
      try {
        out[i] = solve_scene_file_layer(bulk, eps[i], SolverKind::Fast, solver);
        if (options.verbose) {
          std::lock_guard<std::mutex> lock(print);
          std::cerr << "[scene] layer eps " << eps[i] << ": " << (out[i].report.converged ? "converged" : "NOT converged")
                    << ", " << out[i].report.wall_time_s << " s\n";
        }
      } catch (const std::exception& e) {
        errors[i] = e.what();
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, options.threads); ++t) pool.emplace_back(work);
  for (auto& t : pool) t.join();
  for (std::size_t i = 0; i < eps.size(); ++i)
    if (!errors[i].empty()) throw std::invalid_argument("layer mode at eps " + plain(eps[i]) + ": " + errors[i]);
  return out;
}

SceneSample sample_of(const SceneFileBulk& bulk, double eps, const SceneFileScene& layer, const SceneFileScene& limit) {
  SceneSample s;
  s.eps = eps;
  s.e = scene_distance(bulk, layer.record, limit.record, &s.status_diff);
  s.converged = layer.report.converged;
  s.residual = layer.report.residual.value();
  s.time_s = layer.report.wall_time_s;
  s.iterations = layer.report.iterations;
  s.id = layer.record.id;
  return s;
}

void print_samples(const SceneStudyResult& r) {
  std::printf("  %-8s", "eps");
  for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", q.c_str());
  std::printf(" %5s %5s %9s %8s\n", "diff", "it", "residual", "time[s]");
  for (const SceneSample& s : r.samples) {
    std::printf("  %-8g", s.eps);
    for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", sci(s.e.at(q), 2).c_str());
    std::printf(" %5d %5d %9s %8.2f%s\n", s.status_diff, s.iterations, sci(s.residual, 1).c_str(), s.time_s,
                s.converged ? "" : "  NOT converged");
  }
  print_fit_rows(scene_distance_quantities(), r.fit, r.floor_fit, 8, 10);
}

// S3 on the samples: for each τ the bracket between samples, then bisection rounds (the
// midpoints of every open bracket solved together).
void run_validity(const SceneFileBulk& bulk, const SceneFileScene& limit, const SceneStudyOptions& options,
                  SceneStudyResult& r, std::vector<SceneFileScene>& extra) {
  struct Job {
    SceneValidityRow row;
    Bracket bracket;
    bool bisect = false;
  };
  std::vector<SceneSample> by_eps = r.samples;
  std::sort(by_eps.begin(), by_eps.end(), [](const auto& a, const auto& b) { return a.eps < b.eps; });
  bool all_converged = limit.report.converged;
  for (const SceneSample& s : by_eps) all_converged = all_converged && s.converged;
  std::vector<Job> jobs;
  for (double tau : options.taus) {
    Job j;
    j.row.tau = tau;
    j.row.converged = all_converged;
    int within = -1;
    for (std::size_t k = 0; k < by_eps.size(); ++k)
      if (by_eps[k].e.at("u") <= tau) within = static_cast<int>(k);
    if (by_eps.back().e.at("u") <= tau) {
      j.row.status = "at_least";
      j.row.eps_max = by_eps.back().eps;
      j.row.error_at_eps_max = by_eps.back().e.at("u");
    } else if (within < 0) {
      j.row.status = "below_range";
      j.row.eps_max = j.row.eps_beyond = by_eps.front().eps;
      j.row.error_at_eps_max = by_eps.front().e.at("u");
    } else {
      j.row.status = "found";
      const SceneSample &lo = by_eps[within], &hi = by_eps[within + 1];
      j.bracket = {lo.eps, lo.e.at("u"), hi.eps, hi.e.at("u")};
      j.bisect = true;
    }
    jobs.push_back(j);
  }
  for (int step = 0; step < options.bisection_steps; ++step) {
    std::vector<double> round;
    for (const Job& j : jobs)
      if (j.bisect) round.push_back(log_midpoint(j.bracket));
    if (round.empty()) break;
    std::vector<SceneFileScene> solved = solve_layers(bulk, round, options);
    std::size_t k = 0;
    for (Job& j : jobs) {
      if (!j.bisect) continue;
      const SceneFileScene& s = solved[k++];
      const double e = scene_distance(bulk, s.record, limit.record).at("u");
      j.bracket = narrow(j.bracket, log_midpoint(j.bracket), e, j.row.tau);
      j.row.converged = j.row.converged && s.report.converged;
      ++j.row.bisection_steps;
    }
    for (auto& s : solved) extra.push_back(std::move(s));
  }
  for (Job& j : jobs) {
    if (j.bisect) {
      j.row.eps_max = j.bracket.eps_within;
      j.row.error_at_eps_max = j.bracket.error_within;
      j.row.eps_beyond = j.bracket.eps_beyond;
    }
    r.validity.push_back(j.row);
  }
}

void print_validity(const SceneStudyResult& r, int steps) {
  std::printf("\nThickness validity (S3): the largest eps (mm) at which the limit law stays within tau of the layer\n"
              "model (distance of the adherents' displacements, 'u'), %d bisection steps on log eps between samples\n\n",
              steps);
  std::printf("%-5s | %-11s %-10s %-11s %-11s\n", "tau", "eps_max", "error", "first eps>", "status");
  for (const SceneValidityRow& v : r.validity)
    std::printf("%-5g | %-11s %-10s %-11s %-11s%s\n", v.tau,
                (v.status == "at_least" ? ">= " + sci(v.eps_max, 1) : v.status == "below_range" ? "< " + sci(v.eps_max, 1)
                                                                                                 : sci(v.eps_max, 2))
                    .c_str(),
                sci(v.error_at_eps_max, 2).c_str(), v.status == "found" ? sci(v.eps_beyond, 2).c_str() : "-",
                v.status.c_str(), v.converged ? "" : "  (a scene did not converge)");
}

void write_study(H5Writer& out, const SceneFileBulk& bulk, const SceneStudyResult& r, const SceneStudyOptions& o) {
  const std::string g = "/studies/scene/" + bulk.spec().name;
  std::vector<double> eps;
  std::vector<int> diff, converged;
  std::vector<std::string> ids;
  for (const SceneSample& s : r.samples) {
    eps.push_back(s.eps);
    diff.push_back(s.status_diff);
    converged.push_back(s.converged ? 1 : 0);
    ids.push_back(s.id);
  }
  out.dataset(g + "/eps", eps);
  out.dataset(g + "/status_diff", diff);
  out.dataset(g + "/converged", converged);
  out.dataset(g + "/layer_scene", ids);
  for (const std::string& q : scene_distance_quantities()) {
    std::vector<double> e;
    for (const SceneSample& s : r.samples) e.push_back(s.e.at(q));
    out.dataset(g + "/e_" + q, e);
    const auto& f = r.fit.at(q);
    out.attr(g, "p_" + q, f ? f->p : 0.0);
    out.attr(g, "p_" + q + "_stderr", f ? f->p_stderr : 0.0);
    out.attr(g, "fitted_" + q, f ? 1 : 0);
    const auto& ff = r.floor_fit.at(q);
    out.attr(g, "p_floor_" + q, ff ? ff->p : 0.0);
    out.attr(g, "floor_" + q, ff ? ff->floor : 0.0);
    out.attr(g, "fitted_floor_" + q, ff ? 1 : 0);
  }
  out.attr(g, "scene_file", bulk.spec().file);
  out.attr(g, "limit_scene", r.limit_id);
  out.attr(g, "tolerance", o.tolerance);
  out.attr(g, "p_predicted", r.p_predicted ? *r.p_predicted : -1.0);
  out.attr(g, "table1_case", std::string(1, bulk.spec().limit_law().table1_case()));
  if (!r.validity.empty()) {
    ColumnTable table;
    for (const SceneValidityRow& v : r.validity) {
      table.add("tau", v.tau);
      table.add("status", v.status);
      table.add("eps_max", v.eps_max);
      table.add("error_at_eps_max", v.error_at_eps_max);
      table.add("eps_beyond", v.eps_beyond);
      table.add("bisection_steps", v.bisection_steps);
      table.add("converged", v.converged ? 1 : 0);
    }
    table.write(out, g + "/validity");
  }
}

}  // namespace

SceneStudyResult run_scene_study(SceneFileBulk& bulk, const SceneStudyOptions& options, H5Writer* out) {
  const SceneSpec& spec = bulk.spec();
  if (!spec.has_layer()) throw std::invalid_argument("scene '" + spec.name + "' gives a limit law only ('law'): it has no layer mode to study");
  std::vector<double> eps = spec.eps.empty() ? options.eps : spec.eps;
  std::sort(eps.rbegin(), eps.rend());
  if (eps.size() < 3) throw std::invalid_argument("the convergence study needs at least 3 thicknesses");
  for (double e : eps) check_layer_mode(bulk, e);
  SolverOptions solver;
  solver.tolerance = options.tolerance;
  const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, solver);
  std::vector<SceneFileScene> layers = solve_layers(bulk, eps, options);

  SceneStudyResult r;
  r.limit_id = limit.record.id;
  r.limit_converged = limit.report.converged;
  r.limit_residual = limit.report.residual.value();
  r.p_predicted = predicted_rate(spec);
  for (std::size_t i = 0; i < eps.size(); ++i) r.samples.push_back(sample_of(bulk, eps[i], layers[i], limit));
  std::vector<double> eps_list;
  for (const SceneSample& s : r.samples) eps_list.push_back(s.eps);
  for (const std::string& q : scene_distance_quantities()) {
    std::vector<double> e;
    for (const SceneSample& s : r.samples) e.push_back(s.e.at(q));
    r.fit[q] = fit_power_law(eps_list, e);
    r.floor_fit[q] = fit_power_law_with_floor(eps_list, e);
  }

  const InterfaceLaw law = spec.limit_law();
  std::printf("\nScene %s (%s): convergence (S2), layer mode at each eps (mm) against the limit law\n"
              "(Table 1 case %c: lambda_bar %g, mu_bar %g daN/mm^3, f %g); relative L2 distances; diff: S nodes whose\n"
              "combined status differs; limit mode %s, residual %s; scenes solved to residual %g\n",
              spec.name.c_str(), spec.file.c_str(), law.table1_case(), law.lambda_bar, law.mu_bar, law.friction,
              r.limit_converged ? "converged" : "NOT converged", sci(r.limit_residual, 1).c_str(), options.tolerance);
  print_samples(r);
  if (r.p_predicted)
    std::printf("  predicted p = %g (the Table 2 case with gamma %g, delta %g; studies/convergence_rates.md)\n", *r.p_predicted,
                spec.interface.layer->gamma, spec.interface.layer->delta);

  std::vector<SceneFileScene> extra;
  if (options.validity) {
    run_validity(bulk, limit, options, r, extra);
    print_validity(r, options.bisection_steps);
  }

  const std::string id = "scene." + spec.name;
  r.checks.push_back({id + ".limit_converged", r.limit_converged, "limit-mode residual <= " + sci(options.tolerance, 0),
                      sci(r.limit_residual, 1), sci(options.tolerance, 0)});
  int converged = 0;
  for (const SceneSample& s : r.samples) converged += s.converged;
  r.checks.push_back({id + ".layer_converged", converged == static_cast<int>(r.samples.size()),
                      std::to_string(r.samples.size()) + " layer scenes at residual <= " + sci(options.tolerance, 0),
                      std::to_string(converged), sci(options.tolerance, 0)});
  bool decreasing = true;
  for (std::size_t i = 1; i < r.samples.size(); ++i) decreasing = decreasing && r.samples[i].e.at("u") < r.samples[i - 1].e.at("u");
  r.checks.push_back({id + ".u_distance_decreasing", decreasing, "distance u strictly decreasing as eps decreases",
                      sci(r.samples.front().e.at("u"), 2) + " at eps " + plain(r.samples.front().eps) + " ... " +
                          sci(r.samples.back().e.at("u"), 2) + " at eps " + plain(r.samples.back().eps),
                      "0"});
  // As the dovetail's S2 check: the floored rate of u against the asymptotics' prediction for
  // the scene's (γ, δ), where the prediction exists (studies/convergence_rates.md).
  if (r.p_predicted) {
    const auto& f = r.floor_fit.at("u");
    const bool pass = f && std::abs(f->p - *r.p_predicted) <= options.rate_tolerance;
    r.checks.push_back({id + ".rate", pass,
                        "p(u, floored fit) = " + plain(*r.p_predicted) + " +- " + plain(options.rate_tolerance),
                        rate_text(f), plain(options.rate_tolerance)});
  }
  if (out) {
    write_study(*out, bulk, r, options);
    std::set<std::string> written;  // two brackets may bisect at the same ε
    auto write_once = [&](const SceneRecord& rec) {
      if (written.insert(rec.id).second) write_scene(*out, rec);
    };
    write_once(limit.record);
    for (const SceneFileScene& s : layers) write_once(s.record);
    for (const SceneFileScene& s : extra) write_once(s.record);
  }
  return r;
}

}  // namespace thinlayer
