// The reflection coefficient of a block's top (traction, dashpots or the perfectly matched
// layer) for a plane P or S wave packet at a given incidence angle and wavelength, measured
// on the discrete scheme (docs/verification.md "Perfectly matched layer"):
//   - the packet is a sum of exact plane waves of the discrete (Q4, lumped mass, leapfrog)
//     scheme, each with the polarisation and frequency of the eigenpair of the stencil's
//     symbol, with Gaussian weights: a Gaussian envelope in x2 (sigma two vertical
//     wavelengths), going up from inside the block;
//   - the block is a few periods of the wave along x1, tall enough that nothing reaches row 0
//     before the measurement;
//   - R = sqrt(E_back / E_in), E the energy in the rows below the top's first row, at the
//     start and once every reflected mode (P and S) has come back out of the layer: the
//     energy reflection coefficient of all modes together.
// Theory of the continuum layer (the round trip of the stretch, docs/physics.md):
//   R = exp(-2 cos(theta) (omega^2 / (omega^2 + alpha^2)) d0 H / (3 c)),
// an upper bound here: the dashpots at the layer's end take part of what reaches it.
#pragma once

#include "solver/fe/elastic_block.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace slipfront::fe::verification {

struct ReflectionCase {
  double angle_deg = 0;   // incidence from the normal of the top
  double wavelength = 20; // in elements
  bool p_wave = true;     // P (else S)
  TopBoundary top = TopBoundary::pml;
  int layer_rows = 20;
};

struct Reflection {
  double angle_deg = 0;    // the angle of the wave that fits the period
  double omega_dx = 0;     // omega dx / c_s
  double measured = 0;     // sqrt(E_back / E_in)
  double theory = 0;       // the continuum layer's round trip (0 without a layer)
  double energy_error = 0; // |E - E(0) + D| / E(0) over the run, the whole block
};

inline Reflection measure_reflection(const ReflectionCase& c) {
  Material material; // the paper's: c_s = 1 m/s, c_p = sqrt(3) m/s
  const double dx = 0.05, pi = std::acos(-1.0);
  const double k = 2 * pi / (c.wavelength * dx);
  const double theta = c.angle_deg * pi / 180;
  // The period along x1 holds `periods` wavelengths of k1 and at least 40 elements, so that
  // the angle that fits it is within a degree or so of the one asked for.
  int nx = 4;
  double k1 = 0;
  if (std::sin(theta) > 1e-12) {
    const double along = 2 * pi / (k * std::sin(theta)) / dx; // k1's wavelength in elements
    const int periods = int(std::ceil(40.0 / along));
    nx = std::max(3, int(std::lround(periods * along)));
    k1 = 2 * pi * periods / (nx * dx);
  }
  const double k2 = std::sqrt(std::max(k * k - k1 * k1, 0.0));

  // A plane wave of the discrete scheme at (k1, kv): the eigenpair of the stencil's symbol
  // (omega^2 m and the polarisation) and the leapfrog's frequency.
  const MeshStencils stencils = build_stencils(q4_plane_strain_stiffness(material));
  const double m = material.density * dx * dx;
  ElasticBlock probe(material, nx, 3, dx, TopBoundary::traction, 0.0);
  const double dt = 0.5 * probe.stable_dt();
  struct Mode {
    double omega, px, py;
  };
  auto mode = [&](double kv) {
    std::complex<double> sxx = 0, sxy = 0, syy = 0;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        const Block2& b = stencils.interior.b[dj + 1][di + 1];
        const std::complex<double> e = std::polar(1.0, (k1 * di + kv * dj) * dx);
        sxx += b.xx * e;
        sxy += b.xy * e;
        syy += b.yy * e;
      }
    const double a = sxx.real(), bxy = sxy.real(), d = syy.real();
    const double mean = 0.5 * (a + d), half = std::sqrt(0.25 * (a - d) * (a - d) + bxy * bxy);
    const double lambda = c.p_wave ? mean + half : mean - half;
    double px = bxy, py = lambda - a; // eigenvector of [[a, b], [b, d]]
    if (std::hypot(px, py) < 1e-14 * (std::abs(a) + std::abs(d))) {
      px = lambda - d;
      py = bxy;
    }
    if (std::hypot(px, py) < 1e-300) { // diagonal symbol: the axis of the eigenvalue
      const bool x_axis = std::abs(lambda - a) < std::abs(lambda - d);
      px = x_axis ? 1 : 0;
      py = x_axis ? 0 : 1;
    }
    const double norm = std::hypot(px, py);
    const double omega_semi = std::sqrt(lambda / m);
    return Mode{2.0 / dt * std::asin(0.5 * dt * omega_semi), px / norm, py / norm};
  };
  const Mode centre = mode(k2);
  const double omega = centre.omega;

  // Vertical group speeds of the modes that fit k1 at omega (continuum), for the timing.
  auto vertical_speed = [&](double speed) {
    const double kk = omega / speed;
    return kk > k1 ? speed * std::sqrt(1 - (k1 / kk) * (k1 / kk)) : 0.0;
  };
  const double v_in = vertical_speed(c.p_wave ? material.p_wave_speed() : material.s_wave_speed());
  double v_slow = v_in, v_fast = v_in;
  for (double s : {material.p_wave_speed(), material.s_wave_speed()})
    if (const double v = vertical_speed(s); v > 0) {
      v_slow = std::min(v_slow, v);
      v_fast = std::max(v_fast, v);
    }
  const double sigma = 2.0 * 2 * pi / k2; // the envelope: two vertical wavelengths
  const double tau = sigma / v_in;        // its duration
  const int layer = c.top == TopBoundary::pml ? c.layer_rows : 0;
  const double t_layer = 2 * (layer + 2) * dx / v_slow;
  const double D = 5 * sigma; // the packet's centre below the top's first row
  const double t_end = D / v_in + 5 * tau + t_layer + 5 * sigma / v_slow;
  const double reach = (t_end - D / v_in + 5 * tau) * v_fast; // the fastest mode back down
  const int interior = int(std::ceil(std::max(D + 5 * sigma, reach) / dx)) + 10;
  const int entrance = interior; // the row where the top (or its layer) begins
  const int ny = entrance + layer + 1;

  ElasticBlock block(material, nx, ny, dx, c.top, 0.0, layer);
  block.set_time_step(dt);
  block.set_skip_quiet(false);
  VectorField& u = block.displacement();
  VectorField& v = block.velocity();
  // The packet as a sum of plane waves of the scheme, each with its own frequency and
  // polarisation (vertical wavenumbers k2 + q dk, Gaussian weights: the envelope
  // exp(-(y - y0)^2 / (2 sigma^2)) at t = 0); one frequency for all would start a downgoing
  // wave of order 1 / (k2 sigma)^2 at oblique incidence, where omega is not linear in k2.
  // The sum is periodic in y over 2 pi / dk = twice the block's height: no copy is inside.
  const double y0 = (entrance - D / dx) * dx;
  const double dk = pi / (ny * dx);
  const int modes = int(std::ceil(5.0 / (sigma * dk)));
  std::vector<double> cx(ny, 0.0), sx(ny, 0.0), cy(ny, 0.0), sy(ny, 0.0);     // u at t = 0
  std::vector<double> cxp(ny, 0.0), sxp(ny, 0.0), cyp(ny, 0.0), syp(ny, 0.0); // u at t = -dt
  for (int q = -modes; q <= modes; ++q) {
    const double kv = k2 + q * dk;
    Mode w = mode(kv);
    if (w.px * centre.px + w.py * centre.py < 0) { // one sign along the branch
      w.px = -w.px;
      w.py = -w.py;
    }
    const double weight = std::exp(-0.5 * (q * dk * sigma) * (q * dk * sigma));
    for (int j = 0; j < ny; ++j) {
      const double phase = kv * (j * dx - y0), back = phase + w.omega * dt;
      cx[j] += weight * w.px * std::cos(phase);
      sx[j] += weight * w.px * std::sin(phase);
      cy[j] += weight * w.py * std::cos(phase);
      sy[j] += weight * w.py * std::sin(phase);
      cxp[j] += weight * w.px * std::cos(back);
      sxp[j] += weight * w.px * std::sin(back);
      cyp[j] += weight * w.py * std::cos(back);
      syp[j] += weight * w.py * std::sin(back);
    }
  }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      // cos(k1 x + phase) = cos(k1 x) cos(phase) - sin(k1 x) sin(phase)
      const double ck = std::cos(k1 * i * dx), sk = std::sin(k1 * i * dx);
      u.x.at(i, j) = ck * cx[j] - sk * sx[j];
      u.y.at(i, j) = ck * cy[j] - sk * sy[j];
      // v^{-1/2} = (u^0 - u^{-1}) / dt with u^{-1} the packet at t = -dt.
      v.x.at(i, j) = (u.x.at(i, j) - (ck * cxp[j] - sk * sxp[j])) / dt;
      v.y.at(i, j) = (u.y.at(i, j) - (ck * cyp[j] - sk * syp[j])) / dt;
    }
  u.x.refresh_all_ghosts();
  u.y.refresh_all_ghosts();
  v.x.refresh_all_ghosts();
  v.y.refresh_all_ghosts();
  block.activate_all_rows();

  BlockStepRecord record;
  std::vector<double> scratch(3 * std::size_t(nx));
  const double m0 = block.node_mass(0);
  const long steps = long(std::ceil(t_end / dt));
  double e_first = 0, e_last = 0, dissipated = 0, total_first = 0, worst = 0;
  for (long n = 0; n <= steps; ++n) {
    record.reset(ny, true);
    block.begin_interface_row(record);
    // Row 0 is a free surface here (nothing reaches it): v -= dt/m K u.
    double* v0x = v.x.row(0);
    double* v0y = v.y.row(0);
    double row0 = 0; // its energy terms, as the block's rows have theirs
    for (int i = 0; i < nx; ++i) {
      const double kx = block.interface_stiffness_x()[i], ky = block.interface_stiffness_y()[i];
      v0x[i] -= dt / m0 * kx;
      v0y[i] -= dt / m0 * ky;
      row0 += 0.5 * m0 * (v0x[i] * v0x[i] + v0y[i] * v0y[i]) +
              0.5 * (kx * (u.x.row(0)[i] + dt * v0x[i]) + ky * (u.y.row(0)[i] + dt * v0y[i]));
    }
    for (int r = 1; r <= ny; ++r)
      block.row_step(record, r, scratch);
    block.finish_trip();
    double below = row0, total = row0;
    for (int j = 1; j < ny; ++j) {
      const double e = record.row_kinetic[j] + record.row_strain[j];
      total += e;
      if (j < entrance) below += e;
      dissipated += record.row_dissipated[j];
    }
    if (n == 0) {
      e_first = below;
      total_first = total;
      dissipated = 0; // the balance counts from the first energy on
    }
    e_last = below;
    worst = std::max(worst, std::abs(total - total_first + dissipated) / total_first);
  }
  Reflection out;
  out.angle_deg = std::atan2(k1, k2) * 180 / pi;
  out.omega_dx = omega * dx / material.s_wave_speed();
  out.measured = std::sqrt(std::max(e_last, 0.0) / e_first);
  if (layer > 0) {
    const AbsorbingLayer& l = block.layer();
    const double speed = c.p_wave ? material.p_wave_speed() : material.s_wave_speed();
    const double shift =
        omega * omega / (omega * omega + l.frequency_shift() * l.frequency_shift());
    out.theory = std::exp(-2 * std::cos(std::atan2(k1, k2)) * shift * l.max_damping() *
                          (layer * dx) / (3 * speed));
  }
  out.energy_error = worst;
  return out;
}

} // namespace slipfront::fe::verification
