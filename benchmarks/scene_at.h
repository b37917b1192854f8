#pragma once
// A scene file meshed at element size h along its bondlines, its far size in the file's own
// proportion (4 where the file gives none): the same h gives the same mesh in every benchmark
// driver (thinlayer_scaling, thinlayer_export_problem).
#include <string>

#include "cases/scene/scene_spec.h"

namespace thinlayer {

inline SceneSpec scene_at(const std::string& path, double h) {
  SceneSpec spec = read_scene_spec(path);
  const double far_ratio = spec.h_interface && spec.h_far ? *spec.h_far / *spec.h_interface : 4.0;
  spec.h_interface = h;
  spec.h_far = h * far_ratio;
  return spec;
}

}  // namespace thinlayer
