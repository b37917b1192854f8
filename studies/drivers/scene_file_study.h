#pragma once
// S2 and S3 (SPEC §3) on a user's scene file (SPEC §5): the distance between the layer mode at
// every ε of the scene's grid and the limit mode, its fitted rates, and the largest ε at which
// the limit law stays within τ of the layer model (bisection on log ε between the samples).
// The distances: studies/tools/scene_distance.h.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/tools/rate_fit.h"
#include "cases/scene/scene_file_scenes.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

struct SceneStudyOptions {
  std::vector<double> eps = {1e-2, 5e-3, 1e-3, 5e-4, 1e-4};  // the scene's "eps" replaces it
  double tolerance = 1e-10;   // the SPEC residual every scene is solved to
  int threads = 2;            // layer scenes solved at once
  bool verbose = true;
  std::vector<double> taus = {0.01, 0.05};
  int bisection_steps = 2;
  bool validity = false;      // also S3
  double rate_tolerance = 0.15;  // |p_fit − p_predicted| allowed, as the dovetail's S2 check
};

struct SceneSample {
  double eps = 0;
  std::map<std::string, double> e;  // quantity → distance to the limit mode
  int status_diff = 0;              // S nodes whose combined status differs from the limit's
  bool converged = false;
  double residual = 0, time_s = 0;
  int iterations = 0;
  std::string id;
};

struct SceneValidityRow {
  double tau = 0;
  std::string status;  // found | at_least | below_range (as studies/drivers/validity_study.h)
  double eps_max = 0, error_at_eps_max = 0, eps_beyond = 0;
  int bisection_steps = 0;
  bool converged = true;
};

struct SceneStudyResult {
  std::string limit_id;
  bool limit_converged = false;
  double limit_residual = 0;
  std::vector<SceneSample> samples;  // by decreasing ε
  std::map<std::string, std::optional<PowerLawFit>> fit;
  std::map<std::string, std::optional<FlooredPowerLawFit>> floor_fit;
  std::optional<double> p_predicted;  // the Table 2 case with the scene's (γ, δ), if any
  std::vector<SceneValidityRow> validity;
  std::vector<Check> checks;
};

// Runs S2 (and S3 if options.validity), prints its tables, writes /studies/scene/<name>/ and
// every scene it solved under /scenes when `out` is given. Checks (ids "scene.<name>.*"): the
// limit and every layer scene converged; the distance u decreases as ε decreases; where the
// asymptotics predict a rate for the scene's (γ, δ), the floored rate of u within
// rate_tolerance of it.
SceneStudyResult run_scene_study(SceneFileBulk& bulk, const SceneStudyOptions& options, H5Writer* out);

}  // namespace thinlayer
