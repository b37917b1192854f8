#include "studies/parallel/result_bytes.h"

namespace thinlayer {

void put(ByteWriter& w, const StatusCount& c) { put(w, c.gap), put(w, c.slide), put(w, c.stick); }
void get(ByteReader& r, StatusCount& c) { get(r, c.gap), get(r, c.slide), get(r, c.stick); }

void put(ByteWriter& w, const LayerCounts& c) { put(w, c.plus_face), put(w, c.minus_face), put(w, c.combined); }
void get(ByteReader& r, LayerCounts& c) { get(r, c.plus_face), get(r, c.minus_face), get(r, c.combined); }

void put(ByteWriter& w, const MeshQuality& q) {
  put(w, q.min_angle_deg), put(w, q.max_angle_deg), put(w, q.max_aspect_ratio), put(w, q.min_scaled_jacobian);
  put(w, q.cells);
}
void get(ByteReader& r, MeshQuality& q) {
  get(r, q.min_angle_deg), get(r, q.max_angle_deg), get(r, q.max_aspect_ratio), get(r, q.min_scaled_jacobian);
  get(r, q.cells);
}

void put(ByteWriter& w, const SolveReport& s) {
  put(w, s.solver), put(w, s.u), put(w, s.r), put(w, s.w), put(w, s.iterations);
  put(w, s.residual.interface), put(w, s.residual.bulk), put(w, s.residual.per_interface), put(w, s.residual.per_body);
  put(w, s.residual.per_body_floor), put(w, s.residual.per_body_nodal_floor), put(w, s.residual.per_interface_floor);
  put(w, s.tolerance), put(w, s.converged);
  put(w, s.stop_cause), put(w, s.condition_estimate), put(w, s.wall_time_s), put(w, s.message);
}
void get(ByteReader& r, SolveReport& s) {
  get(r, s.solver), get(r, s.u), get(r, s.r), get(r, s.w), get(r, s.iterations);
  get(r, s.residual.interface), get(r, s.residual.bulk), get(r, s.residual.per_interface), get(r, s.residual.per_body);
  get(r, s.residual.per_body_floor), get(r, s.residual.per_body_nodal_floor), get(r, s.residual.per_interface_floor);
  get(r, s.tolerance), get(r, s.converged);
  get(r, s.stop_cause), get(r, s.condition_estimate), get(r, s.wall_time_s), get(r, s.message);
}

void put(ByteWriter& w, const InterfaceFields& f) {
  put(w, f.name), put(w, f.x), put(w, f.normal), put(w, f.length), put(w, f.jump_N), put(w, f.jump_T);
  put(w, f.sigma_N), put(w, f.sigma_T), put(w, f.status), put(w, f.node_plus), put(w, f.node_minus);
}
void get(ByteReader& r, InterfaceFields& f) {
  get(r, f.name), get(r, f.x), get(r, f.normal), get(r, f.length), get(r, f.jump_N), get(r, f.jump_T);
  get(r, f.sigma_N), get(r, f.sigma_T), get(r, f.status), get(r, f.node_plus), get(r, f.node_minus);
}

void put(ByteWriter& w, const SceneRecord& s) {
  put(w, s.id), put(w, s.text), put(w, s.numbers), put(w, s.integers), put(w, s.nodes), put(w, s.cells);
  put(w, s.u), put(w, s.body_names), put(w, s.cell_body), put(w, s.cell_stress), put(w, s.interfaces);
  put(w, s.reactions), put(w, s.combined_status), put(w, s.residual_per_body), put(w, s.residual_per_interface);
  put(w, s.residual_floor_per_body), put(w, s.residual_nodal_floor_per_body), put(w, s.residual_floor_per_interface);
  put(w, s.interface_names);
}
void get(ByteReader& r, SceneRecord& s) {
  get(r, s.id), get(r, s.text), get(r, s.numbers), get(r, s.integers), get(r, s.nodes), get(r, s.cells);
  get(r, s.u), get(r, s.body_names), get(r, s.cell_body), get(r, s.cell_stress), get(r, s.interfaces);
  get(r, s.reactions), get(r, s.combined_status), get(r, s.residual_per_body), get(r, s.residual_per_interface);
  get(r, s.residual_floor_per_body), get(r, s.residual_nodal_floor_per_body), get(r, s.residual_floor_per_interface);
  get(r, s.interface_names);
}

void put(ByteWriter& w, const BarScene& s) { put(w, s.record), put(w, s.report), put(w, s.counts); }
void get(ByteReader& r, BarScene& s) { get(r, s.record), get(r, s.report), get(r, s.counts); }

void put(ByteWriter& w, const BarLayerScene& s) {
  put(w, s.record), put(w, s.report), put(w, s.counts), put(w, s.layer_quality);
}
void get(ByteReader& r, BarLayerScene& s) {
  get(r, s.record), get(r, s.report), get(r, s.counts), get(r, s.layer_quality);
}

void put(ByteWriter& w, const DovetailScene& s) {
  put(w, s.record), put(w, s.report), put(w, s.limit), put(w, s.counts), put(w, s.layer_quality);
  put(w, s.meshing_time_s);
}
void get(ByteReader& r, DovetailScene& s) {
  get(r, s.record), get(r, s.report), get(r, s.limit), get(r, s.counts), get(r, s.layer_quality);
  get(r, s.meshing_time_s);
}

void put(ByteWriter& w, const MapCellLevel& c) {
  put(w, c.h), put(w, c.converged), put(w, c.failure), put(w, c.layer_residual), put(w, c.limit_residual);
  put(w, c.measured), put(w, c.estimate), put(w, c.interior), put(w, c.order1), put(w, c.order1_interior);
  put(w, c.layer_time_s), put(w, c.limit_time_s), put(w, c.estimate_time_s);
}
void get(ByteReader& r, MapCellLevel& c) {
  get(r, c.h), get(r, c.converged), get(r, c.failure), get(r, c.layer_residual), get(r, c.limit_residual);
  get(r, c.measured), get(r, c.estimate), get(r, c.interior), get(r, c.order1), get(r, c.order1_interior);
  get(r, c.layer_time_s), get(r, c.limit_time_s), get(r, c.estimate_time_s);
}

void put(ByteWriter& w, const MapCell& c) {
  put(w, c.spec.t_over_L), put(w, c.spec.E_ratio), put(w, c.spec.nu), put(w, c.thickness), put(w, c.E), put(w, c.shear_lag);
  put(w, c.law_case), put(w, c.rule_case), put(w, c.coarse), put(w, c.fine);
  put(w, c.rule_solved), put(w, c.rule_converged), put(w, c.rule_measured);
}
void get(ByteReader& r, MapCell& c) {
  get(r, c.spec.t_over_L), get(r, c.spec.E_ratio), get(r, c.spec.nu), get(r, c.thickness), get(r, c.E), get(r, c.shear_lag);
  get(r, c.law_case), get(r, c.rule_case), get(r, c.coarse), get(r, c.fine);
  get(r, c.rule_solved), get(r, c.rule_converged), get(r, c.rule_measured);
}

}  // namespace thinlayer
