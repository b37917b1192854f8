#include "studies/tools/limit_error_estimate.h"

#include <algorithm>

#include "studies/tools/scene_distance.h"

namespace thinlayer {

LimitErrorEstimate limit_error_estimate(const SceneFileBulk& bulk, const SceneFileScene& limit) {
  LimitErrorEstimate e;
  const SceneFirstOrder& first = limit.first_order;
  e.time_s = first.time_s;
  e.extra_factorisation = first.extra_factorisation;
  for (double t : first.thickness) e.eps = std::max(e.eps, t);
  if (!first.record) {
    e.note = first.note.empty() ? "not computed: the limit solve was not asked for it" : first.note;
    return e;
  }
  const std::map<std::string, double> d = scene_distance(bulk, *first.record, limit.record);
  e.computed = true;
  e.u = d.at("u");
  e.sigma_N = d.at("sigma_N");
  e.sigma_T = d.at("sigma_T");
  e.reactions = reaction_distance(*first.record, limit.record);
  return e;
}

}  // namespace thinlayer
