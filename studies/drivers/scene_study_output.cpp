#include "studies/drivers/scene_study_output.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>

#include "core/io/output_target.h"
#include <algorithm>
#include "studies/tools/format.h"
#include "studies/tools/scene_distance.h"
#include "core/io/csv_writer.h"

namespace thinlayer {

namespace {

const std::map<std::string, std::string>& quantity_descriptions() {
  static const std::map<std::string, std::string> d = {
      {"u", "the adherents' nodal displacements, relative to the largest |u| of the limit mode"},
      {"jump_N", "[u]_N across the whole bondline (from the adherents' nodes), relative to the largest |u|"},
      {"jump_T", "[u]_T across the whole bondline (from the adherents' nodes), relative to the largest |u|"},
      {"sigma_N", "sigma_N on the plus adherent's face, relative to the largest |sigma| of the limit mode on S"},
      {"sigma_T", "sigma_T on the plus adherent's face, relative to the largest |sigma| of the limit mode on S"},
  };
  return d;
}

std::string verdict_text(const SceneValidityRow& v) {
  if (v.status == "at_least") return ">= " + sci(v.eps_max, 1);
  if (v.status == "below_range") return "< " + sci(v.eps_max, 1);
  if (v.status == "not_judged") return "-";
  return sci(v.eps_max, 2);
}

// The distance of quantity q in every row (samples or floor levels), in order.
template <typename Row>
std::vector<double> column(const std::vector<Row>& rows, const std::string& q) {
  std::vector<double> e;
  for (const Row& row : rows) e.push_back(row.e.at(q));
  return e;
}

void write_fits(H5Writer& out, const std::string& g, const std::string& q, const std::optional<PowerLawFit>& f,
                const std::string& prefix) {
  out.attr(g, prefix + q, f ? f->p : 0.0);
  out.attr(g, prefix + q + "_stderr", f ? f->p_stderr : 0.0);
  out.attr(g, "fitted_" + q, f ? 1 : 0);
}

}  // namespace

void print_scene_study(const SceneFileBulk& bulk, const SceneStudyResult& r, const SceneStudyOptions& options) {
  const SceneSpec& spec = bulk.spec();
  std::printf("\nScene %s (%s): convergence (S2), layer mode at each eps (mm) against the limit law\n", spec.name.c_str(),
              spec.file.c_str());
  for (std::size_t i = 0; i < spec.interfaces.size(); ++i) {
    const SceneInterfaceSpec& b = spec.interfaces[i];
    const InterfaceLaw law = bulk.limit_law(static_cast<int>(i), r.samples.front().eps);
    std::printf("  %s (faces %s/%s): %s", b.label().c_str(), to_string(b.faces.plus), to_string(b.faces.minus),
                law.describe().c_str());
    if (b.glue)
      std::printf(", an engineer's glue E %g, nu %g, t %g mm: its own springs K_N = (lambda_g+2mu_g)/eps, K_T = mu_g/eps "
                  "at each eps (SPEC 1.3)", b.glue->E, b.glue->nu, b.glue->thickness);
    else
      std::printf(" (lambda_bar %g, mu_bar %g %s, f %g)", law.lambda_bar, law.mu_bar, spec.units.stiffness().c_str(),
                  law.friction);
    std::printf("\n");
  }
  std::printf("  relative L2 distances; diff: S nodes whose combined status differs; limit mode %s, residual %s;\n"
              "  scenes solved to residual %g\n",
              r.limit_converged ? "converged" : "NOT converged", sci(r.limit_residual, 1).c_str(), options.tolerance);
  std::printf("  %-8s", "eps");
  for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", q.c_str());
  std::printf(" %5s %5s %9s %8s\n", "diff", "it", "residual", "time[s]");
  for (const SceneSample& s : r.samples) {
    std::printf("  %-8g", s.eps);
    for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", sci(s.e.at(q), 2).c_str());
    std::printf(" %5d %5d %9s %8.2f%s\n", s.status_diff, s.iterations, sci(s.residual, 1).c_str(), s.time_s,
                s.converged ? "" : "  NOT converged");
    if (!s.not_used.empty()) std::printf("    not used (its distances are not reported): %s\n", s.not_used.c_str());
  }
  print_fit_rows(scene_distance_quantities(), r.fit, r.floor_fit, 8, 10);
  std::printf("  (the verdict's quantities below: the reactions, u, and the peaks at d = %g mm from the bondline ends)\n",
              r.peak_distance);
  std::printf("  %-8s", "p Cauchy");
  for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", rate_text(r.cauchy_fit.at(q)).c_str());
  std::printf("   (the layer model's differences between neighbouring eps: the mesh floor cancels)\n");
  std::printf("  %-8s", "p tail");
  for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", rate_text(r.cauchy_tail.at(q).fit).c_str());
  std::printf("   (the last three differences: the rate where the grid ends)\n");
  std::printf("  %-8s", "slopes");
  for (const std::string& q : scene_distance_quantities()) {
    const std::vector<double>& s = r.cauchy_tail.at(q).local_slopes;
    std::string last;
    for (std::size_t k = s.size() > 2 ? s.size() - 2 : 0; k < s.size(); ++k) last += (last.empty() ? "" : " ") + fixed(s[k], 2);
    std::printf(" %10s", last.c_str());
  }
  std::printf("   (the last two local slopes; settled: within 0.1)\n");
  if (r.p_predicted)
    std::printf("  predicted p = %g (the Table 2 case with the scene's gamma, delta; studies/convergence_rates.md)\n",
                *r.p_predicted);
}

void print_scene_floor(const SceneStudyResult& r) {
  if (r.floor.empty()) return;
  std::printf("\nMesh floor: the modes' distance at eps %g mm (%s), the scene re-meshed\n"
              "with the element size h along the bondlines halved (and far from them)\n",
              r.floor.front().eps, r.family == "engineer" ? "the glue's own thickness" : "its eps part far below");
  std::printf("  %-8s %6s", "h (mm)", "nodes");
  for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", q.c_str());
  std::printf("\n");
  for (const SceneFloorRow& row : r.floor) {
    std::printf("  %-8g %6d", row.h, row.S_nodes);
    for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", sci(row.e.at(q), 2).c_str());
    std::printf("%s\n", row.converged ? "" : "  NOT converged");
    if (!row.not_used.empty()) std::printf("    not used (its distances are not reported): %s\n", row.not_used.c_str());
  }
  std::printf("  %-15s", "rate in h");
  for (const std::string& q : scene_distance_quantities()) std::printf(" %10s", rate_text(r.floor_rate.at(q)).c_str());
  std::printf("\n");
}

std::string verdict_label(const std::string& q, double d) {
  if (q == "reactions") return "reactions (those that can differ, each)";
  if (q == "u") return "adherents' displacements";
  // On the quantity's scale on the bondlines (scene_distance.h), never pointwise.
  if (q == "peel_at_d") return "peel at " + plain(d) + " mm from the ends, on max|sigma_N|";
  if (q == "shear_at_d") return "shear at " + plain(d) + " mm from the ends, on max|sigma_T|";
  return q;
}

void print_scene_ends(const SceneStudyResult& r) {
  std::printf("\nThe verdict's quantities at each eps (relative distance of the layer model to the limit law), and the\n"
              "peaks at d = %g mm from each bondline end (%s; the worse face of the layer), both modes\n",
              r.peak_distance, r.peak_distance_reason.c_str());
  std::printf("  %-8s", "eps");
  for (const std::string& q : verdict_quantities()) std::printf(" %10s", q.c_str());
  std::printf(" | %9s %9s | %9s %9s\n", "peel lay", "peel lim", "shear lay", "shear lim");
  for (const SceneSample& s : r.samples) {
    std::printf("  %-8g", s.eps);
    for (const std::string& q : verdict_quantities()) std::printf(" %10s", sci(s.verdict.at(q), 2).c_str());
    std::printf(" | %9.4g %9.4g | %9.4g %9.4g\n", s.layer_ends.peel, s.limit_ends.peel, s.layer_ends.shear,
                s.limit_ends.shear);
  }
  if (!r.closed_forms.joint.empty()) {
    std::printf("\nThe classical closed forms (%s; %s), at eps %g mm, against the limit law's and the layer's peaks:\n",
                r.closed_forms.joint.c_str(), r.closed_forms.assumptions.c_str(), r.samples.at(r.nominal).eps);
    for (const ClosedFormCurves& c : r.closed_forms.bondlines) {
      auto peak = [](const std::vector<double>& v) {
        double m = 0;
        for (double x : v) m = std::max(m, std::abs(x));
        return m;
      };
      std::printf("  %s: P = %.4g, overlap %.4g mm; peak shear Volkersen %.4g", c.bondline.empty() ? "S" : c.bondline.c_str(), c.P,
                  c.length, peak(c.volkersen_shear));
      if (!c.gr_shear.empty())
        std::printf(", Goland-Reissner %.4g, peak peel Goland-Reissner %.4g\n    Goland-Reissner's bending factor from "
                    "linear statics of the joint's supports: k %.3g (%.3g at s = 0, %.3g at its far end%s; k' %.3g); "
                    "GR's own geometrically nonlinear k at this P, %.3g, is not the linear model's",
                    peak(c.gr_shear), *std::max_element(c.gr_peel.begin(), c.gr_peel.end()), c.k, c.k_ends[0], c.k_ends[1],
                    std::abs(c.k_ends[0] - c.k_ends[1]) > 0.01 * std::abs(c.k)
                        ? ": the supports are not symmetric, the closed form draws their mean"
                        : "",
                    c.k_prime, c.k_nonlinear);
      else if (!c.gr_why_not.empty())
        std::printf("\n    %s", c.gr_why_not.c_str());
      if (!c.start.empty()) std::printf("\n    s = 0 at %s; s = %.4g mm at %s", c.start.c_str(), c.length, c.end.c_str());
      std::printf("\n");
    }
    std::printf("  computed at eps %g mm (the corners): shear limit %.4g, layer %.4g; peel limit %.4g, layer %.4g\n",
                r.samples.at(r.nominal).eps, r.samples.at(r.nominal).limit_ends.shear_end,
                r.samples.at(r.nominal).layer_ends.shear_end, r.samples.at(r.nominal).limit_ends.peel_end,
                r.samples.at(r.nominal).layer_ends.peel_end);
  } else if (!r.closed_forms.why_not.empty()) {
    std::printf("\nNo classical closed form drawn: %s\n", r.closed_forms.why_not.c_str());
  }
  if (r.floor.empty()) return;
  std::printf("\nThe bondline ends under mesh refinement (eps %g mm): the corner of the layer model is singular (its\n"
              "value grows as h shrinks: it is shown, not judged); at d = %g mm both modes converge and are compared\n",
              r.floor.front().eps, r.peak_distance);
  std::printf("  %-8s | %-21s %-21s | %-21s %-21s\n", "h (mm)", "corner peel lay/lim", "peel at d lay/lim",
              "corner shear lay/lim", "shear at d lay/lim");
  for (const SceneFloorRow& row : r.floor)
    std::printf("  %-8g | %9.4g %9.4g   %9.4g %9.4g   | %9.4g %9.4g   %9.4g %9.4g%s\n", row.h, row.layer_ends.peel_end,
                row.limit_ends.peel_end, row.layer_ends.peel, row.limit_ends.peel, row.layer_ends.shear_end,
                row.limit_ends.shear_end, row.layer_ends.shear, row.limit_ends.shear, row.converged ? "" : "  NOT converged");
}

void print_scene_validity(const SceneStudyResult& r, int steps) {
  std::printf("\nThickness validity (S3), one verdict per quantity: the largest eps (mm) at which the limit law stays\n"
              "within tau of the layer model (%d bisection steps on log eps between samples; 'found': by bisection,\n"
              ">=: within at every sample, <: at none)\n\n",
              steps);
  for (const std::string& q : verdict_quantities()) {
    std::string line;
    bool converged = true;
    for (const SceneValidityRow& v : r.validity) {
      if (v.quantity != q) continue;
      if (v.status == "not_judged") {
        line = "not judged: " + v.why_not_judged;
        continue;
      }
      line += (line.empty() ? "" : "; ") + std::string("within ") + plain(100 * v.tau) + " % up to eps " + verdict_text(v) +
              " (" + sci(v.error_at_eps_max, 1) + ")";
      converged = converged && v.converged;
    }
    std::printf("  %-48s %s%s\n", (verdict_label(q, r.peak_distance) + ":").c_str(), line.c_str(),
                converged ? "" : "  (a scene did not converge)");
    if (!r.floor.empty() && !std::isnan(r.floor.front().verdict.at(q)))  // the same distance on the finer meshes: where it moves, the verdict measures the mesh too
      std::printf("  %-48s at eps %g mm: %s at h %g mm, %s at h %g mm\n", "", r.floor.front().eps,
                  sci(r.floor.front().verdict.at(q), 2).c_str(), r.floor.front().h, sci(r.floor.back().verdict.at(q), 2).c_str(),
                  r.floor.back().h);
  }
  std::printf("  %-40s singular in the layer model: not judged (above, under refinement)\n", "the corners themselves:");
  if (!r.floor.empty() && r.family == "engineer")
    std::printf("\nOn the mesh: the distance u at the glue's own thickness %g mm is %s at h %g mm and %s at h %g mm:\n"
                "a verdict changes with the mesh where tau is within that change\n",
                r.floor.front().eps, sci(r.floor.front().e.at("u"), 2).c_str(), r.floor.front().h,
                sci(r.floor.back().e.at("u"), 2).c_str(), r.floor.back().h);
  else if (!r.floor.empty())
    std::printf("The mesh floor of u on this mesh (h %g mm): %s; a tau below it cannot be resolved here (refine\n"
                "mesh_size.interface; at h %g mm it is %s)\n",
                r.floor.front().h, sci(r.floor.front().e.at("u"), 2).c_str(), r.floor.back().h,
                sci(r.floor.back().e.at("u"), 2).c_str());
}

std::string bondline_fields_csv(const std::vector<ScenesOnBulk>& scenes) {
  std::ostringstream csv;
  csv.precision(10);
  std::string units = "daN";
  if (!scenes.empty()) units = scenes.front().bulk->spec().units.name();
  csv << "# thinlayer bondline fields (SPEC 5): one row per node of each bondline of each scene\n"
      << "# units " << units << ": s, x, y, eps, h and the jumps in mm, the stresses in "
      << (scenes.empty() ? "daN/mm^2" : scenes.front().bulk->spec().units.stress()) << "\n"
      << "# s: arc length along the bondline from its first node; x, y: the limit mode's position; sigma_N, sigma_T on\n"
      << "# the plus adherent's face (sigma_N > 0 tension: peel); jump_N, jump_T across the whole bondline (in layer mode\n"
      << "# across the layer); status 0 gap, 1 slide, 2 stick (layer mode: combined through both faces); eps 0: limit mode\n"
      << "scene,mode,eps,h,bondline,node,s,x,y,sigma_N,sigma_T,jump_N,jump_T,status\n";
  for (const ScenesOnBulk& s : scenes) {
    const SceneRecord& r = s.scene->record;
    const std::string mode = r.text.at("mode");
    const double eps = mode == "layer" ? r.numbers.at("eps") : 0.0;
    for (const BondlineField& f : bondline_fields(*s.bulk, r))
      for (std::size_t k = 0; k < f.s.size(); ++k)
        // Names quoted and neutralised (RFC 4180, no formula: core/io/csv_writer.h).
        csv << CsvRow()
                   .text(s.id)
                   .text(mode)
                   .number(eps)
                   .number(s.h)
                   .text(f.bondline)
                   .integer(static_cast<long long>(k))
                   .number(f.s[k])
                   .number(f.x[k])
                   .number(f.y[k])
                   .number(f.sigma_N[k])
                   .number(f.sigma_T[k])
                   .number(f.jump_N[k])
                   .number(f.jump_T[k])
                   .integer(f.status[k])
                   .line();
  }
  return csv.str();
}

void write_scene_study(H5Writer& out, const SceneFileBulk& bulk, const SceneStudyResult& r, const SceneStudyOptions& o,
                       const std::vector<const SceneFileScene*>& scenes, const std::vector<FloorScenes>& floor) {
  const SceneSpec& spec = bulk.spec();
  const std::string g = "/studies/scene/" + spec.name;
  const std::string stress = spec.units.stress();
  out.attr(g, "description",
           "S2/S3 on a scene file: the layer mode at each eps against the limit law (" +
               std::string(r.family == "engineer" ? "an engineer's glue: the same glue at each thickness, its law by SPEC 1.3 "
                                                    "at that thickness"
                                                  : "the paper's family: one limit law") +
               "), the Cauchy differences, the mesh floor, the peak stresses and the thickness validity");
  out.attr(g, "family", r.family);
  out.attr(g, "scene_file", spec.file);
  out.attr(g, "units", spec.units.name());
  out.attr(g, "limit_scene", r.limit_id);
  out.attr(g, "tolerance", o.tolerance);
  out.attr(g, "p_predicted", r.p_predicted ? *r.p_predicted : -1.0);
  std::string cases;
  for (std::size_t i = 0; i < spec.interfaces.size(); ++i) {
    if (i) cases += ',';
    cases += bulk.limit_law(static_cast<int>(i), r.samples.front().eps).table1_case();
  }
  out.attr(g, "table1_case", cases);
  out.attr(g, "characteristic_length", bulk.characteristic_length());
  out.attr(g, "characteristic_length_units", std::string("mm"));
  out.attr(g, "h_interface", spec.h_interface.value_or(0.0));
  out.attr(g, "h_interface_units", std::string("mm"));

  std::vector<double> eps;
  std::vector<int> diff, converged;
  std::vector<std::string> ids, limit_ids;
  for (const SceneSample& s : r.samples) {
    eps.push_back(s.eps);
    diff.push_back(s.status_diff);
    converged.push_back(s.converged ? 1 : 0);
    ids.push_back(s.id);
    limit_ids.push_back(s.limit_id);
  }
  out.described_dataset(g + "/eps", eps, "mm", "the layer's thickness of each sample (every layer bondline alike)");
  out.described_dataset(g + "/status_diff", diff, "", "nodes of S whose combined status differs from the limit mode's");
  out.described_dataset(g + "/converged", converged, "", "1: the layer scene and its limit scene reached the tolerance");
  out.described_dataset(g + "/layer_scene", ids, "", "the layer scene of each sample (/scenes/<id>)");
  out.described_dataset(g + "/limit_scene", limit_ids, "", "the limit scene each sample is measured against (/scenes/<id>)");
  for (const std::string& q : scene_distance_quantities()) {
    out.described_dataset(g + "/e_" + q, column(r.samples, q), "1 (relative)", "relative discrete L2 distance of " + quantity_descriptions().at(q));
    write_fits(out, g, q, r.fit.at(q), "p_");
    const auto& ff = r.floor_fit.at(q);
    out.attr(g, "p_floor_" + q, ff ? ff->p : 0.0);
    out.attr(g, "floor_" + q, ff ? ff->floor : 0.0);
    out.attr(g, "fitted_floor_" + q, ff ? 1 : 0);
  }

  // The verdict's quantities (issue 35): distances per sample and the peaks at d of both modes.
  out.attr(g, "peak_distance", r.peak_distance);
  out.attr(g, "peak_distance_units", std::string("mm"));
  out.attr(g, "peak_distance_description", "d: the peaks are judged at d from each bondline end (the corner itself is "
                                            "singular in the layer model); " + r.peak_distance_reason);
  {
    std::string order;
    for (const std::string& q : verdict_quantities()) order += (order.empty() ? "" : ",") + q;
    out.attr(g, "verdict_quantities", order);
  }
  for (const std::string& q : verdict_quantities()) {
    std::vector<double> v;
    for (const SceneSample& smp : r.samples) v.push_back(smp.verdict.at(q));
    out.described_dataset(g + "/verdict_" + q, v, "1 (relative)",
        "relative distance of the layer model to the limit law: " + verdict_label(q, r.peak_distance));
  }
  auto ends_column = [&](auto member, bool layer) {
    std::vector<double> v;
    for (const SceneSample& smp : r.samples) v.push_back((layer ? smp.layer_ends : smp.limit_ends).*member);
    return v;
  };
  for (const bool layer : {true, false}) {
    const std::string mode = layer ? "layer" : "limit";
    out.described_dataset(g + "/ends/" + mode + "_peel_at_d", ends_column(&EndStresses::peel, layer), stress,
        "the largest sigma_N at d from either bondline end (worse face), " + mode + " mode");
    out.described_dataset(g + "/ends/" + mode + "_shear_at_d", ends_column(&EndStresses::shear, layer), stress,
        "the largest |sigma_T| at d from either bondline end (worse face), " + mode + " mode");
    out.described_dataset(g + "/ends/" + mode + "_peel_corner", ends_column(&EndStresses::peel_end, layer), stress,
        "the largest sigma_N at the bondline ends' nodes (singular in the layer model), " + mode + " mode");
    out.described_dataset(g + "/ends/" + mode + "_shear_corner", ends_column(&EndStresses::shear_end, layer), stress,
        "the largest |sigma_T| at the bondline ends' nodes (singular in the layer model), " + mode + " mode");
  }
  out.attr(g + "/ends", "description", "per sample (eps): the peaks at d from the bondline ends and at the corners, both modes");

  if (!r.closed_forms.joint.empty() || !r.closed_forms.why_not.empty())
    write_joint_closed_forms(out, g + "/closed_forms", r.closed_forms, stress, spec.units.force);
  out.attr(g, "nominal_sample", static_cast<int>(r.nominal));

  const std::string c = g + "/cauchy";
  out.described_dataset(c + "/eps", std::vector<double>(eps.begin(), eps.end() - 1), "mm",
      "the thicker eps of each pair of neighbouring samples");
  for (const std::string& q : scene_distance_quantities()) {
    out.described_dataset(c + "/d_" + q, r.cauchy.at(q), "1 (relative)",
        "distance between the layer model at eps and at the next (thinner) sample: " + quantity_descriptions().at(q));
    write_fits(out, c, q, r.cauchy_fit.at(q), "p_");
    const CauchyTail& tail = r.cauchy_tail.at(q);
    out.attr(c, "p_tail_" + q, tail.fit ? tail.fit->p : 0.0);
    out.attr(c, "p_tail_" + q + "_stderr", tail.fit ? tail.fit->p_stderr : 0.0);
    out.attr(c, "fitted_tail_" + q, tail.fit ? 1 : 0);
    out.attr(c, "settled_" + q, tail.settled ? 1 : 0);
    out.described_dataset(c + "/local_slope_" + q, tail.local_slopes, "1",
        "the local rate between neighbouring differences of " + q + " (NaN where a difference is 0)");
  }
  out.attr(c, "tail_description",
           "p_tail_<q>: the Cauchy fit of the last three differences; settled_<q>: the last two local slopes within 0.1");
  out.attr(c, "description", "d_k = C eps_k^p (1 - (eps_k+1/eps_k)^p): the rate p with the mesh floor cancelled");

  if (!r.floor.empty()) {
    const std::string f = g + "/floor";
    std::vector<double> h, feps;
    std::vector<int> nodes, fconv;
    std::vector<std::string> layer_ids, limit_ids_f;
    for (const SceneFloorRow& row : r.floor) {
      h.push_back(row.h);
      feps.push_back(row.eps);
      nodes.push_back(row.S_nodes);
      fconv.push_back(row.converged ? 1 : 0);
      layer_ids.push_back(row.layer_id);
      limit_ids_f.push_back(row.limit_id);
    }
    out.described_dataset(f + "/h", h, "mm", "the element size along the bondlines (mesh_size.interface; far halved alike)");
    out.described_dataset(f + "/eps", feps, "mm",
        r.family == "engineer" ? "the layer's thickness: the glue's own (the joint as glued)"
                               : "the layer's thickness: the thinnest sample times floor_eps_factor");
    out.described_dataset(f + "/S_nodes", nodes, "", "nodes on every bondline together");
    out.described_dataset(f + "/converged", fconv, "", "1: both scenes reached the tolerance");
    out.described_dataset(f + "/layer_scene", layer_ids, "", "the layer scene at h (/scenes/<id>)");
    out.described_dataset(f + "/limit_scene", limit_ids_f, "", "the limit scene at h (/scenes/<id>)");
    for (const std::string& q : scene_distance_quantities()) {
      out.described_dataset(f + "/floor_" + q, column(r.floor, q), "1 (relative)", "the mesh floor: distance of " + quantity_descriptions().at(q));
      write_fits(out, f, q, r.floor_rate.at(q), "rate_");
    }
    for (const bool layer : {true, false}) {
      const std::string mode = layer ? "layer" : "limit";
      std::vector<double> peel, shear, peel_corner, shear_corner;
      for (const SceneFloorRow& row : r.floor) {
        const EndStresses& e = layer ? row.layer_ends : row.limit_ends;
        peel.push_back(e.peel);
        shear.push_back(e.shear);
        peel_corner.push_back(e.peel_end);
        shear_corner.push_back(e.shear_end);
      }
      out.described_dataset(f + "/" + mode + "_peel_at_d", peel, stress, "the largest sigma_N at d from either end at h, " + mode + " mode");
      out.described_dataset(f + "/" + mode + "_shear_at_d", shear, stress, "the largest |sigma_T| at d from either end at h, " + mode + " mode");
      out.described_dataset(f + "/" + mode + "_peel_corner", peel_corner, stress,
          "the largest sigma_N at the ends' nodes at h (the layer's grows: singular), " + mode + " mode");
      out.described_dataset(f + "/" + mode + "_shear_corner", shear_corner, stress,
          "the largest |sigma_T| at the ends' nodes at h (the layer's grows: singular), " + mode + " mode");
    }
    for (const std::string& q : verdict_quantities()) {
      std::vector<double> v;
      for (const SceneFloorRow& row : r.floor) v.push_back(row.verdict.at(q));
      out.described_dataset(f + "/verdict_" + q, v, "1 (relative)", "at h: " + verdict_label(q, r.peak_distance));
    }
    out.attr(f, "floor_eps_factor", o.floor_eps_factor);
    out.attr(f, "description", "the modes' distance far below the eps grid, at h, h/2, h/4: a mesh effect, not a modelling one");
  }

  {
    const std::string p = g + "/peaks";
    std::vector<std::string> scene, mode, bondline;
    std::vector<double> peps, ph, peel, s_peel, shear, s_shear, compression;
    for (const ScenePeak& k : r.peaks) {
      scene.push_back(k.scene);
      mode.push_back(k.mode);
      bondline.push_back(k.bondline);
      peps.push_back(k.eps);
      ph.push_back(k.h);
      peel.push_back(k.peaks.peel);
      s_peel.push_back(k.peaks.s_peel);
      shear.push_back(k.peaks.shear);
      s_shear.push_back(k.peaks.s_shear);
      compression.push_back(k.peaks.compression);
    }
    out.described_dataset(p + "/scene", scene, "", "the scene (/scenes/<id>)");
    out.described_dataset(p + "/mode", mode, "", "limit or layer");
    out.described_dataset(p + "/bondline", bondline, "", "the bondline's group");
    out.described_dataset(p + "/eps", peps, "mm", "the layer's thickness (0: limit mode)");
    out.described_dataset(p + "/h", ph, "mm", "the element size along the bondlines (mesh_size.interface)");
    out.described_dataset(p + "/peel", peel, stress, "the largest tension sigma_N > 0 on the plus adherent's face (0 if none)");
    out.described_dataset(p + "/s_peel", s_peel, "mm", "where: arc length along the bondline");
    out.described_dataset(p + "/shear", shear, stress, "the largest |sigma_T| on the plus adherent's face");
    out.described_dataset(p + "/s_shear", s_shear, "mm", "where: arc length along the bondline");
    out.described_dataset(p + "/compression", compression, stress, "the largest compression -sigma_N > 0 (0 if none)");
  }

  if (!r.validity.empty()) {
    const std::string v = g + "/validity";
    std::vector<double> tau, eps_max, error, beyond;
    std::vector<std::string> status, quantity, why_not;
    std::vector<int> steps, vconv;
    for (const SceneValidityRow& row : r.validity) {
      quantity.push_back(row.quantity);
      tau.push_back(row.tau);
      status.push_back(row.status);
      why_not.push_back(row.why_not_judged);
      eps_max.push_back(row.eps_max);
      error.push_back(row.error_at_eps_max);
      beyond.push_back(row.eps_beyond);
      steps.push_back(row.bisection_steps);
      vconv.push_back(row.converged ? 1 : 0);
    }
    out.described_dataset(v + "/quantity", quantity, "", "the quantity judged: reactions, u (the adherents' displacements), "
                                               "peel_at_d, shear_at_d (the peaks at peak_distance from the ends)");
    out.described_dataset(v + "/tau", tau, "1 (relative)", "the tolerance on the quantity's distance");
    out.described_dataset(v + "/status", status, "", "found: by bisection; at_least: within tau at every sample (a lower bound); "
                                          "below_range: not within tau even at the thinnest sample; not_judged: see why_not_judged");
    out.described_dataset(v + "/why_not_judged", why_not, "", "status not_judged: why (statically determinate, or no usable "
                                                  "sample); else empty");
    out.described_dataset(v + "/eps_max", eps_max, "mm", "the largest eps at which the limit law stays within tau (the quantity)");
    out.described_dataset(v + "/error_at_eps_max", error, "1 (relative)", "the quantity's distance at eps_max");
    out.described_dataset(v + "/eps_beyond", beyond, "mm", "the smallest eps known beyond tau (status found)");
    out.described_dataset(v + "/bisection_steps", steps, "", "bisection steps on log eps");
    out.described_dataset(v + "/converged", vconv, "", "1: every scene behind the verdict reached the tolerance");
    if (!r.floor.empty()) {
      out.attr(v, "mesh_floor_u", r.floor.front().e.at("u"));
      out.attr(v, "mesh_floor_u_finest", r.floor.back().e.at("u"));
      out.attr(v, "mesh_floor_h", r.floor.front().h);
      out.attr(v, "mesh_floor_h_finest", r.floor.back().h);
      out.attr(v, "mesh_floor_note", std::string("a tau below the mesh floor of u cannot be resolved on that mesh: the "
                                                 "verdict there measures the mesh, not the model"));
    }
  }

  std::set<std::string> written;  // two brackets may bisect at the same ε
  std::vector<ScenesOnBulk> csv;
  for (const SceneFileScene* s : scenes)
    if (written.insert(s->record.id).second) {
      write_scene_file_scene(out, *s, bulk);
      csv.push_back({&bulk, s, s->record.id, spec.h_interface.value_or(0.0)});
    }
  for (const FloorScenes& f : floor)
    for (const SceneFileScene* s : {&f.limit, &f.layer})
      if (written.insert(s->record.id).second) {
        write_scene_file_scene(out, *s, *f.bulk);
        csv.push_back({f.bulk.get(), s, s->record.id, f.bulk->spec().h_interface.value_or(0.0)});
      }
  out.write_beside("bondline_fields.csv", OutputKind::Csv, bondline_fields_csv(csv));
}

}  // namespace thinlayer
