#include "core/solvers/solve_report.h"

namespace thinlayer {

const char* to_string(StopCause cause) {
  switch (cause) {
    case StopCause::Converged: return "converged";
    case StopCause::IterationCap: return "iteration cap";
    case StopCause::Singular: return "singular system";
    case StopCause::LossOfAccuracy: return "loss of accuracy";
    case StopCause::NonFinite: return "non-finite values";
    case StopCause::RoundOffFloor: return "round-off floor";
    case StopCause::LayerAdrift: return "layer adrift";
  }
  return "unknown";
}

}  // namespace thinlayer
