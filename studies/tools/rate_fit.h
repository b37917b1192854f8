#pragma once
// The convergence rate p in e(ε) ≈ C ε^p, fitted by least squares on the log–log points.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace thinlayer {

struct PowerLawFit {
  double p = 0;         // the slope on log–log axes
  double C = 0;         // e(1) of the fitted line
  double p_stderr = 0;  // standard error of p: s / sqrt(Σ (ln ε - mean)²), s² = Σ residual² / (n - 2)
  int points = 0;       // the points used: those with e > 0
};

// Fits the points with e > 0 (a zero error has no logarithm: the modes agree there exactly).
// Empty when fewer than three such points remain (no standard error without a residual).
// Throws std::invalid_argument for mismatched sizes or ε ≤ 0.
std::optional<PowerLawFit> fit_power_law(const std::vector<double>& eps, const std::vector<double>& error);

// e(ε) ≈ e_∞ + C ε^p: a power law above a floor e_∞ ≥ 0 that does not shrink with ε (between
// the dovetail's modes, the misfit at the slot corners, which depends on the element size;
// SPEC §2.2). Least squares on relative residuals, (model − e)/e, so every point counts like
// on log–log axes: for each p on a fine grid the best (e_∞ ≥ 0, C) is linear least squares,
// then p is refined around the best grid point. p_stderr from the Jacobian of the three
// parameters (s² (JᵀJ)⁻¹, s² = Σ residual² / (n − 3)). Empty with fewer than 4 points.
struct FlooredPowerLawFit {
  double p = 0, C = 0, floor = 0;
  double p_stderr = 0;
  int points = 0;
};
std::optional<FlooredPowerLawFit> fit_power_law_with_floor(const std::vector<double>& eps,
                                                          const std::vector<double>& error);

// "p±se" of a fit, "n/a" without one.
std::string rate_text(const std::optional<PowerLawFit>& fit);
std::string rate_text(const std::optional<FlooredPowerLawFit>& fit);

// The three rows under a study's distance table, one column per quantity: the plain fit "p",
// the floored fit "p floor" and its floor "e_inf". label_width and column_width as the table's.
void print_fit_rows(const std::vector<std::string>& quantities,
                    const std::map<std::string, std::optional<PowerLawFit>>& fit,
                    const std::map<std::string, std::optional<FlooredPowerLawFit>>& floor_fit, int label_width,
                    int column_width);

}  // namespace thinlayer
