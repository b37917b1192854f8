#include "studies/tools/scene_generator.h"

#include "cases/bar/bar.h"
#include "cases/dovetail/dovetail_mesh.h"

#include <cmath>
#include <cstdio>
#include <random>

namespace thinlayer {

namespace {

// Uniform draws in [0, 1) from the generator's raw 64-bit output: the same on every library.
class Draws {
 public:
  explicit Draws(int seed) : engine_(0x5eed0000ULL + static_cast<unsigned long long>(seed)) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int integer(int lo, int hi) { return lo + static_cast<int>(uniform() * (hi - lo + 1)); }  // [lo, hi]

 private:
  std::mt19937_64 engine_;
};

constexpr double eps_min = 1e-8;
const char* const shipped_scenes[] = {"lap_joint/lap_joint.json", "double_lap/double_lap.json",
                                      "stepped_lap/stepped_lap.json"};

}  // namespace

GeneratedScene generate_scene(int seed, const GeneratorRanges& ranges) {
  Draws draw(seed);
  GeneratedScene s;
  s.seed = seed;
  const double which = draw.uniform();
  s.kind = which < 0.6 ? GeneratedScene::Kind::Dovetail : which < 0.8 ? GeneratedScene::Kind::Bar
                                                                        : GeneratedScene::Kind::SceneFile;
  switch (s.kind) {
    case GeneratedScene::Kind::Dovetail:
      if (draw.uniform() < 0.5) {
        s.law_case = "abcdefghi"[draw.integer(0, 8)];
        s.exponents = dovetail::exponents_of(s.law_case);
      } else {
        s.exponents = {draw.uniform(0.0, 2.0), draw.uniform(0.0, 1.95)};
      }
      s.eps = draw.log_uniform(eps_min, dovetail::thickest_layer);
      s.friction = draw.uniform();
      s.h_interface = draw.log_uniform(ranges.h_min, ranges.h_max);
      s.layer_elements = draw.integer(2, 4);
      break;
    case GeneratedScene::Kind::Bar:
      s.bar_row = draw.integer(1, 6);
      s.eps = draw.log_uniform(eps_min, bar::thickest_layer);
      s.bar_nx = static_cast<int>(std::lround(draw.log_uniform(16, ranges.bar_nx_max)));
      s.layer_elements = draw.integer(2, 4);
      s.load_scale = draw.log_uniform(0.1, 10.0);
      break;
    case GeneratedScene::Kind::SceneFile:
      s.scene_file = shipped_scenes[draw.integer(0, 2)];
      // The file's own limit is known only once it is meshed: ε is drawn as a fraction of it,
      // log-uniform down to 1e-8 of its value in mm (the thickest of the shipped joints are ~0.1-1 mm).
      s.eps_fraction = draw.log_uniform(eps_min, 1.0);
      break;
  }
  return s;
}

std::string GeneratedScene::describe() const {
  char buf[256];
  switch (kind) {
    case Kind::Dovetail:
      if (law_case)
        std::snprintf(buf, sizeof buf, "seed %d: dovetail case %c, eps %.2e, f %.2f, h %.4f, %d across", seed, law_case,
                      eps, friction, h_interface, layer_elements);
      else
        std::snprintf(buf, sizeof buf, "seed %d: dovetail gamma %.2f delta %.2f, eps %.2e, f %.2f, h %.4f, %d across",
                      seed, exponents.gamma, exponents.delta, eps, friction, h_interface, layer_elements);
      break;
    case Kind::Bar:
      std::snprintf(buf, sizeof buf, "seed %d: bar row %d, eps %.2e mm, nx %d, %d across, load x %.2f", seed, bar_row,
                    eps, bar_nx, layer_elements, load_scale);
      break;
    case Kind::SceneFile:
      std::snprintf(buf, sizeof buf, "seed %d: %s, eps %.2e of its thickest", seed, scene_file.c_str(), eps_fraction);
      break;
  }
  return buf;
}

}  // namespace thinlayer
