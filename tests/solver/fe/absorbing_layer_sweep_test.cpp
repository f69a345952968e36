// The perfectly matched layer's reflection coefficient against the incidence angle (0-80 deg;
// 0-60 deg at 40 elements, whose grazing packets take minutes) and the wavelength (10, 20, 40
// elements), P and S, beside the dashpots' at 20 elements
// (docs/verification.md
// "Perfectly matched layer"; bench/layer_reflection.py runs it and draws the figure). Every
// case also checks the bound of the continuum layer and the energy balance.
#include "layer_reflection.hpp"
#include "verification_support.hpp"

#include <gtest/gtest.h>

namespace slipfront::fe {
namespace {

using slipfront::verification::measure;
using verification::measure_reflection;
using verification::Reflection;
using verification::ReflectionCase;

TEST(AbsorbingLayerSweep, ReflectionAgainstAngleAndWavelength) {
  for (const TopBoundary top : {TopBoundary::pml, TopBoundary::absorbing})
    for (const bool p_wave : {true, false})
      for (const double wavelength : {10.0, 20.0, 40.0}) {
        if (top == TopBoundary::absorbing && wavelength != 20.0) continue; // the comparison
        for (int angle = 0; angle <= (wavelength > 20 ? 60 : 80); angle += 10) {
          ReflectionCase c;
          c.angle_deg = angle;
          c.wavelength = wavelength;
          c.p_wave = p_wave;
          c.top = top;
          const Reflection r = measure_reflection(c);
          measure("sweep top=%s wave=%s angle=%.2f wavelength=%g omega_dx=%.4f R=%.4e "
                  "theory=%.4e energy=%.1e",
                  top == TopBoundary::pml ? "pml" : "dashpots", p_wave ? "P" : "S", r.angle_deg,
                  wavelength, r.omega_dx, r.measured, r.theory, r.energy_error);
          EXPECT_LT(r.energy_error, 1e-10);
        }
      }
}

} // namespace
} // namespace slipfront::fe
