#pragma once
// Particles for gravity from a snapshot (sphv gravity --input, sphv score gravity): positions and
// masses checked so that the direct sum is finite.
#include <vector>

#include "verification/cases/gravity/models.hpp"
#include "verification/snapshot/snapshot.hpp"

namespace sphv {

// x, y, z (missing coordinates of a 1D/2D file are 0) and m of the snapshot. Refuses masses <= 0,
// and, with zero softening, particles at the same position (their mutual force is infinite):
// InputError naming the file and the particles.
gravity::ParticleSet gravity_particles(const Snapshot& s, double eps);

// The finite entries (relative errors of particles whose reference force is zero are not).
std::vector<double> finite_values(const std::vector<double>& v);

}  // namespace sphv
