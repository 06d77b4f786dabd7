#pragma once
// Initial conditions SWIFT's reader accepts (read_ic_single, src/single_io.c, with the gas fields
// of its hydro schemes, e.g. src/hydro/SPHENIX/hydro_io.h): the Header attributes it reads
// (BoxSize, NumPart_Total, NumPart_Total_HighWord, Flag_Entropy_ICs, Dimension, ...), the Units
// group with its five attributes, and PartType0 with Coordinates and Velocities (N x 3),
// Masses, SmoothingLength, InternalEnergy and ParticleIDs, plus Density (optional for SWIFT,
// what sphv scores).
#include <array>
#include <filesystem>
#include <optional>

#include "verification/snapshot/snapshot.hpp"

namespace sphv {

// What a SWIFT IC file states beyond the particles.
struct SwiftIcHeader {
  std::array<double, 3> box{};   // the periodic box [0, box) per axis; every coordinate lies inside
  std::optional<double> gamma;   // the adiabatic index, written to HydroScheme for scorers (SWIFT's
                                 // read_ic ignores it; its own gamma is compiled in)
};

// SWIFT's cubic spline (M4, its default kernel) has the support radius kernel_gamma h, with
// kernel_gamma its value in src/kernel_hydro.h for the dimension: sphv's h is that support radius.
double swift_kernel_gamma(int dim);

// Writes s (sphv's columns; h is the support radius) as SWIFT initial conditions, atomically:
// SmoothingLength = h / swift_kernel_gamma(dim), ParticleIDs 1..N, unit system all 1 (sphv's
// quantities are dimensionless).
void write_swift_ic(const Snapshot& s, const SwiftIcHeader& header, const std::filesystem::path& path);

}  // namespace sphv
