#include "studies/tools/refined_rate.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "studies/tools/cauchy_fit.h"
#include "studies/tools/format.h"

namespace thinlayer {

namespace {

// Items 1 and 2 of the rule for difference k, and the part of item 3 that does not look along
// the grid: "" if it may count.
std::string first_reason(const RefinedRateInput& in, const RefinedRateRule& rule, std::size_t k) {
  const std::string within = "within " + plain(rule.spread_factor) + "x the selections' spread";
  if (!in.answered[k] || !in.answered[k + 1]) return "a scene without an answer";
  if (!std::isfinite(in.difference[k]) || !(in.difference[k] > 0)) return "no difference";
  if (!std::isfinite(in.spread[k])) return "selection spread not measured";
  if (in.difference[k] <= rule.spread_factor * in.spread[k]) return within;
  if (in.eps[k] > rule.eps_max * (1 + 1e-9)) return "thicker than the tail";
  return "";
}

std::string two(double x) {
  if (!std::isfinite(x)) return "n/a";
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", x);
  return text;
}

}  // namespace

int RefinedRate::counted() const {
  int n = 0;
  for (const std::string& why : left_out) n += why.empty();
  return n;
}

RefinedRate refined_rate(const RefinedRateInput& in, const RefinedRateRule& rule) {
  const std::size_t n = in.eps.size();
  if (n < 2 || in.answered.size() != n || in.difference.size() + 1 != n || in.spread.size() + 1 != n ||
      in.status_changes.size() + 1 != n)
    throw std::invalid_argument("refined_rate: n thicknesses and answers, n - 1 differences, spreads and status changes");
  RefinedRate r;
  r.left_out.resize(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) r.left_out[k] = first_reason(in, rule, k);
  // Item 3's status rule: walking up from the thinnest pair, the first pair of answered scenes
  // whose statuses differ stops the tail (it and every thicker pair are out).
  bool changed = false;
  for (std::size_t k = n - 1; k-- > 0;) {
    const bool pair_answered = in.answered[k] && in.answered[k + 1];
    changed = changed || (pair_answered && in.status_changes[k] > 0);
    if (changed && r.left_out[k].empty()) r.left_out[k] = "above a status change";
  }
  // The thinnest run of at least `count` consecutive counted differences.
  for (int last = static_cast<int>(n) - 2; last >= 0 && r.run_last < 0;) {
    if (!r.left_out[last].empty()) {
      --last;
      continue;
    }
    int first = last;
    while (first > 0 && r.left_out[first - 1].empty()) --first;
    if (last - first + 1 >= rule.count) r.run_first = first, r.run_last = last;
    last = first - 1;
  }
  if (r.run_last < 0) return r;
  r.run_end_eps = in.eps[r.run_last + 1];
  r.run_reaches_end = r.run_last + 2 == static_cast<int>(n);
  const std::vector<double> eps(in.eps.begin() + r.run_first, in.eps.begin() + r.run_last + 2),
      d(in.difference.begin() + r.run_first, in.difference.begin() + r.run_last + 1);
  const CauchyTail tail = fit_cauchy_tail(eps, d, rule.count, rule.settle);
  r.fit = tail.fit;
  r.local_slopes = tail.local_slopes;
  r.settled = tail.settled;
  return r;
}

std::string RefinedVerdict::line() const {
  return rates + (established ? ": established" : ": not established: " + cause);
}

RefinedVerdict refined_verdict(const std::vector<MeshRate>& meshes, double p_predicted, const RefinedRateRule& rule) {
  RefinedVerdict v;
  std::vector<std::string> causes;
  for (const MeshRate& m : meshes) {
    std::string rate = m.mesh + " ";
    if (!m.run) {
      rate += "not run";
      causes.push_back(m.mesh + " not run");
    } else if (!m.rate.fit) {
      rate += "—";
      const int counted = m.rate.counted();
      causes.push_back(m.mesh + " too few points (" + std::to_string(counted) + (counted == 1 ? " difference" : " differences") +
                       " counted, " + std::to_string(rule.count) + " in a row needed)");
    } else {
      const std::vector<double>& s = m.rate.local_slopes;
      rate += two(m.rate.fit->p) + " (" + (s.size() >= 2 ? two(s[s.size() - 2]) + " " : "") +
              (s.empty() ? "" : two(s.back())) + (m.rate.run_reaches_end ? "" : "; to " + sci(m.rate.run_end_eps, 2)) + ")";
      if (std::abs(m.rate.fit->p - p_predicted) > rule.tolerance)
        causes.push_back(m.mesh + " " + two(m.rate.fit->p) + " outside " + plain(p_predicted) + " ± " + plain(rule.tolerance));
      if (!m.rate.settled)
        causes.push_back(m.mesh + " local slopes not settled (" + (s.size() >= 2 ? two(s[s.size() - 2]) : "n/a") + ", " +
                         two(s.empty() ? NAN : s.back()) + ")");
    }
    v.rates += (v.rates.empty() ? "" : ", ") + rate;
  }
  v.established = causes.empty();
  for (const std::string& c : causes) v.cause += (v.cause.empty() ? "" : "; ") + c;
  return v;
}

}  // namespace thinlayer
