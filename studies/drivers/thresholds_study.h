#pragma once
// Study S4 (SPEC §1.3, §3): the paper's §3.3 rule replaces a finite law by the 0 law when
// λ_ε/ε (or μ_ε/ε) is below 3 % of λ_m/L (μ_m/L), and by the ∞ law above 30 times it. On the
// dovetail in limit mode, sweep λ̄ = ρ λ_m/L (μ̄ held at μ_m/L) and μ̄ = ρ μ_m/L (λ̄ held at
// λ_m/L), and measure the error of each replacement: the relative distance between the
// stress vectors on S (and between the adherents' displacements) under the finite law and
// under the 0 or ∞ law. Then find, by
// bisection on log ρ, where that error crosses 1 % and 5 %, and read the paper's thresholds
// against it.
#include <string>
#include <vector>

#include "studies/tools/scene_cache.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

struct ThresholdsStudyOptions {
  double ratio_min = 1e-4, ratio_max = 1e4;
  int points_per_decade = 4;
  std::vector<double> taus = {0.01, 0.05};
  int bisection_steps = 40;          // limit-mode solves are cheap (milliseconds)
  double threshold_low = 0.03, threshold_high = 30;  // paper §3.3
  double tolerance = 1e-10;
  // The error measure the crossings table leads with: "sigma", the stress vector on S (the
  // load the joint transfers), relative L² with scale μ_m U/L; "u", the adherents'
  // displacements, is also reported (it is dominated by the tenon's imposed motion, so it
  // varies by a few % at most between the 0 and ∞ laws).
  std::string quantity = "sigma";
};

struct ThresholdCrossing {
  std::string param;  // "lambda" | "mu"
  std::string law;    // "0" | "inf"
  std::string quantity;  // "sigma" | "u"
  double tau = 0;
  // "found": the error equals τ at `ratio` (within the bisection's precision); "never": the
  // error stays above τ over the whole sweep; "always": below τ over the whole sweep.
  std::string status;
  double ratio = 0;
  double error_at_threshold = 0;  // the error at the paper's threshold (3 % for 0, 30 for ∞)
  bool confirmed = false;         // that error ≤ τ
};

std::vector<ThresholdCrossing> run_thresholds_study(const ThresholdsStudyOptions& options, DovetailLimitBulk& bulk,
                                                    H5Writer* out, std::vector<Check>& checks);

}  // namespace thinlayer
