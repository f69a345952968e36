#include "solver/fe/absorbing_layer.hpp"

#include "solver/fe/element_stiffness.hpp"

#include <cmath>
#include <stdexcept>

namespace slipfront::fe {

AbsorbingLayer::AbsorbingLayer(const Material& material, int nx, int ny, int rows, double dx)
    : nx_(nx), ny_(ny), rows_(rows), first_(ny - 1 - rows) {
  const double thickness = rows * dx;
  d0_ = 3.0 * material.p_wave_speed() * std::log(1.0 / kLayerDesignReflection) / (2.0 * thickness);
  alpha_ = kLayerFrequencyShift * d0_;
  k11_ = build_stencils(q4_plane_strain_stiffness_part(material, StrainPart::along_x1));
  k22_ = build_stencils(q4_plane_strain_stiffness_part(material, StrainPart::along_x2));
  for (int l = 0; l <= rows; ++l) { // d_above K_11^above + d_below K_11^below of each row
    const int j = first_ + l;
    const double a = element_damping(j), b = element_damping(j - 1);
    NodeStencil row;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const Block2 &up = k11_.bottom.b[r][c], &down = k11_.top.b[r][c];
        row.b[r][c] = {a * up.xx + b * down.xx, a * up.xy + b * down.xy, a * up.yx + b * down.yx,
                       a * up.yy + b * down.yy};
      }
    k11_rows_.push_back(row);
  }
  // K_11 and K_22 of an isotropic element couple no components (the rows take half the work).
  for (const NodeStencil* part : {&k11_.bottom, &k11_.top, &k22_.bottom, &k22_.top})
    if (!has_no_cross_terms(*part))
      throw std::logic_error("the directional stiffness of the layer couples x1 and x2");
  zeta_ = VectorField(nx, rows + 1);
  phi_above_ = VectorField(nx, rows + 1);
  phi_below_ = VectorField(nx, rows + 1);
  zero_row_.assign(nx + 2, 0.0);
}

double AbsorbingLayer::damping(int j) const {
  if (!damps_row(j)) return 0.0;
  const double depth = double(j - first_) / rows_; // x / H
  return d0_ * depth * depth;
}

namespace {

// phi' = d f - (alpha + d) phi over half a step with f held:
//   phi <- phi e^{-(alpha+d) dt/2} + d f (1 - e^{-(alpha+d) dt/2}) / (alpha + d).
struct HalfStep {
  double decay = 1, gain = 0;
  HalfStep(double d, double alpha, double dt) {
    if (d > 0) {
      decay = std::exp(-(alpha + d) * 0.5 * dt);
      gain = -std::expm1(-(alpha + d) * 0.5 * dt) * d / (alpha + d);
    }
  }
};

} // namespace

double AbsorbingLayer::element_damping(int e) const {
  if (rows_ == 0 || e < first_ || e >= ny_ - 1) return 0.0;
  const double depth = (e + 0.5 - first_) / rows_; // of the element's centre, x / H
  return d0_ * depth * depth;
}

AbsorbingLayer::RowEnergy AbsorbingLayer::velocity_row(int j, const NodeStencil& stiffness,
                                                       const SymmetricStencil* symmetric,
                                                       const VectorField& u, VectorField& v,
                                                       const double* extra_x, const double* extra_y,
                                                       double mass, double dashpot_x,
                                                       double dashpot_y, bool energy) {
  const bool top = j == ny_ - 1;
  const double* z = zero_row_.data() + 1;
  const int l = j - first_; // the row in zeta and phi
  const double *uxm = u.x.row(j - 1), *uym = u.y.row(j - 1), *ux0 = u.x.row(j), *uy0 = u.y.row(j),
               *uxp = top ? z : u.x.row(j + 1), *uyp = top ? z : u.y.row(j + 1);
  const double *zxm = l > 0 ? zeta_.x.row(l - 1) : z, *zym = l > 0 ? zeta_.y.row(l - 1) : z,
               *zx0 = zeta_.x.row(l), *zy0 = zeta_.y.row(l), *zxp = top ? z : zeta_.x.row(l + 1),
               *zyp = top ? z : zeta_.y.row(l + 1);
  double* vx = v.x.row(j);
  double* vy = v.y.row(j);
  double *pax = phi_above_.x.row(l), *pay = phi_above_.y.row(l);
  double *pbx = phi_below_.x.row(l), *pby = phi_below_.y.row(l);

  // d of the node (its mass) and of the elements above and below it (their stiffness).
  const double d = damping(j), d_above = element_damping(j), d_below = element_damping(j - 1);
  const double alpha = alpha_, m = mass;
  const double c_x = dashpot_x + m * d, c_y = dashpot_y + m * d; // velocity-proportional forces
  const double b_x = c_x * dt_ / (2 * m), b_y = c_y * dt_ / (2 * m);
  const HalfStep above(d_above, alpha, dt_), below(d_below, alpha, dt_);

  // The directional stiffness of the elements above the node (the "bottom" stencil of a
  // node with elements above it only) and below it, each with its own d: s and 1/s are
  // constant in an element, so that the layer is the Galerkin form of the stretched equations.
  // d_above K_11^above + d_below K_11^below is one stencil per row (k11_rows_).
  thread_local std::vector<double> scratch; // this thread's (several may step rows at once)
  scratch.resize(11 * std::size_t(nx_));
  double* __restrict kux = scratch.data(); // K u
  double* __restrict kuy = kux + nx_;
  double* __restrict f11x = kuy + nx_; // sum_e d_e K_11^e zeta
  double* __restrict f11y = f11x + nx_;
  double* __restrict f22ax = f11y + nx_; // K_22^above u
  double* __restrict f22ay = f22ax + nx_;
  double* __restrict f22bx = f22ay + nx_; // K_22^below u
  double* __restrict f22by = f22bx + nx_;
  double* __restrict dis = f22by + nx_; // each node's energy terms
  double* __restrict kin = dis + nx_;
  double* __restrict str = kin + nx_;
  if (symmetric != nullptr)
    symmetric_force_row(*symmetric, uxm, uym, ux0, uy0, uxp, uyp, kux, kuy, nx_);
  else
    stencil_force_row(stiffness, uxm, uym, ux0, uy0, uxp, uyp, kux, kuy, nx_);
  uncoupled_force_row(k11_rows_[l], zxm, zym, zx0, zy0, zxp, zyp, f11x, f11y, nx_);
  uncoupled_force_row(k22_.bottom, z, z, ux0, uy0, uxp, uyp, f22ax, f22ay, nx_);
  uncoupled_force_row(k22_.top, uxm, uym, ux0, uy0, z, z, f22bx, f22by, nx_);
  const double* __restrict ex = extra_x ? extra_x : z;
  const double* __restrict ey = extra_y ? extra_y : z;
  const double da = above.decay, ga = above.gain, db = below.decay, gb = below.gain;
  const double mda = m * d * alpha, mdaa = m * d * alpha * alpha;
  for (int i = 0; i < nx_; ++i) {
    // phi of each side at t_n (kept at the half steps, advanced with K_22 u^n held).
    const double pax_n = pax[i] * da + ga * f22ax[i], pay_n = pay[i] * da + ga * f22ay[i];
    const double pbx_n = pbx[i] * db + gb * f22bx[i], pby_n = pby[i] * db + gb * f22by[i];
    // The forces beyond K u: the other force, the layer's stiffness and memory terms (the
    // velocity-proportional ones are in c_x, c_y).
    const double gx = ex[i] + f11x[i] - pax_n - pbx_n + mdaa * zx0[i] - mda * ux0[i];
    const double gy = ey[i] + f11y[i] - pay_n - pby_n + mdaa * zy0[i] - mda * uy0[i];
    const double vx_new = (vx[i] * (1 - b_x) - dt_ / m * (kux[i] + gx)) / (1 + b_x);
    const double vy_new = (vy[i] * (1 - b_y) - dt_ / m * (kuy[i] + gy)) / (1 + b_y);
    const double vx_mid = 0.5 * (vx[i] + vx_new), vy_mid = 0.5 * (vy[i] + vy_new);
    dis[i] = dt_ * (c_x * vx_mid * vx_mid + c_y * vy_mid * vy_mid + gx * vx_mid + gy * vy_mid);
    kin[i] = vx_new * vx_new + vy_new * vy_new;
    str[i] = kux[i] * (ux0[i] + dt_ * vx_new) + kuy[i] * (uy0[i] + dt_ * vy_new);
    vx[i] = vx_new;
    vy[i] = vy_new;
    pax[i] = pax_n * da + ga * f22ax[i]; // at t_{n+1/2}
    pay[i] = pay_n * da + ga * f22ay[i];
    pbx[i] = pbx_n * db + gb * f22bx[i];
    pby[i] = pby_n * db + gb * f22by[i];
  }
  RowEnergy out;
  for (int i = 0; i < nx_; ++i)
    out.dissipated += dis[i];
  if (energy) {
    for (int i = 0; i < nx_; ++i) {
      out.kinetic += kin[i];
      out.strain += str[i];
    }
    out.kinetic *= 0.5 * m;
    out.strain *= 0.5;
  }
  return out;
}

void AbsorbingLayer::advance_memory_row(int j, const VectorField& u, const VectorField& v) {
  if (rows_ == 0 || j < first_) return;
  // zeta' = u - alpha zeta with u held at its midpoint value u^{n+1/2} = u^{n+1} - dt/2 v^{n+1/2}
  // (alpha = 0: zeta += dt u^{n+1/2}, the trapezoidal rule).
  const int l = j - first_;
  const double decay = std::exp(-alpha_ * dt_);
  const double gain = alpha_ > 0 ? -std::expm1(-alpha_ * dt_) / alpha_ : dt_;
  double* zx = zeta_.x.row(l);
  double* zy = zeta_.y.row(l);
  const double* ux = u.x.row(j);
  const double* uy = u.y.row(j);
  const double* vx = v.x.row(j);
  const double* vy = v.y.row(j);
  for (int i = 0; i < nx_; ++i) {
    zx[i] = zx[i] * decay + gain * (ux[i] - 0.5 * dt_ * vx[i]);
    zy[i] = zy[i] * decay + gain * (uy[i] - 0.5 * dt_ * vy[i]);
  }
  zeta_.x.refresh_ghosts(l);
  zeta_.y.refresh_ghosts(l);
}

} // namespace slipfront::fe
