#include "studies/drivers/scene_solve_output.h"

#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cases/film_admissibility.h"
#include "studies/tools/format.h"

namespace thinlayer {

namespace {

nlohmann::json counts_json(const StatusCount& c) { return {{"gap", c.gap}, {"slide", c.slide}, {"stick", c.stick}}; }

nlohmann::json vector_json(const Eigen::Vector2d& v) { return nlohmann::json::array({v.x(), v.y()}); }

void print_counts(const char* what, const StatusCount& c) {
  std::printf("  %-9s gap %3d  slide %3d  stick %3d\n", what, c.gap, c.slide, c.stick);
}

}  // namespace

void print_scene_solve(const SceneFileBulk& bulk, const std::string& mode, double eps, const SceneFileScene& s) {
  const SceneSpec& spec = bulk.spec();
  std::printf("scene %s (%s), %s mode%s; units %s (stresses in %s)\n", spec.name.c_str(), spec.file.c_str(), mode.c_str(),
              mode == "layer" && eps > 0 ? (" at eps " + plain(eps) + " mm").c_str() : "", spec.units.name().c_str(),
              spec.units.stress().c_str());
  for (std::size_t i = 0; i < spec.interfaces.size(); ++i) {
    const SceneInterfaceSpec& b = spec.interfaces[i];
    const SceneBondline& state = s.bondlines.at(i);
    std::printf("  %s (plus %s, minus %s; faces %s/%s): limit law %s, lambda_bar %g, mu_bar %g %s", b.label().c_str(),
                b.plus.c_str(), b.minus.c_str(), to_string(b.faces.plus), to_string(b.faces.minus),
                state.law.describe().c_str(), state.law.lambda_bar, state.law.mu_bar, spec.units.stiffness().c_str());
    if (!state.law.bilateral) std::printf(", f %g", state.law.friction);
    if (b.glue) {
      const double t = eps > 0 ? eps : b.glue->thickness;
      std::printf("; glue E %g, nu %g, t %g mm: its own springs at %g mm, K_N = (lambda_g+2mu_g)/t = %g, K_T = mu_g/t = %g "
                  "(SPEC 1.3)", b.glue->E, b.glue->nu, b.glue->thickness, t, state.law.K_N(), state.law.K_T());
      const InterfaceLaw& c = state.classified;
      if (c.table1_case() != state.law.table1_case() || c.lambda_bar != state.law.lambda_bar || c.mu_bar != state.law.mu_bar)
        std::printf("; the paper's 3 %% / 30x rule (L = %g mm) would choose class (%c), lambda_bar %g, mu_bar %g%s",
                    bulk.characteristic_length(), c.table1_case(), c.lambda_bar, c.mu_bar,
                    mode == "layer" ? " (not solved here: --mode limit solves it and says what it would cost)" : "");
      else
        std::printf("; the paper's 3 %% / 30x rule (L = %g mm) keeps it", bulk.characteristic_length());
    }
    if (state.thickness > 0)
      std::printf("; layer %g mm, lambda_eps %g, mu_eps %g", state.thickness, state.moduli.lambda, state.moduli.mu);
    std::printf("\n");
  }
  std::printf("  meshes:");
  for (std::size_t b = 0; b < spec.bodies.size(); ++b)
    std::printf(" %s %d nodes%s", spec.bodies[b].name.c_str(), bulk.meshes().bodies[b].num_nodes(),
                bulk.model().bodies[b].floating ? " (held by its bondlines alone)" : "");
  int nodes = 0;
  for (const SceneInterfaceNodes& S : bulk.interface_nodes()) nodes += static_cast<int>(S.plus.size());
  std::printf("; %d nodes on S; meshed in %.3f s\n", nodes, bulk.meshes().meshing_time_s);
  if (mode == "limit") {
    print_counts("S", s.limit);
  } else {
    const MeshQuality& q = s.layer_quality;
    if (q.cells > 0)
      std::printf("  %s: %d Q1 cells, angles %.1f..%.1f deg, aspect ratio up to %.3g\n",
                  bulk.spec().interfaces.size() > 1 ? "layers, all together" : "layer", q.cells, q.min_angle_deg,
                  q.max_angle_deg, q.max_aspect_ratio);
    print_counts("S+", s.counts.plus_face);
    print_counts("S-", s.counts.minus_face);
    print_counts("combined", s.counts.combined);
    if (const std::string film = film_line(s.record); !film.empty()) std::printf("  %s\n", film.c_str());
  }
  const auto& n = s.record.numbers;
  if (n.count("displacement_over_size")) {
    std::printf("  displacements: largest |u| %.3g mm, %.3g %% of the size of body '%s' (%.3g mm)",
                n.at("displacement_max"), 100 * n.at("displacement_over_size"), s.record.text.at("displacement_body").c_str(),
                n.at("displacement_body_size"));
    if (n.count("slip_over_h")) std::printf("; largest slip on the bondlines %.3g elements along S", n.at("slip_over_h"));
    std::printf("\n");
  }
  const SolveReport& r = s.report;
  const std::string outcome = r.converged ? "converged" : std::string("NOT converged (") + to_string(r.stop_cause) + ")";
  std::printf("  %s after %d iterations; residual %.3e (interface %.3e, bulk %.3e), tolerance %.0e\n", outcome.c_str(),
              r.iterations, r.residual.value(), r.residual.interface, r.residual.bulk, r.tolerance);
  std::printf("  time: solve %.4f s, setup %.4f s\n", r.wall_time_s, s.record.numbers.at("setup_time_s"));
  const std::string force = spec.units.force + "/mm";
  std::printf("  reactions (%s):", force.c_str());
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const auto& [name, R] : s.record.reactions) {
    std::printf(" %s (%.6g, %.6g)", name.c_str(), R.x(), R.y());
    sum += R;
  }
  std::printf("\n");
  if (!s.loads.empty()) {
    std::printf("  loads (%s):", force.c_str());
    for (const auto& [name, F] : s.loads) {
      std::printf(" %s (%.6g, %.6g)", name.c_str(), F.x(), F.y());
      sum += F;
    }
    std::printf("\n");
  }
  std::printf("  reactions + loads = (%.3g, %.3g) %s\n", sum.x(), sum.y(), force.c_str());
}

nlohmann::json solve_report_json(const SolveReport& report) {
  return {{"solver", report.solver},
          {"solver_method", report.method},
          {"converged", report.converged},
          {"stop_cause", to_string(report.stop_cause)},
          {"iterations", report.iterations},
          {"residual", {{"value", report.residual.value()}, {"interface", report.residual.interface},
                        {"bulk", report.residual.bulk}, {"tolerance", report.tolerance},
                        {"roundoff_floor", report.residual.floor()}}}};
}

nlohmann::json status_counts_json(const SceneRecord& record) {
  nlohmann::json counts;
  for (const InterfaceFields& f : record.interfaces) counts[f.name] = counts_json(f.counts());
  if (!record.combined_status.empty()) {
    std::vector<NodeStatus> combined;
    for (int v : record.combined_status) combined.push_back(static_cast<NodeStatus>(v));
    counts["combined"] = counts_json(count_statuses(combined));
  }
  return counts;
}

std::string scene_solve_json(const SceneFileBulk& bulk, const std::string& scene_file, const std::string& mode,
                             const SceneFileScene& s, const std::string& out, const std::string& vtu,
                             const ClassificationCost* cost) {
  const SceneRecord& record = s.record;
  const SolveReport& report = s.report;
  const nlohmann::json counts = status_counts_json(record);
  nlohmann::json reactions = nlohmann::json::object(), loads = nlohmann::json::object();
  for (const auto& [name, R] : record.reactions) reactions[name] = vector_json(R);
  for (const auto& [name, F] : s.loads) loads[name] = vector_json(F);
  nlohmann::json j = {
      {"scene", record.id},
      {"case", record.text.at("case")},
      {"scene_file", scene_file},
      {"mode", mode},
      {"law_case", record.text.at("law_case")},
      {"units", bulk.spec().units.name()},
      {"counts", counts},
      {"carries_load", s.carries_load},
      {"carried", {{"bondline_force", s.bondline_force}, {"force_scale", s.force_scale}}},
      {"reactions", reactions},
      {"loads", loads},
      {"force_units", bulk.spec().units.force + "/mm"},
      {"times_s", {{"solve", report.wall_time_s}, {"setup", record.numbers.at("setup_time_s")},
                   {"meshing", record.numbers.at("meshing_time_s")}}},
      {"out", out.empty() ? nullptr : nlohmann::json(out)},
      {"vtu", vtu.empty() ? nullptr : nlohmann::json(vtu)},
  };
  j.update(solve_report_json(report));
  // Each bondline's law (K = inf is null in JSON) and what the paper's rule would choose (SPEC 1.3).
  nlohmann::json bondlines = nlohmann::json::array();
  for (const SceneBondline& b : s.bondlines)
    bondlines.push_back({{"name", b.name},
                         {"law_case", std::string(1, b.law.table1_case())},
                         {"lambda_bar", b.law.lambda_bar},
                         {"mu_bar", b.law.mu_bar},
                         {"K_N", b.law.K_N()},
                         {"K_T", b.law.K_T()},
                         {"classified", {{"law_case", std::string(1, b.classified.table1_case())},
                                         {"lambda_bar", b.classified.lambda_bar},
                                         {"mu_bar", b.classified.mu_bar}}}});
  j["bondlines"] = std::move(bondlines);
  if (cost && cost->differs) {
    j["classification_cost"] = cost->computed
                                   ? nlohmann::json{{"computed", true}, {"reactions", cost->reactions}, {"u", cost->u}}
                                   : nlohmann::json{{"computed", false}, {"not_computed", cost->not_computed}};
  }
  if (nlohmann::json film = film_json(record); !film.is_null()) j["film"] = std::move(film);
  return j.dump();
}

nlohmann::json film_json(const SceneRecord& record) {
  const auto& n = record.numbers;
  if (!n.count("film_slip_over_h") && !n.count("film_strain_max") && !n.count("glue_strain_max")) return nullptr;
  // Each where it applies: slip_over_h on contact faces, strain_max of films (no bonded face),
  // glue_strain_max of glued layers (a load level).
  nlohmann::json film = nlohmann::json::object();
  for (const auto& [key, name] : {std::pair{"slip_over_h", "film_slip_over_h"}, std::pair{"strain_max", "film_strain_max"},
                                  std::pair{"glue_strain_max", "glue_strain_max"}})
    if (n.count(name)) film[key] = n.at(name);
  return film;
}

void check_scene_eps(const SceneFileBulk& bulk, const std::string& mode, double eps) {
  if (mode == "layer") {
    if (eps == 0 && !bulk.spec().engineer_glue_only())
      throw std::invalid_argument("layer mode needs --eps (the scene's layers are the paper's family, which has no thickness of its own)");
    check_layer_mode(bulk, eps);
  } else if (eps > 0 && !bulk.spec().has_layer()) {
    throw std::invalid_argument("--eps applies to a layer: this scene gives limit laws only ('law')");
  }
  // Limit mode: --eps chooses an engineer's glue's law (SPEC 1.3 at that thickness), and for every
  // layer the thickness SPEC 3 S6's estimate measures the law against (the paper's family keeps its law).
  if (mode == "limit" && eps > 0) check_layer_mode(bulk, eps);
  // The same "not thin" rule as layer mode, at an engineer's glue's own thickness: the limit law
  // replaces a thin layer by a surface (SPEC 1.2), so a glue too thick to be a thin layer of this
  // joint has no limit law standing for it.
  if (mode == "limit" && eps == 0)
    for (const SceneInterfaceSpec& i : bulk.spec().interfaces)
      if (i.glue && i.glue->thickness > bulk.thickest_layer()) {
        std::ostringstream s;
        s << "the glue" << (bulk.spec().interface_list ? " of " + i.group : "") << ", " << i.glue->thickness
          << " mm thick, is not thin for this joint: at most " << bulk.thickest_layer() << " mm, " << bulk.thickest_reason()
          << " (layer mode's rule); the limit law replaces a thin layer by a surface (SPEC 1.2), so no limit law stands for "
             "a glue this thick";
        throw std::invalid_argument(s.str());
      }
}

void print_limit_error_estimate(const LimitErrorEstimate& e, const std::string& reactions_fixed) {
  if (!e.computed) {
    std::printf("  distance to the layer (SPEC 3 S6): %s\n", e.note.c_str());
    return;
  }
  std::printf("  distance to the layer it stands for (SPEC 3 S6, from its first-order answer: one extra %s and the\n"
              "  end cell; %.3f s):\n",
              e.extra_factorisation ? "factorisation and solve at the limit's statuses" : "solve on the limit's factorisation",
              e.time_s);
  const std::pair<const char*, double> lines[] = {{"the reactions", e.reactions},
                                                  {"the adherents' displacements", e.u},
                                                  {"sigma_N on the bondlines", e.sigma_N},
                                                  {"sigma_T on the bondlines", e.sigma_T}};
  // SPEC 3 S6's phrase where the estimate is small; above 10 % it is a difference, said as one
  // ("within 66 %" read as reassurance).
  for (const auto& [what, value] : lines)
    if (!reactions_fixed.empty() && std::string(what) == "the reactions")
      std::printf("    the reactions are fixed by statics (%s): not judged\n", reactions_fixed.c_str());
    else if (value <= 0.1)
      std::printf("    the limit law is within %s %% of a layer of thickness %s mm for %s\n", significant(100 * value, 2).c_str(),
                  plain(e.eps).c_str(), what);
    else
      std::printf("    the limit law differs from a layer of thickness %s mm by about %s %% for %s: it does not stand "
                  "for that layer there\n", plain(e.eps).c_str(), significant(100 * value, 2).c_str(), what);
}

nlohmann::json limit_error_estimate_json(const LimitErrorEstimate& e) {
  if (!e.computed) return {{"computed", false}, {"eps", e.eps}, {"note", e.note}};
  return {{"eps", e.eps}, {"u", e.u}, {"reactions", e.reactions}, {"sigma_N", e.sigma_N}, {"sigma_T", e.sigma_T},
          {"time_s", e.time_s}};
}

void write_limit_error_estimate(H5Writer& file, const std::string& scene_id, const LimitErrorEstimate& e) {
  const std::string g = "/scenes/" + scene_id;
  file.attr(g, "limit_error_estimate_computed", e.computed ? 1 : 0);
  file.attr(g, "limit_error_estimate_eps", e.eps);
  file.attr(g, "limit_error_estimate_eps_units", std::string("mm"));
  if (!e.computed) {
    file.attr(g, "limit_error_estimate_note", e.note);
    return;
  }
  file.attr(g, "limit_error_estimate_u", e.u);
  file.attr(g, "limit_error_estimate_reactions", e.reactions);
  file.attr(g, "limit_error_estimate_sigma_N", e.sigma_N);
  file.attr(g, "limit_error_estimate_sigma_T", e.sigma_T);
  file.attr(g, "limit_error_estimate_description",
            std::string("SPEC 3 S6: the estimated relative distance (1 = 100 %) of this limit answer to the layer model "
                        "of thickness eps it stands for, in S2's norms (reactions: every support group together), "
                        "from its first-order answer (studies/limit_error_estimate.md)"));
}

std::string no_load_warning(const SceneFileScene& s) {
  if (s.carries_load) return "";
  bool open = true;
  for (const SceneBondline& b : s.bondlines)
    for (int status : b.status) open = open && status == static_cast<int>(NodeStatus::Gap);
  if (open)
    return "warning: every bondline node is open (gap): the joint carries no load across its bondlines (a glued joint "
           "needs \"faces\": {\"plus\": \"bonded\", \"minus\": \"bonded\"})";
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "warning: the joint carries next to nothing across its bondlines: %.3g per mm in all, against %.3g per "
                "mm that its loads and imposed displacements call for (a law without stiffness along the load?)",
                s.bondline_force, s.force_scale);
  return buf;
}

}  // namespace thinlayer
