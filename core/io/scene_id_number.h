#pragma once
// A number as it goes into a scene id (/scenes/<id>): text that reads back as the same double.
// Two thicknesses that differ only beyond six digits (10^-5.5 computed as pow(10, -5.5) and as
// 1e-5 × 10^-0.5) are two scenes, and six digits gave them one id. Values that six digits
// represent exactly keep the form ids always had (0.0001, 5e-05, 3.16228e-06).
#include <string>

namespace thinlayer {

std::string scene_id_number(double x);

}  // namespace thinlayer
