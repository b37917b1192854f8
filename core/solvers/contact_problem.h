#pragma once
// The discrete interface problem shared by every solver (paper §4, SPEC §1.4-1.5):
//
//   K u = F + Bᵀ r,       jumps g = B u + g_D,       d = g + C r,
//
// with one (N, T) pair of rows per interface node: r = (r_N, r_T) are the nodal interface
// forces acting on the plus side (daN per unit thickness: r = ℓ σ), C = diag(1 / (K ℓ)) the
// compliance of the layer's springs (0 for a rigid law), and d the part of the jump taken by
// the stop and the skidding block. At every node the law then reads (Signorini-Coulomb on d):
//   r_N ≤ 0, d_N ≤ 0, r_N d_N = 0;   |r_T| ≤ f |r_N|, d_T = -ζ r_T, ζ ≥ 0,
// and r_N = 0 (r_T = 0) wherever K_N = 0 (K_T = 0). A bilateral law (a bonded face, SPEC §1.6)
// reads d_N = 0 and d_T = 0 for either sign of r instead (core/interface/law.h).
#include <algorithm>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/fem/linear_system.h"
#include "core/interface/interface.h"

namespace thinlayer {

enum class NodeStatus { Gap = 0, Slide = 1, Stick = 2 };

class ContactProblem {
 public:
  ContactProblem(const LinearSystem& system, std::vector<Interface> interfaces);

  const LinearSystem& system() const { return *system_; }
  const std::vector<Interface>& interfaces() const { return interfaces_; }
  int num_nodes() const { return static_cast<int>(nodes_.size()); }  // all interfaces, in order
  const InterfaceNode& node(int k) const { return nodes_[k]; }
  const InterfaceLaw& law(int k) const { return interfaces_[interface_of_[k]].law; }
  int interface_of(int k) const { return interface_of_[k]; }

  const Eigen::SparseMatrix<double>& B() const { return B_; }     // 2m × free DOFs
  const Eigen::VectorXd& jump_offset() const { return g_D_; }      // 2m, mm
  const Eigen::VectorXd& compliance() const { return C_; }         // 2m, mm/daN (may be +inf)
  // Natural-map scaling per row (daN/mm): the local stiffness seen by that interface
  // component, so that r - proj(r - κ d) is a force.
  const Eigen::VectorXd& kappa() const { return kappa_; }

  Eigen::VectorXd jumps(const Eigen::VectorXd& u_free) const { return B_ * u_free + g_D_; }
  // d = B u + g_D + C r (mm): the part of the jump the stop and the skidding block take, what the
  // natural map's status guess reads (C r only where the spring is finite: a rigid law's C is +inf).
  Eigen::VectorXd stop_jumps(const Eigen::VectorXd& u_free, const Eigen::VectorXd& r) const;

 private:
  const LinearSystem* system_;
  std::vector<Interface> interfaces_;
  std::vector<InterfaceNode> nodes_;
  std::vector<int> interface_of_;
  Eigen::SparseMatrix<double> B_;
  Eigen::VectorXd g_D_, C_, kappa_;
};

// SPEC §1.5: the residual every solver is judged by, interface by interface and body by body,
// evaluated in extended precision (long double products and sums): its value is the answer's own,
// not that of evaluating it in double, so a residual above the tolerance is the answer's, and
// within its floor only where the answer's digits allow no better (SPEC §1.5, "round-off floor").
//  - interface i: ‖natural map on i‖ / max(‖r_i‖, floor), the map being a force (r minus its
//    projection, see natural_map);
//  - body b: ‖K_b u_b - F_b - (Bᵀ r)_b‖ / max(‖F_b‖, ‖(Bᵀ r)_b‖, floor).
// A floating layer carries forces far smaller than the adherents: a global norm would hide its
// imbalance, a per-body one does not. The floor is residual_load_floor · ‖F‖ (F the whole
// load): an interface that opens everywhere, or a body that carries nothing, is judged against a
// millionth of the load rather than against round-off forces. A millionth because the status
// classification (SPEC §1.2) does not resolve stresses below 1e-6 of the largest either.
constexpr double residual_load_floor = 1e-6;

struct Residual {
  double interface = 0;              // the largest interface residual
  double bulk = 0;                   // the largest body residual
  std::vector<double> per_interface; // in the order of ContactProblem::interfaces()
  std::vector<double> per_body;      // in the order of Model::bodies (LinearSystem::body_name)
  // The round-off floor of each body's residual: what evaluating K_b u_b − F_b − (Bᵀ r)_b in
  // double precision from these u and r can resolve, u_eps ‖|K_b||u_b| + |F_b| + |(Bᵀ r)_b|‖
  // relative to the same scale (u_eps = 2⁻⁵³); for a band given in its column basis, the same
  // bound of that evaluation (|K_z||z| …, carried to nodal forces). In the nodal basis a stiff
  // layer whose film moved far holds its compression, 1e-9 mm, in the last digits of a
  // displacement of 1e-2 mm: no nodal answer stored in double has a smaller residual than this.
  std::vector<double> per_body_floor;
  // The same bound for the nodal u alone (K_b u_b evaluated nodally, as a user re-evaluating the
  // written `u` would): equal to per_body_floor except on a band given in its column basis.
  std::vector<double> per_body_nodal_floor;
  // The round-off floor of each interface's residual: what rounding the answer's u and r to double
  // moves its natural map by, u_eps ‖|r| + κ (|B||u| + |g_D| + |C r|)‖ relative to the same scale (a film
  // that slid 35 mm holds its normal jump, 1e-20 mm, in the last digits of its position).
  std::vector<double> per_interface_floor;
  double value() const { return std::max(interface, bulk); }
  double floor() const;              // the largest floor, body or interface
};
// band_z: the displacement of each layer band (LinearSystem::floating_bands, in order) in its
// column basis z (core/fem/column_basis.h), when the solver has it (empty: nodal u only). A band's
// imbalance is then evaluated where its digits are, K_z z − F_z − (column forces of Bᵀ r) mapped
// back to nodal forces by the exact inverse map: the same K_b u_b − F_b − (Bᵀ r)_b in exact
// arithmetic, without the round-off of a huge through-thickness stiffness times a film's
// translation (the nodal evaluation's floor, 1e-9 for the dovetail's case f at ε = 1e-8), and
// with the film's in-plane stiffness as accurate as its own size.
Residual contact_residual(const ContactProblem& problem, const Eigen::VectorXd& u_free,
                          const Eigen::VectorXd& r, const std::vector<Eigen::VectorXd>& band_z = {});

// Natural map of one node's law, given its forces r = (r_N, r_T) and d = (d_N, d_T).
Eigen::Vector2d natural_map(const InterfaceLaw& law, const Eigen::Vector2d& r, const Eigen::Vector2d& d,
                            const Eigen::Vector2d& kappa);

// Gap / slide / stick from the nodal stresses (SPEC §1.2), with a relative tolerance: gap when
// |σ_N| ≤ tol · max|σ_N| over the interface, slide when |σ_T| ≥ (1 - tol) f |σ_N|. A node of a
// bilateral (bonded) law is "stick" when it carries a stress, |σ_N| or |σ_T| above tol times the
// largest (tension included), else "gap": it never slides.
struct StatusCount {
  int gap = 0, slide = 0, stick = 0;
  bool operator==(const StatusCount&) const = default;
};
std::vector<NodeStatus> classify_statuses(const std::vector<InterfaceLaw>& laws,
                                          const Eigen::VectorXd& sigma_N,
                                          const Eigen::VectorXd& sigma_T, double tolerance);
StatusCount count_statuses(const std::vector<NodeStatus>& statuses);

// The adherents' median nodal stiffness (daN/mm) along the interfaces (a floating body's own where
// only floating bodies touch them): the scale of a floating layer's selection springs.
double adherent_stiffness(const ContactProblem& problem);

// The status of a point of S seen through the two faces of the layer (SPEC §2.2): gap if
// either face is open, else slide if either face slides, else stick.
NodeStatus combined_status(NodeStatus plus_face, NodeStatus minus_face);

}  // namespace thinlayer
