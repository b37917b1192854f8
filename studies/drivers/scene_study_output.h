#pragma once
// What a scene-file study prints and writes (studies/drivers/scene_file_study.h): its tables on
// stdout, /studies/scene/<name>/ in the results file (every dataset with its units and a
// description), every scene it solved under /scenes, and the bondline fields of every scene as
// CSV beside the results file.
#include <memory>
#include <vector>

#include "studies/drivers/scene_file_study.h"

namespace thinlayer {

// One level of the mesh-floor study: its own re-meshed scene and both modes on it.
struct FloorScenes {
  std::unique_ptr<SceneFileBulk> bulk;
  SceneFileScene layer, limit;
};

void print_scene_study(const SceneFileBulk& bulk, const SceneStudyResult& r, const SceneStudyOptions& options);
void print_scene_floor(const SceneStudyResult& r);
// The bondline ends: the peaks at d and at the corners under mesh refinement (the floor's meshes),
// both modes: the corner of the layer model is singular (it grows as h shrinks), d's value converges.
void print_scene_ends(const SceneStudyResult& r);
// The verdict, one line per quantity (reactions, u, peak peel and peak shear at d).
void print_scene_validity(const SceneStudyResult& r, int steps);
// A verdict quantity as words: "reactions", "adherents' displacements", "peak peel at 0.5 mm from the ends", ...
std::string verdict_label(const std::string& quantity, double d);

// /studies/scene/<name>/ (eps, e_*, cauchy/, floor/, peaks/, validity/), the scenes (the floor's
// with "-h<h>" after their id), and <results folder>/bondline_fields.csv.
void write_scene_study(H5Writer& out, const SceneFileBulk& bulk, const SceneStudyResult& r, const SceneStudyOptions& o,
                       const std::vector<const SceneFileScene*>& scenes, const std::vector<FloorScenes>& floor);

// The CSV of the bondline fields of some scenes (header comment lines start with '#').
struct ScenesOnBulk {
  const SceneFileBulk* bulk = nullptr;
  const SceneFileScene* scene = nullptr;
  std::string id;  // as written
  double h = 0;    // mm, the element size along the bondlines (0: the scene's own mesh)
};
std::string bondline_fields_csv(const std::vector<ScenesOnBulk>& scenes);

}  // namespace thinlayer
