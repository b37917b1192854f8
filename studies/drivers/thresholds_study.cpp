#include "studies/drivers/thresholds_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>

#include "core/io/column_table.h"
#include "core/solvers/fast_solver.h"
#include "studies/tools/bisection.h"
#include "studies/tools/error_norms.h"
#include "studies/tools/format.h"
#include "studies/parallel/scene_batch.h"

namespace thinlayer {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
const double U = std::hypot(dovetail::pull_x, dovetail::pull_y);  // mm

struct Sweep {
  std::string param;  // "lambda" | "mu"
  double reference;   // λ_m/L or μ_m/L, daN/mm³
  // The law with the swept parameter set to `value` (0, finite or ∞), the other held.
  std::function<InterfaceLaw(double)> law;
};

const double sigma_ref = dovetail::mu_m * U / 1.0;                // daN/mm², L = 1

// What a replacement changes: the adherents' displacements, and the stress vector on S.
struct Response {
  Eigen::VectorXd u;      // free DOFs, mm
  Eigen::VectorXd sigma;  // (σ_N, σ_T) per S node, daN/mm²
  bool converged = false;
};
void put(ByteWriter& w, const Response& r) { put(w, r.u), put(w, r.sigma), put(w, r.converged); }
void get(ByteReader& b, Response& r) { get(b, r.u), get(b, r.sigma), get(b, r.converged); }

class Solver {
 public:
  Solver(DovetailLimitBulk& bulk, double tolerance) : bulk_(bulk) {
    options_.tolerance = tolerance;
    const Interface S = dovetail::make_limit_interface(bulk_.model(), InterfaceLaw{});
    weights_.resize(2 * S.nodes.size());
    for (size_t k = 0; k < S.nodes.size(); ++k) weights_[2 * k] = weights_[2 * k + 1] = S.nodes[k].length;
  }
  // Counts the solves that did not converge.
  Response solve(const InterfaceLaw& law) { return count(solve_uncounted(law)); }
  // For a solve made elsewhere (on another rank): counted as if made here.
  Response count(Response r) {
    ++solves_;
    if (!r.converged) ++failures_;
    return r;
  }
  Response solve_uncounted(const InterfaceLaw& law) {
    const ContactProblem problem(bulk_.system(), {dovetail::make_limit_interface(bulk_.model(), law)});
    const SolveReport r = solve_fast(problem, bulk_.condensed(), options_);
    return {r.u, r.r.cwiseQuotient(weights_), r.converged};
  }
  // The error of `replaced` against `finite` in one quantity: "u" or "sigma".
  double error(const std::string& quantity, const Response& finite, const Response& replaced) const {
    if (quantity == "u") return relative_distance(replaced.u, finite.u, Eigen::VectorXd::Ones(finite.u.size()), U);
    return relative_distance(replaced.sigma, finite.sigma, weights_, sigma_ref);
  }
  int solves() const { return solves_; }
  int failures() const { return failures_; }

 private:
  DovetailLimitBulk& bulk_;
  SolverOptions options_;
  Eigen::VectorXd weights_;  // tributary length of each row of S, mm
  int solves_ = 0, failures_ = 0;
};

// Where an error that grows with x crosses τ, from a sweep (x ascending) refined by bisection:
// ("found", the largest x with error ≤ τ), or ("never", first x) when the sweep starts above τ,
// or ("always", last x) when it never leaves it.
std::pair<std::string, double> crossing(const std::vector<double>& x, const std::vector<double>& e, double tau,
                                        const std::function<double(double)>& error_at, int steps) {
  size_t within = 0;  // how many leading samples are within τ
  while (within < e.size() && e[within] <= tau) ++within;
  if (within == 0) return {"never", x.front()};
  if (within == e.size()) return {"always", x.back()};
  const size_t k = within - 1;
  return {"found", bisect_log(error_at, {x[k], e[k], x[k + 1], e[k + 1]}, tau, steps).eps_within};
}

// A limit-mode solve of the dovetail on its shared factorisation (seconds, for spreading).
constexpr double limit_cost = 0.02;

}  // namespace

std::vector<ThresholdCrossing> run_thresholds_study(const ThresholdsStudyOptions& options, DovetailLimitBulk& bulk,
                                                    H5Writer* out, std::vector<Check>& checks) {
  if (!(options.ratio_min > 0) || !(options.ratio_max > options.ratio_min) || options.points_per_decade < 1)
    throw std::invalid_argument("thresholds: need 0 < ratio_min < ratio_max and points_per_decade >= 1");
  const double f = dovetail::friction;
  const std::vector<Sweep> sweeps = {
      {"lambda", dovetail::lambda_m, [f](double v) { return InterfaceLaw::make(v, dovetail::mu_m, f); }},
      {"mu", dovetail::mu_m, [f](double v) { return InterfaceLaw::make(dovetail::lambda_m, v, f); }}};
  Solver solver(bulk, options.tolerance);
  const std::vector<std::string> quantities = {"sigma", "u"};
  const int n = static_cast<int>(std::round(std::log10(options.ratio_max / options.ratio_min) * options.points_per_decade));

  std::printf("\nClassification thresholds (S4, paper 3.3): error of replacing the finite law by the 0 or inf law,\n"
              "relative distances of the stress vector on S ('sigma', scale mu_m U/L) and of the adherents' displacements\n"
              "('u', scale U) (dovetail, limit mode); ratio = lambda_bar/(lambda_m/L)\n"
              "with mu_bar = mu_m/L, or mu_bar/(mu_m/L) with lambda_bar = lambda_m/L; paper: 0 below %g, inf above %g\n\n",
              options.threshold_low, options.threshold_high);
  // The sweeps' solves (the 0 and inf laws and every ratio), spread over the MPI ranks (if any),
  // one at a time on each (they share the bulk's factorisation); the bisections below depend
  // on them and run on every rank alike.
  std::vector<double> ratio;
  for (int i = 0; i <= n; ++i)
    ratio.push_back(options.ratio_min * std::pow(10.0, static_cast<double>(i) / options.points_per_decade));
  std::vector<std::vector<Response>> swept(sweeps.size(), std::vector<Response>(ratio.size() + 2));
  SceneBatch batch("thresholds", 1, false);
  for (size_t k = 0; k < sweeps.size(); ++k) {
    const Sweep& s = sweeps[k];
    batch.add(s.param + " 0 law", limit_cost, swept[k][0], [&, k] { return solver.solve_uncounted(sweeps[k].law(0.0)); });
    batch.add(s.param + " inf law", limit_cost, swept[k][1], [&, k] { return solver.solve_uncounted(sweeps[k].law(inf)); });
    for (size_t i = 0; i < ratio.size(); ++i)
      batch.add(s.param + " ratio " + sci(ratio[i], 2), limit_cost, swept[k][i + 2],
                [&, k, i] { return solver.solve_uncounted(sweeps[k].law(ratio[i] * sweeps[k].reference)); });
  }
  batch.run();

  std::vector<ThresholdCrossing> crossings;
  for (size_t k = 0; k < sweeps.size(); ++k) {
    const Sweep& s = sweeps[k];
    const Response zero_law = solver.count(swept[k][0]), inf_law = solver.count(swept[k][1]);
    const auto finite = [&](double ratio) { return solver.solve(s.law(ratio * s.reference)); };
    std::map<std::string, std::vector<double>> e_zero, e_inf;  // per quantity
    for (size_t i = 0; i < ratio.size(); ++i) {
      const Response r = solver.count(swept[k][i + 2]);
      for (const std::string& q : quantities) {
        e_zero[q].push_back(solver.error(q, r, zero_law));
        e_inf[q].push_back(solver.error(q, r, inf_law));
      }
    }
    for (const std::string& q : quantities)
      for (const char* law : {"0", "inf"}) {
        const bool zero = std::string(law) == "0";
        const Response& replaced = zero ? zero_law : inf_law;
        const double threshold = zero ? options.threshold_low : options.threshold_high;
        const double at_threshold = solver.error(q, finite(threshold), replaced);
        // As a function of x = ρ (0 law) or x = 1/ρ (∞ law) the error grows with x: the crossing
        // is the largest x with error ≤ τ.
        auto e_of_x = [&](double x) { return solver.error(q, finite(zero ? x : 1 / x), replaced); };
        // The sweep in x, ascending.
        std::vector<double> x = ratio, e = zero ? e_zero[q] : e_inf[q];
        if (!zero) {
          for (double& v : x) v = 1 / v;
          std::reverse(x.begin(), x.end());
          std::reverse(e.begin(), e.end());
        }
        for (double tau : options.taus) {
          const auto [status, x_crossing] = crossing(x, e, tau, e_of_x, options.bisection_steps);
          crossings.push_back({s.param, law, q, tau, status, zero ? x_crossing : 1 / x_crossing, at_threshold,
                               at_threshold <= tau});
        }
      }
    if (out) {
      const std::string g = "/studies/thresholds/" + s.param;
      out->dataset(g + "/ratio", ratio);
      out->dataset(g + "/error_zero", e_zero[options.quantity]);
      out->dataset(g + "/error_inf", e_inf[options.quantity]);
      for (const std::string& q : quantities) {
        out->dataset(g + "/error_zero_" + q, e_zero[q]);
        out->dataset(g + "/error_inf_" + q, e_inf[q]);
      }
      out->attr(g, "quantity", options.quantity);
      out->attr(g, "fixed_other", s.param == "lambda" ? std::string("mu_bar = mu_m/L = 5400 daN/mm^3")
                                                      : std::string("lambda_bar = lambda_m/L = 4500 daN/mm^3"));
    }
  }

  std::printf("%-7s %-4s %-6s %-5s | %-8s %-10s | %-22s %s\n", "param", "law", "error", "tau", "status", "crossing",
              "error at paper's threshold", "confirmed");
  for (const ThresholdCrossing& c : crossings)
    std::printf("%-7s %-4s %-6s %-5g | %-8s %-10s | %-8s at %-12g %s\n", c.param.c_str(), c.law.c_str(), c.quantity.c_str(), c.tau,
                c.status.c_str(), sci(c.ratio, 2).c_str(), sci(c.error_at_threshold, 2).c_str(),
                c.law == "0" ? options.threshold_low : options.threshold_high, c.confirmed ? "yes" : "no");
  std::printf("(%d limit-mode solves, %d not converged)\n", solver.solves(), solver.failures());
  checks.push_back({"thresholds.solves_converged", solver.failures() == 0,
                    "every solve at residual <= " + sci(options.tolerance, 0), std::to_string(solver.failures()) + " of " +
                    std::to_string(solver.solves()) + " did not converge", sci(options.tolerance, 0)});

  if (out) {
    ColumnTable table;
    std::string summary;
    for (const ThresholdCrossing& c : crossings) {
      table.add("param", c.param);
      table.add("law", c.law);
      table.add("quantity", c.quantity);
      table.add("tau", c.tau);
      table.add("ratio", c.ratio);
      table.add("status", c.status);
      table.add("error_at_threshold", c.error_at_threshold);
      table.add("confirmed", c.confirmed ? 1 : 0);
      if (c.quantity != options.quantity) continue;
      char line[160];
      std::snprintf(line, sizeof line, "%s%s %s-law at tau %g: %s", summary.empty() ? "" : "; ", c.param.c_str(),
                    c.law.c_str(), c.tau, c.confirmed ? "confirmed" : "not confirmed");
      summary += line;
    }
    const std::string g = "/studies/thresholds/crossings";
    table.write(*out, g);
    for (const std::string& group : {std::string("/studies/thresholds"), g}) {
      out->attr(group, "threshold_low", options.threshold_low);
      out->attr(group, "threshold_high", options.threshold_high);
      out->attr(group, "confirmed", summary);
    }
  }
  return crossings;
}

}  // namespace thinlayer
