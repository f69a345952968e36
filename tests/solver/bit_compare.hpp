// Bit-for-bit comparisons of solver states for the tests that claim identical results
// (quiet skipping, temporal blocking): values, rows with their ghost nodes, the interface,
// the energy balance.
#pragma once

#include "solver/fe/nodal_field.hpp"
#include "solver/interface/interface_fields.hpp"

#include <cstring>
#include <vector>

namespace slipfront::bits {

inline bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

inline long differing(const std::vector<double>& a, const std::vector<double>& b) {
  long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    n += !same_bits(a[i], b[i]);
  return n;
}

inline long differing_nodes(const fe::VectorField& a, const fe::VectorField& b) {
  long n = 0;
  for (int j = 0; j < a.x.ny(); ++j)
    for (int i = -1; i <= a.x.nx(); ++i) // with the ghost nodes
      n += !same_bits(a.x.at(i, j), b.x.at(i, j)) + !same_bits(a.y.at(i, j), b.y.at(i, j));
  return n;
}

inline long differing_interface(const InterfaceFields& a, const InterfaceFields& b) {
  return differing(a.velocity, b.velocity) + differing(a.half_velocity, b.half_velocity) +
         differing(a.slip, b.slip) + differing(a.opening, b.opening) +
         differing(a.shear_traction, b.shear_traction) + differing(a.pressure, b.pressure) +
         differing(a.strength, b.strength) + long(a.state != b.state);
}

inline long differing_energy(const EnergyBalance& a, const EnergyBalance& b) {
  return !same_bits(a.kinetic, b.kinetic) + !same_bits(a.strain, b.strain) +
         !same_bits(a.external_work, b.external_work) + !same_bits(a.dissipated, b.dissipated);
}

} // namespace slipfront::bits
