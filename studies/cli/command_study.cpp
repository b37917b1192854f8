#include "studies/cli/command_study.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "core/io/h5_writer.h"
#include "core/io/output_ownership.h"
#include "core/io/output_target.h"
#include "studies/cli/command_scene.h"
#include "studies/cli/command_validity_map.h"
#include "studies/drivers/scene_file_study.h"
#include "studies/tools/stopwatch.h"
#include "studies/cli/summary_json.h"
#include "studies/drivers/cauchy_rates.h"
#include "studies/drivers/convergence_study.h"
#include "studies/drivers/floor_study.h"
#include "studies/drivers/dovetail_study.h"
#include "studies/tools/format.h"
#include "studies/cli/options.h"
#include "studies/parallel/process_group.h"
#include "studies/cli/report_runner.h"
#include "studies/cli/results_file.h"
#include "studies/drivers/quadrature_control.h"
#include "studies/drivers/refinement_study.h"
#include "studies/drivers/selection_control.h"
#include "studies/drivers/skip_study.h"
#include "studies/parallel/spread_command.h"
#include "studies/drivers/stress_study.h"
#include "studies/drivers/table3_study.h"
#include "studies/drivers/thresholds_study.h"
#include "studies/drivers/timing_study.h"
#include "studies/drivers/validity_study.h"
#include "studies/drivers/validity_map.h"
#include "studies/tools/run_phase.h"

namespace thinlayer {

namespace {

struct StudyInput {
  std::string out_dir;
  bool force = false;
  Table3StudyOptions table3;
  DovetailStudyOptions dovetail;
  ConvergenceStudyOptions convergence;
  CauchyStudyOptions rates;
  FloorStudyOptions floor;
  bool floor_study = true;  // --quick skips it (three mesh levels, the finest the slowest scenes of S2)
  RefinementStudyOptions refinement;
  bool refine = false;  // study convergence --refine: S2 under mesh refinement, alone
  ValidityStudyOptions validity;
  ThresholdsStudyOptions thresholds;
  TimingStudyOptions timing;
  StressStudyOptions stress;
  int threads = 2;
  bool verbose = true;
};

// The options each study reads; any other is refused rather than silently ignored.
const std::map<std::string, std::set<std::string>> study_options = {
    {"table3", {"out", "quiet", "force", "repeats", "quick"}},
    {"dovetail", {"out", "quiet", "force", "cases", "eps", "relaxation-cap", "friction-path"}},
    {"convergence", {"out", "quiet", "force", "quick", "cases", "eps", "rate-eps", "tolerance", "threads", "refine",
                     "scene-cap", "resolve"}},
    {"validity", {"out", "quiet", "force", "cases", "eps", "tolerance", "threads", "bisection-steps"}},
    {"thresholds", {"out", "quiet", "force"}},
    {"asymptotics", {"out", "quiet", "force", "quick", "cases", "eps", "rate-eps", "tolerance", "threads", "bisection-steps"}},
    {"timing", {"out", "quiet", "force", "repeats", "quick"}},
    {"stress", {"out", "quiet", "force", "quick"}},
    // verify runs table3, asymptotics, the quick timing and stress.
    {"verify", {"out", "quiet", "force", "repeats", "quick", "cases", "eps", "rate-eps", "tolerance", "threads", "bisection-steps"}},
};

// The dovetail's thickest thin layer (its layer meshes stop there; SPEC §4: a layer thicker
// than makes geometric sense is refused).
constexpr double thickest_dovetail_layer = 0.1;

// study convergence --refine LIST [--scene-cap S] [--resolve stale|failed|all]: S2 under mesh
// refinement (studies/drivers/refinement_study.h), on the cases and rate grid of --cases, --rate-eps.
void parse_refinement(const CLI::App& c, const StudyArgs& a, StudyInput& in) {
  in.refine = given(c, "refine");
  if (!in.refine) {
    for (const char* option : {"scene-cap", "resolve"})
      if (given(c, option)) throw std::invalid_argument(std::string("--") + option + " applies only with --refine");
    return;
  }
  for (const char* option : {"eps", "quick", "threads"})
    if (given(c, option))
      throw std::invalid_argument(std::string("--") + option + " does not apply with --refine (it solves the rate grid, "
                                  "one scene at a time per rank: spread it with mpirun)");
  if (in.out_dir.empty()) throw std::invalid_argument("--refine needs --out DIR: its scenes are kept in DIR/scenes as they are solved");
  RefinementSceneOptions& s = in.refinement.scenes;
  s.refine.clear();
  for (double r : a.refine.values) {
    if (!(r >= 1 && r <= 16) || r != std::floor(r))
      throw std::invalid_argument("--refine: each refinement is a whole number from 1 to 16 (h / r along S), not " + plain(r));
    if (!s.refine.empty() && !(r > s.refine.back())) throw std::invalid_argument("--refine: the refinements must increase");
    s.refine.push_back(static_cast<int>(r));
  }
  if (s.refine.empty()) throw std::invalid_argument("--refine: give at least one refinement");
  s.cases = in.dovetail.cases;
  s.eps = in.rates.eps;
  s.tolerance = in.convergence.tolerance;
  s.verbose = in.verbose;
  s.store_folder = in.out_dir + "/scenes";
  if (given(c, "scene-cap")) {
    if (!(a.scene_cap > 0) || a.scene_cap > 7 * 86400) throw std::invalid_argument("--scene-cap: seconds in (0, 604800]");
    s.scene_cap_s = a.scene_cap;
  }
  if (given(c, "resolve")) s.resolve = parse_resolve_policy(a.resolve);
}

StudyInput parse(const CLI::App& c, const StudyArgs& a, const std::string& name) {
  require_only(c, study_options.at(name), name == "verify" ? "verify" : "study " + name);
  const bool require_out = name == "verify";
  StudyInput in;
  in.out_dir = a.out;
  in.force = a.force;
  if (require_out && in.out_dir.empty()) throw std::invalid_argument("--out DIR is required");
  in.table3.repeats = given(c, "repeats") ? a.repeats : 3;
  if (in.table3.repeats < 1) throw std::invalid_argument("--repeats must be >= 1");
  if (a.quick) {
    in.table3.sensitivity = in.table3.refinement = false;
    in.stress.quick = true;
    in.timing = TimingStudyOptions::quick();
    in.floor_study = false;
  }
  in.timing.repeats = in.table3.repeats;
  in.verbose = !a.quiet;
  in.table3.verbose = in.dovetail.verbose = in.stress.verbose = in.verbose;
  if (given(c, "cases")) in.dovetail.cases = a.cases;
  for (char c : in.dovetail.cases)
    if (c < 'a' || c > 'i') throw std::invalid_argument("--cases: unknown case '" + std::string(1, c) + "' (expected a..i)");
  if (in.dovetail.cases.empty()) throw std::invalid_argument("--cases: give at least one case");
  for (size_t i = 0; i < in.dovetail.cases.size(); ++i)
    if (in.dovetail.cases.find(in.dovetail.cases[i]) != i)
      throw std::invalid_argument("--cases: case '" + std::string(1, in.dovetail.cases[i]) + "' is given twice");
  if (given(c, "eps")) {
    in.dovetail.eps = a.eps.values;
    for (double eps : in.dovetail.eps)
      if (!(eps > 0) || std::isinf(eps)) throw std::invalid_argument("--eps: thicknesses must be finite and > 0");
      else if (eps > thickest_dovetail_layer)
        throw std::invalid_argument("--eps: " + plain(eps) + " is no thin layer for the dovetail: at most 0.1 (a tenth of its size)");
  }
  if (given(c, "rate-eps")) {
    in.rates.eps = a.rate_eps.values;
    for (size_t k = 0; k < in.rates.eps.size(); ++k)
      if (!(in.rates.eps[k] > 0) || std::isinf(in.rates.eps[k]) || in.rates.eps[k] > thickest_dovetail_layer)
        throw std::invalid_argument("--rate-eps: thicknesses must be in (0, 0.1]");
      else if (k > 0 && !(in.rates.eps[k] < in.rates.eps[k - 1]))
        throw std::invalid_argument("--rate-eps: the grid must decrease (its neighbours are differenced)");
    if (in.rates.eps.size() < 2) throw std::invalid_argument("--rate-eps: give at least two thicknesses");
  }
  if (given(c, "friction-path"))
    in.dovetail.friction_path = friction_path_multipliers(a.friction_path.values, dovetail::friction);
  in.dovetail.relaxation_cap = given(c, "relaxation-cap") ? a.relaxation_cap : 0;
  if (in.dovetail.relaxation_cap < 0) throw std::invalid_argument("--relaxation-cap must be >= 0");
  in.convergence.cases = in.dovetail.cases;
  in.convergence.eps = in.dovetail.eps;
  if (given(c, "tolerance")) in.convergence.tolerance = a.tolerance;
  in.rates.cases = in.convergence.cases;
  in.rates.tolerance = in.convergence.tolerance;
  in.floor.tolerance = in.convergence.tolerance;
  if (!(in.convergence.tolerance > 0) || !(in.convergence.tolerance < 1))
    throw std::invalid_argument("--tolerance must be in (0, 1)");
  in.threads = given(c, "threads") ? a.threads : 2;
  if (in.threads < 1 || in.threads > 64) throw std::invalid_argument("--threads must be in 1..64");
  in.floor.threads = in.threads;
  in.floor.verbose = in.verbose;
  parse_refinement(c, a, in);
  in.validity.bisection_steps = given(c, "bisection-steps") ? a.bisection_steps : 2;
  if (in.validity.bisection_steps < 0 || in.validity.bisection_steps > 20)
    throw std::invalid_argument("--bisection-steps must be in 0..20");
  return in;
}

// S2's controls behind the rates of the nearly incompressible layers (cases e, f), for the cases
// asked: the quadrature (case e) and the two selections.
void run_s2_controls(const StudyInput& in, DovetailSceneCache& cache, H5Writer* out, std::vector<Check>& checks) {
  if (in.rates.cases.find('e') != std::string::npos) {
    QuadratureControlOptions quadrature;
    quadrature.eps.clear();  // the rate grid's thicknesses one decade apart (its own scenes)
    for (size_t k = 0; k < in.rates.eps.size(); k += 2) quadrature.eps.push_back(in.rates.eps[k]);
    quadrature.tolerance = in.rates.tolerance;
    if (quadrature.eps.size() >= 2) run_quadrature_control(quadrature, cache, out);
  }
  SelectionControlOptions selection;
  selection.cases.clear();
  for (char c : std::string("ef"))
    if (in.rates.cases.find(c) != std::string::npos) selection.cases += c;
  selection.tolerance = in.rates.tolerance;
  if (!selection.cases.empty()) run_selection_control(selection, cache, out, checks);
}

// S2, S3 and S4 as asked: they share one limit-mode bulk and one scene cache.
std::vector<Check> run_asymptotic_studies(const StudyInput& in, bool s2, bool s3, bool s4, H5Writer* out) {
  std::vector<Check> checks;
  DovetailLimitBulk bulk;
  if (s2 || s3) {
    if (in.convergence.eps.size() < 3) throw std::invalid_argument("--eps: the convergence study needs at least 3 thicknesses");
    DovetailSceneCache cache(bulk, in.threads, in.verbose, "convergence");
    const ConvergenceResult samples = run_convergence_study(in.convergence, cache, out);
    checks = samples.checks;
    if (s2) run_cauchy_rates(in.rates, cache, out, checks);
    if (s2) run_s2_controls(in, cache, out, checks);
    if (s2 && in.floor_study) run_floor_study(in.floor, cache, out, checks);
    else if (s2) std::printf("\nFloor (S2): skipped (--quick)\n");
    if (s3) {
      ValidityStudyOptions validity = in.validity;
      validity.extra_eps = in.rates.eps;  // solved by S2's rates when it ran; else solved here
      run_validity_study(validity, samples, in.convergence, cache, out, checks);
    }
    std::printf("\n(%d scenes solved, %d requests answered from memory; %.1f s of solving over %d threads)\n",
                cache.solves(), cache.reuses(), cache.solve_time_s(), in.threads);
    if (out) cache.write(*out);
  }
  if (s4) {
    if (in.verbose) std::cerr << "[thresholds] limit-mode sweeps\n";
    run_thresholds_study(in.thresholds, bulk, out, checks);
  }
  return checks;
}

// S5's timings: run time against error, and what each shortcut of the fast solver saves.
std::vector<Check> run_timing_studies(const TimingStudyOptions& timing, H5Writer* out) {
  std::vector<Check> checks = run_timing_study(timing, out);
  const std::vector<Check> skip = run_skip_study(SkipStudyOptions{timing.repeats}, out);
  checks.insert(checks.end(), skip.begin(), skip.end());
  return checks;
}

// The lap joint's S2 and S3 (cases/lap_joint): its scene file is read like a user's.
std::vector<Check> run_lap_joint_study(bool verbose, H5Writer* out) {
  SceneFileBulk bulk(read_scene_spec(std::string(THINLAYER_CASES_DIR) + "/lap_joint/lap_joint.json"));
  SceneStudyOptions options;
  options.validity = true;
  options.verbose = verbose;
  return run_scene_study(bulk, options, out).checks;
}

// The engineer's validity map of the shipped joints (SPEC 3 S3) on a small grid, so that verify stays
// fast (4 s of its time on this machine): t/L 1e-2 and 1e-1 at nu_g 0.45, by E_g/E_a 1e-3 and 1e-1 on
// the double lap (the map's corners), at E_g/E_a 1e-1 (an epoxy on aluminium) on the stepped lap and
// the lap joint. The full map (7 x 7 x 2 cells) is `study validity-map --scene` (docs/studies.md,
// "The engineer's validity map").
std::vector<Check> run_validity_maps(int threads, bool verbose, H5Writer* out) {
  std::vector<Check> checks;
  for (const char* joint : {"double_lap", "stepped_lap", "lap_joint"}) {
    SceneFileBulk bulk(read_scene_spec(std::string(THINLAYER_CASES_DIR) + "/" + joint + "/" + joint + ".json"));
    ValidityMapOptions options;
    options.t_over_L = {1e-2, 1e-1};
    options.E_ratio = std::string(joint) == "double_lap" ? std::vector<double>{1e-3, 1e-1} : std::vector<double>{1e-1};
    options.nu = {0.45};
    options.threads = threads;
    options.verbose = verbose;
    const std::vector<Check> c = run_validity_map(bulk, options, out).checks;
    checks.insert(checks.end(), c.begin(), c.end());
  }
  return checks;
}

int report_checks(const std::vector<Check>& checks) {
  int failed = 0;
  for (const Check& c : checks)
    if (!c.pass) {
      ++failed;
      std::printf("FAIL %s: expected %s, got %s\n", c.id.c_str(), c.expected.c_str(), c.got.c_str());
    }
  std::printf("\n%zu checks: %zu passed, %d failed\n", checks.size(), checks.size() - failed, failed);
  return failed == 0 ? 0 : 1;
}

}  // namespace

namespace {

const std::vector<std::string> study_names = {"table3",     "dovetail",    "convergence", "validity",
                                              "thresholds", "asymptotics", "timing",      "stress", "validity-map"};

// The options of `study` and `verify`, with their help; on verify, those it does not read are
// declared too (so that giving one says "does not apply to verify") but not shown.
void declare_study_options(CLI::App& c, StudyArgs& a, const std::set<std::string>& shown) {
  auto group = [&](CLI::Option* option) {
    const std::string name = option->get_lnames().front();
    option->group(shown.count(name) ? "Options" : "");
  };
  group(c.add_option("--out", a.out, "write DIR/results.h5 (the scenes and the study's tables)")->type_name("DIR"));
  group(c.add_option("--repeats", a.repeats, "table3, timing: repetitions per timed solve, medians reported (default 3)")
            ->type_name("N")->transform(integer("repeats")));
  group(c.add_flag("--quick", a.quick,
                   "table3: skip the sensitivity and refinement parts; S2: skip the floor\n"
                   "study (three mesh levels); stress: skip the scenes at eps <= 1e-6 and\n"
                   "the slowest contrast; timing: bar levels 32-128, peers at 32 and 64,\n"
                   "dovetail h 0.05 and 0.025, layer eps 1e-4"));
  group(c.add_flag("--quiet", a.quiet, "no progress lines on stderr"));
  group(c.add_flag("--force", a.force, "replace DIR's files that thinlayer did not write (results.h5, summary.json)"));
  group(c.add_option("--cases", a.cases, "dovetail studies: the cases to run, each once (default abcdefghi)")->type_name("LETTERS"));
  group(c.add_option("--eps", a.eps,
                     "dovetail studies: comma-separated thicknesses, each in (0, 0.1]\n"
                     "(default 1e-2,5e-3,1e-3,5e-4,1e-4); with --scene, mm")
            ->type_name("LIST")->check(number_list("eps")));
  group(c.add_option("--rate-eps", a.rate_eps,
                     "S2: the decreasing eps grid of the Cauchy differences (default\n"
                     "1e-4 ... 1e-8, ratio 10^-1/2); the rate is fitted on eps <= 1e-4")
            ->type_name("LIST")->check(number_list("rate-eps")));
  group(c.add_option("--refine", a.refine,
                     "convergence: S2 under mesh refinement alone: the rate grid (--rate-eps) of\n"
                     "every case (--cases) at h / r along S for each r of the list (1,2,4: h, h/2,\n"
                     "h/4; SPEC 3 S2 item 3), both selections of the layer; resumable: each scene\n"
                     "is kept in DIR/scenes as it is solved (--out required). Hours: spread it with\n"
                     "mpirun (docs/studies.md, \"S2 under mesh refinement\")")
            ->type_name("R1,R2,...")->check(number_list("refine")));
  group(c.add_option("--scene-cap", a.scene_cap,
                     "with --refine: each scene's wall-time cap in seconds (default 900); a scene\n"
                     "past it is stopped, recorded as capped and never fitted")
            ->type_name("S")->check(decimal("scene-cap")));
  group(c.add_option("--resolve", a.resolve,
                     "with --refine: which stored scenes are solved again: stale (default: those\n"
                     "of another solver revision), failed (every scene without an answer, whichever\n"
                     "solver; answers of any solver kept), all, or none (the tables of what is\n"
                     "stored: a copy of a store under way)")
            ->type_name("WHAT")->check(one_of("resolve", {"stale", "failed", "all", "none"})));
  group(c.add_option("--tolerance", a.tolerance,
                     "S2/S3: the SPEC residual the scenes are solved to (default 1e-10; below\n"
                     "it, case d is re-solved at 1e-10 to show how much the distances move)")
            ->type_name("T")->check(decimal("tolerance")));
  group(c.add_option("--threads", a.threads, "S2/S3: layer-mode scenes solved in parallel (default 2)")
            ->type_name("N")->transform(integer("threads")));
  group(c.add_option("--peak-distance", a.peak_distance,
                     "with --scene: the distance d (mm) from each bondline end at which the\n"
                     "peak peel and shear are judged (default: the larger of the glue's\n"
                     "thickness and two elements along the bondline; the corner itself is singular)")
            ->type_name("D")->check(decimal("peak-distance")));
  group(c.add_option("--bisection-steps", a.bisection_steps, "S3: bisection steps per bracket (default 2)")
            ->type_name("N")->transform(integer("bisection-steps")));
  group(c.add_option("--relaxation-cap", a.relaxation_cap, "dovetail: also run the relaxation solver, capped at N sweeps")
            ->type_name("N")->transform(integer("relaxation-cap")));
  group(c.add_option("--friction-path", a.friction_path,
                     "dovetail: solve every layer scene along this continuation in the Coulomb\n"
                     "coefficient first (as `thinlayer solve --friction-path`), then at f = 0.5")
            ->type_name("F1,F2,...")->check(number_list("friction-path")));
  group(c.add_option("--scene", a.scene,
                     "convergence, validity: S2 (and S3) on your own joint, a scene file\n"
                     "(docs/joints.md)")
            ->type_name("FILE.json"));
  group(c.add_option("--thickness-ratios", a.thickness_ratios,
                     "validity-map: the glue's thicknesses t/L (default 1e-3 ... 1e-1, 3 a decade)")
            ->type_name("LIST")->check(number_list("thickness-ratios")));
  group(c.add_option("--modulus-ratios", a.modulus_ratios,
                     "validity-map: the glue's Young's moduli E_g/E_a (default 1e-4 ... 1e-1, 2 a decade)")
            ->type_name("LIST")->check(number_list("modulus-ratios")));
  group(c.add_option("--poisson", a.poisson, "validity-map: the glue's Poisson ratios (default 0.3,0.45)")
            ->type_name("LIST")->check(number_list("poisson")));
  group(c.add_option("--max-nodes", a.max_nodes,
                     "with --scene: refuse a mesh of more nodes than N, before meshing\n"
                     "(estimated from the geometry and mesh_size; default 2000000)")
            ->type_name("N")->transform(integer("max-nodes")));
  group(c.add_option("--mesh-timeout", a.mesh_timeout,
                     "with --scene and validity-map: stop gmsh after S seconds of wall clock\n"
                     "for all the meshing of the command together, not each mesh (default 600)")
            ->type_name("S")->check(decimal("mesh-timeout")));
}

}  // namespace

CLI::App* declare_study(CLI::App& thinlayer, StudyArgs& a) {
  CLI::App* c = thinlayer.add_subcommand(
      "study",
      "run a study: table3, dovetail, convergence, validity, thresholds, asymptotics, timing, stress or\n"
      "validity-map\n"
      "\n"
      "Without --out the study prints its tables and saves nothing. An option the study does not\n"
      "read is refused, as is an option given twice or a stray argument.\n"
      "\n"
      "Studies:\n"
      "  table3       S1: the bar's Table 3, both solvers, paper vs the project's baseline, the\n"
      "               sensitivity study, the transitions along AD under refinement, and the layer\n"
      "               mode at eps 1e-2, 1e-3, 1e-4\n"
      "  dovetail     the nine cases of Table 2 in limit mode and in layer mode at every eps\n"
      "               (SPEC 2.2): statuses per face and combined, iterations, residuals, times\n"
      "  convergence  S2: distances between the layer and limit modes of the dovetail at every eps,\n"
      "               and the rates from the layer model's Cauchy differences along a finer eps\n"
      "               grid against the predicted ones (studies/convergence_rates.md)\n"
      "  validity     S3 (runs S2 for its samples): the largest eps at which the limit law stays\n"
      "               within 1 % and 5 % of the layer model, by bisection on eps\n"
      "  thresholds   S4: the error of replacing a finite law by the 0 or inf law across the\n"
      "               paper's 3 % and 30x thresholds\n"
      "  asymptotics  S2, S3 and S4 together, sharing their scenes\n"
      "  timing       S5: wall time against error for the fast solver, the relaxation and the Siconos\n"
      "               peers (fc2d NSGS, Lemke) on the bar at 32..512 contact nodes, the dovetail's\n"
      "               limit mode at three levels and its layer mode at eps 1e-2 and 1e-4; ratios to\n"
      "               one linear solve, growth exponents, the targets of issue 5; and the time each\n"
      "               shortcut of the fast solver saves (skip what a scene doesn't need)\n"
      "  stress       S5 stress tests: eps to 1e-8, stiffness contrast to 1e-12, f from 0 to 10,\n"
      "               distorted meshes, interfaces that open everywhere, capped solves; each scene\n"
      "               converges or stops with a named cause (iteration cap, singular system, loss of\n"
      "               accuracy with a condition estimate), and no NaN/Inf is written\n"
      "\n"
      "  validity-map the engineer's validity map of a joint (--scene FILE.json, required): the finite\n"
      "               spring law of a glue at its own thickness against its meshed layer over t/L and\n"
      "               E_g/E_a (and nu_g), at h and h/2, SPEC 3 S6's estimate judged on it, the\n"
      "               paper's 3 % / 30x rule's cost; spread over MPI ranks\n"
      "\n"
      "Your own joint: study convergence --scene FILE.json, study validity --scene FILE.json run S2\n"
      "and S3 on a scene file (docs/joints.md, docs/studies.md); options --out, --eps LIST (mm), --tolerance\n"
      "(default 1e-10 there), --threads, --quiet, --max-nodes, --mesh-timeout, --peak-distance D (mm) and\n"
      "(validity) --bisection-steps. The verdict is one line per quantity: the reactions, the adherents'\n"
      "displacements, and the peak peel and shear at d from each bondline end.");
  c->formatter(help_formatter("usage: thinlayer study NAME [--out DIR] [options]"));
  c->set_help_flag("-h,--help", "this help");
  c->allow_extras();
  c->add_option("name", a.name)->check(one_of("study", study_names))->group("");
  std::set<std::string> all;
  for (const auto& [study, options] : study_options) all.insert(options.begin(), options.end());
  all.insert({"relaxation-cap", "friction-path", "scene", "max-nodes", "mesh-timeout", "thickness-ratios", "modulus-ratios", "poisson"});
  declare_study_options(*c, a, all);
  c->footer("Exit status: 0 when every check of the study passes, 1 otherwise, 2 on bad input.");
  return c;
}

CLI::App* declare_verify(CLI::App& thinlayer, StudyArgs& a) {
  CLI::App* c = thinlayer.add_subcommand(
      "verify",
      "run every study, write the summary and the report\n"
      "\n"
      "Runs the studies S1 (table3), S2-S4 (convergence, validity, thresholds), S5 (timing, quick,\n"
      "and stress), S2-S3 on the shipped single-lap shear joint (cases/lap_joint, a scene file), and\n"
      "the validity map of the shipped joints on a small grid (study validity-map), and writes\n"
      "  DIR/results.h5           every scene, study table and check, the environment\n"
      "  DIR/summary.json         every check: id, pass, expected, got, tolerance; and the timings\n"
      "  DIR/report/index.html    the report, with its figures (made from results.h5 alone:\n"
      "                           /usr/bin/python3 report/make_report.py DIR/results.h5 DIR/report)\n"
      "Its options are those of `thinlayer study` that the studies it runs read.");
  c->formatter(help_formatter("usage: thinlayer verify --out DIR [--repeats N] [--quiet]"));
  c->set_help_flag("-h,--help", "this help");
  c->allow_extras();
  declare_study_options(*c, a, study_options.at("verify"));
  c->footer(
      "Exit status: 0 only if every check passes; 1 if one fails; 2 on bad input or a failure to\n"
      "write an output.");
  return c;
}

int command_study(const CLI::App& command, const StudyArgs& a) {
  StudyInput in;
  const std::string name = a.name;
  try {
    if (name.empty())
      throw std::invalid_argument(
          "which study? (table3, dovetail, convergence, validity, thresholds, asymptotics, timing or stress)");
    // S2/S3 on the user's own joint (SPEC §5).
    // The engineer's validity map of a joint (SPEC 3 S3), spread over MPI ranks like the others.
    if (name == "validity-map") return command_study_validity_map(command, a);
    if (given(command, "scene")) return command_study_scene(name, command, a);
    in = parse(command, a, name);
  } catch (const std::exception& e) {
    if (is_root()) print_message("study", e.what());  // every rank parsed the same
    return 2;
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    auto out = open_results_on_root(in.out_dir, {{}, in.force});
    if (in.out_dir.empty()) std::printf("(no --out DIR: the results are printed, not saved)\n");
    const RunPhase phase("running study " + name);
    std::vector<Check> checks;
    if (name == "table3") checks = run_table3_study(in.table3, out.get());
    else if (name == "dovetail") checks = run_dovetail_study(in.dovetail, out.get());
    else if (name == "timing")
      checks = on_root_alone("timing", "it measures time, so it is never spread",
                             [&] { return run_timing_studies(in.timing, out.get()); });
    else if (name == "stress") checks = run_stress_study(in.stress, out.get());
    else if (name == "convergence" && in.refine) checks = run_refinement_study(in.refinement, out.get()).checks;
    else
      checks = run_asymptotic_studies(in, name == "convergence" || name == "validity" || name == "asymptotics",
                                      name == "validity" || name == "asymptotics",
                                      name == "thresholds" || name == "asymptotics", out.get());
    std::printf("\nstudy %s: %.1f s wall time\n", name.c_str(),
                seconds_since(start));
    on_root([&] {
      if (!out) return;
      write_checks(*out, checks);
      out->commit();
      std::printf("wrote %s\n", out->path().c_str());
      if (in.refine) {  // its own report: the rates under refinement (report/section_refinement.py)
        std::fflush(stdout);
        run_report(out->path(), in.out_dir + "/report");
        std::printf("wrote %s/report/index.html\n", in.out_dir.c_str());
      }
    });
    return command_status(report_checks(checks));
  } catch (const std::exception& e) {
    return command_failed("study", e);
  }
}

int command_verify(const CLI::App& command, const StudyArgs& a) {
  StudyInput in;
  try {
    in = parse(command, a, "verify");
  } catch (const std::exception& e) {
    print_message("verify", e.what());
    return 2;
  }
  try {
    // Its two files distinct after every link (a dangling summary.json -> results.h5 included).
    check_distinct_outputs({{"results.h5", in.out_dir + "/results.h5"}, {"summary.json", in.out_dir + "/summary.json"}},
                           {});
    const std::string summary = in.out_dir + "/summary.json";
    const std::string report_dir = in.out_dir + "/report";
    check_replaceable(summary, OutputKind::Summary, {}, in.force);  // before the studies, not after (and again at the write)
    check_report_folder(report_dir);
    auto out = open_results(in.out_dir, {{}, in.force});
    std::map<std::string, double> timings;
    std::vector<Check> checks;
    auto timed = [&](const std::string& name, const std::function<std::vector<Check>()>& study) {
      std::cerr << "[verify] study " << name << "\n";
      const RunPhase phase("running study " + name);
      const auto start = std::chrono::steady_clock::now();
      const std::vector<Check> c = study();
      checks.insert(checks.end(), c.begin(), c.end());
      timings[name + "_s"] = seconds_since(start);
    };
    timed("table3", [&] { return run_table3_study(in.table3, out.get()); });
    timed("asymptotics", [&] { return run_asymptotic_studies(in, true, true, true, out.get()); });
    // verify runs the quick S5 (the full one, with the bar up to 512 contact nodes, takes minutes).
    TimingStudyOptions timing = TimingStudyOptions::quick();
    timing.repeats = in.timing.repeats;
    timed("timing", [&] { return run_timing_studies(timing, out.get()); });
    timed("stress", [&] { return run_stress_study(in.stress, out.get()); });
    // A joint beyond the paper's two (SPEC §5): the shipped single-lap shear joint, both modes,
    // S2 and S3, through the same scene-file machinery a user's joint goes through.
    timed("lap_joint", [&] { return run_lap_joint_study(in.verbose, out.get()); });
    timed("validity_map", [&] { return run_validity_maps(in.threads, in.verbose, out.get()); });
    write_checks(*out, checks);
    out->commit();
    out->write_beside("summary.json", OutputKind::Summary, summary_json(checks, timings));
    std::cerr << "[verify] report\n";
    run_report_keeping(out->path(), report_dir, {out->path(), summary});
    std::printf("\nwrote %s, %s and %s/index.html\n", out->path().c_str(), summary.c_str(), report_dir.c_str());
    return report_checks(checks);
  } catch (const std::exception& e) {
    print_message("verify", failure_text(e));
    return 2;
  }
}

}  // namespace thinlayer
