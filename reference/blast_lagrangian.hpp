#pragma once
#include <functional>

#include "reference/lagrangian_1d.hpp"

namespace reference {

// The Sedov blast as sphv's case poses it, from a deposit of finite size: a uniform gas of density
// rho0 at rest with specific internal energy u_ambient, to which the energy E is added as heat
// with a radial shape w(r) (the heat per unit mass at r proportional to w(r)), in cylindrical (2D)
// or spherical (3D) symmetry, solved by the 1D Lagrangian mesh of reference/lagrangian_1d.hpp
// with a wall at r_out. The point blast (reference/sedov.hpp) is its limit as the deposit
// shrinks; at a fixed deposit radius the two differ at every time by the deposit's memory (the
// hot, nearly empty centre is made from the deposit's gas).
//
// Zones of equal initial width r_out / N; zone k holds u_ambient plus the share
// int_zone w dV / int_0^r_out w dV of E (4-point Gauss-Legendre per zone), as SPH shares E over
// its particles by w(r_i).
struct BlastOptions {
  int dim = 2;
  double gamma = 5.0 / 3.0;
  double E = 1.0, rho0 = 1.0, u_ambient = 1e-6;
  double t_end = 0.0;
  double r_out = 0.5;  // the wall, beyond the shock at t_end
  int zones = 2000;
  std::function<double(double)> deposit;  // w(r) >= 0, positive somewhere inside r_out
};

// The profiles at t_end. Throws std::invalid_argument for dim other than 2 or 3, gamma <= 1,
// E, rho0, u_ambient, t_end or r_out not positive, fewer than 2 zones, a deposit that is empty
// or nowhere positive, or a state gone bad (reference/lagrangian_1d.hpp).
RadialProfile blast_lagrangian(const BlastOptions& o);

}  // namespace reference
