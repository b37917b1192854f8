#pragma once
// Scenes of a user's scene file (SPEC §5), both modes: the limit mode's bulk is built and
// factored once and shared by every limit solve (whatever the laws); each layer scene builds its
// own model (the layers' moduli and the plus bodies' nodes depend on ε).
//
// ε, the layers' thickness: the same on every layer bondline when given (> 0), or 0 for each
// engineer's glue's own thickness. In limit mode it chooses an engineer's glue's law (SPEC §1.3
// at that thickness); the paper's family's law does not depend on it.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cases/layer_scene.h"
#include "cases/scene/load_path.h"
#include "cases/scene/scene_first_order.h"
#include "cases/scene/scene_model.h"
#include "core/fem/linear_system.h"
#include "core/interface/classifier.h"
#include "core/io/scene_record.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/solver_choice.h"

namespace thinlayer {

class SceneFileBulk {
 public:
  // Reads nothing: `spec` is already checked; meshes the geometry and checks the meshes
  // (InputError at the scene file's line and column).
  explicit SceneFileBulk(SceneSpec spec);
  // The same joint and meshes as `meshed`, another glue or law on its bondlines: `spec` differs from
  // meshed.spec() in its interfaces' "glue", "layer", "law" and "faces" at most (checked: the same
  // geometry or mesh, mesh size, bodies, bondline groups, supports and loads), so nothing is meshed
  // again. The validity map's cells (studies/drivers/validity_map.h): one joint, many glues.
  SceneFileBulk(const SceneFileBulk& meshed, SceneSpec spec);
  const SceneSpec& spec() const { return spec_; }
  const SceneMeshes& meshes() const { return meshes_; }
  const std::vector<SceneInterfaceNodes>& interface_nodes() const { return S_; }
  const Model& model() const { return model_; }
  const LinearSystem& system() const { return *system_; }
  const CondensedInterface& condensed();
  // The thickest common layer the joint allows (mm; 0 for a scene without a layer mode) and why.
  double thickest_layer() const { return thickest_.eps; }
  const std::string& thickest_reason() const { return thickest_.reason; }
  // SPEC §1.3's L (mm, cases/scene/scene_reference.h) and bondline i's reference.
  double characteristic_length() const { return L_; }
  AdherentData reference(int i) const;
  // The limit law of bondline i standing for layers of thickness eps (0: each glue's own): an
  // engineer's glue's finite springs at that thickness (SPEC §1.3), Table 1's for the paper's family.
  InterfaceLaw limit_law(int i, double eps) const;
  // What the paper's 3 % / 30x rule would choose instead for bondline i at eps (SPEC §1.3: shown
  // beside the law, with the distance it would cost; equal to limit_law but for an engineer's glue).
  InterfaceLaw classified_law(int i, double eps) const;
  // Some bondline gives an engineer's glue (its limit law depends on the thickness).
  bool has_engineer_glue() const;
  // Every bondline in limit mode, with its law at eps (geometry only: InterfaceLaw{} laws if !with_laws;
  // the paper's rule's laws, classified_law, if `classified`).
  std::vector<Interface> limit_interfaces(double eps, bool with_laws = true, bool classified = false) const;

 private:
  SceneSpec spec_;
  SceneMeshes meshes_;
  std::vector<SceneInterfaceNodes> S_;
  Model model_;
  ThickestLayer thickest_;
  double L_ = 0;
  std::unique_ptr<LinearSystem> system_;
  std::unique_ptr<CondensedInterface> condensed_;
};

// Throws std::invalid_argument unless the scene has a layer mode at thickness `eps` (mm; 0 for
// each glue's own): a "layer" or "glue" somewhere, Q1 elements (the band is Q1), and a thickness
// the joint can hold (saying why not).
void check_layer_mode(const SceneFileBulk& bulk, double eps);

// Does every load have a path to a support, and one inside the friction cones? What statics proves
// (cases/scene/load_path.h), on the model of `mode` ("limit" or "layer") at thickness eps (0: each
// glue's own), before the solve.
LoadPath scene_load_path(const SceneFileBulk& bulk, const std::string& mode, double eps);
// After a solve that failed: what friction alone had to hold, estimated from the joint held stuck.
std::vector<FrictionHold> scene_friction_estimate(const SceneFileBulk& bulk, const std::string& mode, double eps);

// What a scene did on one bondline.
struct SceneBondline {
  std::string name;        // its group in the list form, "" in the one-bondline form
  InterfaceLaw law;        // limit mode: the law solved; layer mode: the limit law of that layer
  InterfaceLaw classified; // what the paper's 3 % / 30x rule would choose for it (SPEC §1.3)
  double thickness = 0;    // layer mode: the layer's (mm); 0 in limit mode or for a law only
  LameModuli moduli;       // layer mode: λ_ε, μ_ε
  std::vector<int> status;  // per node of S: limit mode S's, layer mode the combined one
};

struct SceneFileScene {
  SceneRecord record;
  SolveReport report;
  StatusCount limit;          // limit mode: counts over every bondline
  LayerCounts counts;         // layer mode: per face and combined, over every layer bondline
  MeshQuality layer_quality;  // layer mode: every layer's together (cells summed, the worst angles and ratio)
  std::vector<SceneBondline> bondlines;
  std::map<std::string, Eigen::Vector2d> loads;  // each load group's resultant force (force unit per mm)
  // false: every bondline node is open (SPEC §5), or the bondlines carry next to nothing — under
  // 1e-6 of the force the scene's loads and imposed displacements call for (a law with no stiffness
  // along the load: the steel single lap under a μ̄ = 0 law carried 6.9e-12 N/mm, all "stick").
  bool carries_load = true;
  double bondline_force = 0;  // Σ |σ| ℓ over every bondline's plus face, force unit per mm
  double force_scale = 0;     // the loads' resultants and E × |u| of each imposed displacement, force per mm
  SceneFirstOrder first_order;  // limit mode, when asked: the layer's first-order answer (SPEC §3 S6)
};

// What a limit solve may do beyond its bondlines' own laws.
struct LimitSolveExtras {
  // One law per bondline, solved instead of bulk.limit_law(i, eps) (empty: those): a study that
  // states the law it compares (the validity map, SPEC §3 S3) gives it here.
  std::vector<InterfaceLaw> laws;
  // Also the first-order answer of the layers of thickness eps behind the laws (SPEC §3 S6), and
  // (first_order_interior) the same without the end cells (SceneFirstOrder::interior).
  bool first_order = false;
  bool first_order_interior = false;
};

// `classified`: solve with the laws the paper's 3 % / 30x rule would choose (classified_law) instead of
// the scene's own, to measure what that choice costs (SPEC §1.3); its id ends in "-classified".
SceneFileScene solve_scene_file_limit(SceneFileBulk& bulk, SolverKind solver, const SolverOptions& options,
                                      double eps = 0, double status_tolerance = default_status_tolerance,
                                      bool classified = false, const LimitSolveExtras& extras = {});
// Throws std::invalid_argument for an ε the joint's geometry does not allow.
SceneFileScene solve_scene_file_layer(const SceneFileBulk& bulk, double eps, SolverKind solver,
                                      const SolverOptions& options, double status_tolerance = default_status_tolerance);

// Writes the scene as every record (core/io/scene_record.h), and what a scene file adds: the
// applied loads and the supports (`loads/<group>`: kind, the given value, the resultant;
// `supports/<group>`: u, held), each bondline's law, glue, faces and reference (attributes of
// `interface` in the one-bondline form, `interface/<group>` in the list form; there also each
// layer bondline's `combined_status`), the units and L.
void write_scene_file_scene(H5Writer& file, const SceneFileScene& scene, const SceneFileBulk& bulk);

// The record's interface holding bondline i's stresses on the plus adherent: S (limit, or a law
// only) or S+ (a layer). Its index in record.interfaces.
int plus_face_of(const SceneFileBulk& bulk, const SceneRecord& record, int i);

}  // namespace thinlayer
