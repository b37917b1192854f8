#include "studies/command_study.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <cmath>
#include <memory>
#include <sstream>

#include "core/io/h5_writer.h"
#include "studies/args.h"
#include "studies/summary_json.h"
#include "studies/dovetail_study.h"
#include "studies/table3_study.h"

namespace thinlayer {

const char* const study_help = R"(usage: thinlayer study NAME [--out DIR] [options]

Studies:
  table3     S1: the bar's Table 3, both solvers, paper vs the project's baseline, the
             sensitivity study, the transitions along AD under refinement, and the layer
             mode at eps 1e-2, 1e-3, 1e-4
  dovetail   the nine cases of Table 2 in limit mode and in layer mode at every eps
             (SPEC 2.2): statuses per face and combined, iterations, residuals, times

Options:
  --out DIR          write DIR/results.h5 (the scenes and the study's tables)
  --repeats N        timing repetitions per solve, medians reported (default 3)
  --quick            skip the sensitivity and refinement parts
  --quiet            no progress lines on stderr
  --cases LETTERS    dovetail: the cases to run (default abcdefghi)
  --eps LIST         dovetail: comma-separated thicknesses (default 1e-2,5e-3,1e-3,5e-4,1e-4)
  --relaxation-cap N dovetail: also run the relaxation solver, capped at N sweeps

Exit status: 0 when every check of the study passes, 1 otherwise, 2 on bad input.
)";

const char* const verify_help = R"(usage: thinlayer verify --out DIR [--repeats N] [--quiet]

Runs every study available (now: table3) and writes
  DIR/results.h5     every scene and study table
  DIR/summary.json   every check: id, pass, expected, got, tolerance; and the timings
Exit status: 0 only if every check passes; 1 if one fails; 2 on bad input.
(The HTML report comes with the verification-report work.)
)";

namespace {

struct StudyInput {
  std::string out_dir;
  Table3StudyOptions table3;
  DovetailStudyOptions dovetail;
};

StudyInput parse(const std::vector<std::string>& argv, bool require_out) {
  const Args args(argv, {"out", "repeats", "cases", "eps", "relaxation-cap"}, {"quick", "quiet"});
  StudyInput in;
  in.out_dir = args.text("out", "");
  if (require_out && in.out_dir.empty()) throw std::invalid_argument("--out DIR is required");
  in.table3.repeats = args.integer("repeats", 3);
  if (in.table3.repeats < 1) throw std::invalid_argument("--repeats must be >= 1");
  if (args.has("quick")) in.table3.sensitivity = in.table3.refinement = false;
  in.table3.verbose = !args.has("quiet");
  in.dovetail.verbose = !args.has("quiet");
  in.dovetail.cases = args.text("cases", in.dovetail.cases);
  for (char c : in.dovetail.cases)
    if (c < 'a' || c > 'i') throw std::invalid_argument("--cases: unknown case '" + std::string(1, c) + "' (expected a..i)");
  if (args.has("eps")) {
    in.dovetail.eps.clear();
    std::stringstream list(args.text("eps", ""));
    for (std::string item; std::getline(list, item, ',');) {
      const double eps = parse_number("eps", item);
      if (!(eps > 0) || std::isinf(eps)) throw std::invalid_argument("--eps: thicknesses must be finite and > 0");
      in.dovetail.eps.push_back(eps);
    }
  }
  in.dovetail.relaxation_cap = args.integer("relaxation-cap", 0);
  if (in.dovetail.relaxation_cap < 0) throw std::invalid_argument("--relaxation-cap must be >= 0");
  return in;
}

// Creates DIR if needed and opens DIR/results.h5 (written on commit only).
std::unique_ptr<H5Writer> open_results(const std::string& dir) {
  if (dir.empty()) return nullptr;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create output directory '" + dir + "': " + ec.message());
  return std::make_unique<H5Writer>(dir + "/results.h5");
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

int command_study(const std::vector<std::string>& argv) {
  StudyInput in;
  std::string name;
  try {
    if (argv.empty() || argv[0].rfind("--", 0) == 0) throw std::invalid_argument("which study? (table3 or dovetail)");
    name = argv[0];
    if (name != "table3" && name != "dovetail")
      throw std::invalid_argument("unknown study '" + name + "' (expected table3 or dovetail)");
    in = parse(std::vector<std::string>(argv.begin() + 1, argv.end()), false);
  } catch (const std::exception& e) {
    std::cerr << "thinlayer study: " << e.what() << "\n";
    return 2;
  }
  try {
    auto out = open_results(in.out_dir);
    const auto checks = name == "table3" ? run_table3_study(in.table3, out.get())
                                         : run_dovetail_study(in.dovetail, out.get());
    if (out) {
      out->commit();
      std::printf("\nwrote %s\n", out->path().c_str());
    }
    return report_checks(checks);
  } catch (const std::exception& e) {
    std::cerr << "thinlayer study: " << e.what() << "\n";
    return 2;
  }
}

int command_verify(const std::vector<std::string>& argv) {
  StudyInput in;
  try {
    in = parse(argv, true);
  } catch (const std::exception& e) {
    std::cerr << "thinlayer verify: " << e.what() << "\n";
    return 2;
  }
  try {
    auto out = open_results(in.out_dir);
    std::map<std::string, double> timings;
    const auto start = std::chrono::steady_clock::now();
    std::cerr << "[verify] study table3\n";
    const auto checks = run_table3_study(in.table3, out.get());
    timings["table3_s"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out->commit();
    const std::string summary = in.out_dir + "/summary.json";
    const std::string tmp = summary + ".tmp";
    {
      std::ofstream f(tmp);
      f << summary_json(checks, timings);
      if (!f) throw std::runtime_error("cannot write '" + summary + "'");
    }
    std::filesystem::rename(tmp, summary);
    std::printf("\nwrote %s and %s\n", out->path().c_str(), summary.c_str());
    return report_checks(checks);
  } catch (const std::exception& e) {
    std::cerr << "thinlayer verify: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace thinlayer
