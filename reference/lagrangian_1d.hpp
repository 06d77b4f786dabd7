#pragma once
#include <string>
#include <vector>

namespace reference {

// 1D Lagrangian hydrodynamics in cylindrical or spherical symmetry (von Neumann-Richtmyer
// staggered mesh), with self-gravity from the enclosed mass in spherical symmetry: the solver of
// the Evrard reference (evrard_lagrangian) and of the Sedov blast from its finite deposit
// (blast_lagrangian).
//
// N zones between nodes r_0 = 0 < r_1 < ... < r_N; zone k of mass dm_k holds rho, e (specific
// internal energy), p = (gamma - 1) rho e and the artificial viscosity
// q_k = rho_k (c2 dv^2 + c1 c_k |dv|) for dv = v_{k+1} - v_k < 0; node i carries mass
// m_i = (dm_{i-1} + dm_i) / 2 and velocity v_i. In dimension d the zone volumes are
// V_k = c_d (r_{k+1}^d - r_k^d) and the node areas A_i = dV/dr = d c_d r_i^(d-1) (c_2 = pi,
// c_3 = 4 pi / 3). The semi-discrete system
//   m_i dv_i/dt = A_i (P_{i-1} - P_i) - G m_i M_i / r_i^2 (the last term with self-gravity only),
//   dm_k de_k/dt = -P_k dV_k/dt,   P = p + q,
// with M_i = sum_{j<i} m_j + m_i / 2 (node shells as thin shells, the node at the centre a point
// mass) conserves E = sum_i m_i v_i^2 / 2 + sum_k dm_k e_k + W exactly, where
// W = -G sum_{i>=1} m_i M_i / r_i is the potential energy of the node shells (the force is
// -dW/dr_i; W = 0 without self-gravity). The centre's node stays put; outside the last node is
// vacuum (P_N = 0) or a wall (the last node held). Time integration: classical RK4 with
// dt = C min_k dr_k / (c_k + 2 (c1 c_k + c2 |dv_k|)), landing on the times asked for.
struct LagrangianOptions {
  int dim = 3;  // 2: cylindrical, 3: spherical
  double gamma = 5.0 / 3.0;
  double c1 = 0.5, c2 = 2.0;  // linear and quadratic artificial viscosity
  double courant = 0.25;
  bool self_gravity = false;  // G = 1; spherical (dim 3) only
  bool outer_wall = false;    // the last node held; otherwise vacuum outside it
  long max_steps = 10000000;
  std::string name = "1D Lagrangian reference";  // opens the messages of what it throws
};

// The mesh's state: node radii and velocities (0..N), zone specific internal energies (0..N-1).
struct LagrangianState {
  std::vector<double> r, v, e;
};

// A state as radial profiles: node radii and velocities, zone-centre radii (the mean of the zone's
// two nodes), densities and specific internal energies.
struct RadialProfile {
  std::vector<double> r_node, v, r_zone, rho, e;
};

class Lagrangian1D {
 public:
  // Zone masses dm (at least 2 zones). Throws std::invalid_argument for dim other than 2 or 3,
  // gamma <= 1, self-gravity outside dim 3, or fewer than 2 zones.
  Lagrangian1D(const LagrangianOptions& o, std::vector<double> dm);

  // RK4 steps from t to t_next (the last one lands on it); throws std::invalid_argument when a
  // zone's volume or energy turns non-positive or non-finite, or after max_steps steps in all.
  void advance(LagrangianState& s, double& t, double t_next);

  long steps() const { return steps_; }
  int zones() const { return n_; }
  double volume(const LagrangianState& s, int k) const { return shell_volume(o_.dim, s.r[k], s.r[k + 1]); }
  // c_d (r_b^d - r_a^d), the header's zone volume.
  static double shell_volume(int dim, double ra, double rb);
  const std::vector<double>& zone_mass() const { return dm_; }
  const std::vector<double>& node_mass() const { return mnode_; }
  const std::vector<double>& enclosed_mass() const { return menc_; }  // M_i
  RadialProfile profile(const LagrangianState& s) const;

 private:
  void rate(const LagrangianState& s, LagrangianState& d, double* step_of_zone = nullptr);
  LagrangianState sized() const;

  LagrangianOptions o_;
  int n_;
  std::vector<double> dm_, mnode_, menc_;
  long steps_ = 0;
  // The stages' arrays, kept from one step to the next: a step evaluates the rates four times,
  // and fresh arrays for each would take a large share of the solver's time.
  LagrangianState k1_, k2_, k3_, k4_, y_;
  std::vector<double> P_, step_of_zone_;
};

}  // namespace reference
