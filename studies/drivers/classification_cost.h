#pragma once
// What the paper's 3 % / 30x rule would cost an engineer's glue (SPEC §1.3). An engineer's glue
// keeps its finite spring law at its thickness; the rule of the paper's §3.3 — built for a family
// whose moduli go to 0 or ∞ with ε — would cut a coefficient to 0 or ∞ instead. The scene is solved
// once more in limit mode with the rule's laws, and the distance between the two answers printed
// beside the law: the reactions (every support together) and the adherents' displacements. Where
// the rule chooses the same law nothing is solved; where its solve fails, the cause is said.
#include <string>

#include "cases/scene/scene_file_scenes.h"

namespace thinlayer {

struct ClassificationCost {
  bool differs = false;     // some bondline's classified law differs from the one solved
  bool computed = false;    // the rule's laws were solved and converged
  std::string not_computed; // why not, where differs && !computed
  double reactions = 0;     // ‖R_rule − R‖ / ‖R‖ over every support group together
  double u = 0;             // the adherents' nodal displacements, relative L² (scale: the largest |u|)
};

// `scene`: the limit-mode answer with the scene's own laws at thickness `eps` (0: each glue's own).
ClassificationCost classification_cost(SceneFileBulk& bulk, const SceneFileScene& scene, double eps,
                                       const SolverOptions& options);

// One line for `solve`: "the paper's 3 % / 30x rule would choose ...: reactions X % apart, ..." or
// what was not computed; "" where the rule chooses the scene's own laws.
std::string classification_cost_line(const SceneFileBulk& bulk, const SceneFileScene& scene,
                                     const ClassificationCost& cost);

}  // namespace thinlayer
