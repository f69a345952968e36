#include "solver/fe/elastic_block.hpp"

#include "solver/fe/element_stiffness.hpp"
#include "solver/fe/lumped_mass.hpp"
#include "solver/fe/stable_time_step.hpp"

#include <algorithm>
#include <array>

namespace slipfront::fe {

namespace {

// Rows j-1, j and j+1 of a field (x below, y below, x, y, x above, y above); a missing row
// (below the interface, beyond the far boundary) is the zero row.
std::array<const double*, 6> neighbour_rows(const VectorField& f, int j, int ny, const double* z) {
  return {j > 0 ? f.x.row(j - 1) : z,      j > 0 ? f.y.row(j - 1) : z,     f.x.row(j), f.y.row(j),
          j < ny - 1 ? f.x.row(j + 1) : z, j < ny - 1 ? f.y.row(j + 1) : z};
}

} // namespace

void BlockStepRecord::reset(int rows, bool energy) {
  compute_energy = energy;
  row_kinetic.assign(rows, 0.0);
  row_strain.assign(rows, 0.0);
  row_dissipated.assign(rows, 0.0);
  swept = 0;
}

ElasticBlock::ElasticBlock(const Material& material, int nx, int ny, double dx, TopBoundary far,
                           double mesh_damping, int layer_rows)
    : material_(material), nx_(nx), ny_(ny), dx_(dx), far_(far) {
  if (far == TopBoundary::pml) layer_ = AbsorbingLayer(material, nx, ny, layer_rows, dx);
  stencils_ = build_stencils(q4_plane_strain_stiffness(material));
  interior_symmetric_ = symmetric_form(stencils_.interior, interior_form_);
  damping_a_ = mesh_damping * dx_ / material.s_wave_speed();
  stable_dt_ = damped_stable_time_step(stable_time_step(stencils_, nx_, ny_, dx_, material.density),
                                       damping_a_);
  u_ = VectorField(nx_, ny_);
  v_ = VectorField(nx_, ny_);
  if (damping_a_ > 0) {
    w_ = VectorField(nx_, ny_);
    kdx_.assign(nx_, 0.0);
    kdy_.assign(nx_, 0.0);
    kdx_far_.assign(nx_, 0.0);
    kdy_far_.assign(nx_, 0.0);
  }
  zero_row_.assign(nx_ + 2, 0.0);
  kx0_.assign(nx_, 0.0);
  ky0_.assign(nx_, 0.0);
  columns_.assign(ny_, ColumnRange{});
  next_columns_.assign(ny_, ColumnRange{});
}

double ElasticBlock::node_mass(int j) const {
  return lumped_node_mass(j, ny_, dx_, material_.density);
}

void ElasticBlock::activate_all_rows() {
  active_rows_ = ny_;
  columns_.assign(ny_, ColumnRange{0, nx_});
  if (damping_a_ > 0)
    for (int j = 0; j < ny_; ++j)
      update_damping_row(j);
}

void ElasticBlock::update_damping_row(int j) {
  double* __restrict wx = w_.x.row(j);
  double* __restrict wy = w_.y.row(j);
  const double* __restrict ux = u_.x.row(j);
  const double* __restrict uy = u_.y.row(j);
  const double* __restrict vx = v_.x.row(j);
  const double* __restrict vy = v_.y.row(j);
  for (int i = 0; i < nx_; ++i) {
    wx[i] = ux[i] + damping_a_ * vx[i];
    wy[i] = uy[i] + damping_a_ * vy[i];
  }
  w_.x.refresh_ghosts(j);
  w_.y.refresh_ghosts(j);
}

void ElasticBlock::damping_force_row(const NodeStencil& s, int j, double* dx, double* dy) const {
  const double* z = zero_row_.data() + 1;
  const auto w = neighbour_rows(w_, j, ny_, z);
  const auto u = neighbour_rows(u_, j, ny_, z);
  for_each_node_force(s, w[0], w[1], w[2], w[3], w[4], w[5], nx_, [&](int i, double kx, double ky) {
    dx[i] = kx;
    dy[i] = ky;
  });
  for_each_node_force(s, u[0], u[1], u[2], u[3], u[4], u[5], nx_, [&](int i, double kx, double ky) {
    dx[i] -= kx;
    dy[i] -= ky;
  });
}

void ElasticBlock::damped_interior_row(BlockStepRecord& record, int j, const NodeStencil& s,
                                       ColumnRange cols, std::vector<double>& scratch) {
  const bool compute_energy = record.compute_energy;
  const double* z = zero_row_.data() + 1;
  auto u = neighbour_rows(u_, j, ny_, z);
  auto w = neighbour_rows(w_, j, ny_, z);
  for (int k = 0; k < 6; ++k) { // from the first column swept on
    u[k] += cols.begin;
    w[k] += cols.begin;
  }
  const int n = cols.size();
  double* kin = compute_energy ? scratch.data() : nullptr;
  double* str = compute_energy ? scratch.data() + nx_ : nullptr;
  double* dis = scratch.data() + 2 * nx_;
  stencil_damped_velocity_update(s, u[0], u[1], u[2], u[3], u[4], u[5], w[0], w[1], w[2], w[3],
                                 w[4], w[5], v_.x.row(j) + cols.begin, v_.y.row(j) + cols.begin, n,
                                 dt_, node_mass(j), dis, kin, str);
  double dis_sum = 0;
  for (int i = 0; i < n; ++i)
    dis_sum += dis[i];
  record.row_dissipated[j] = dis_sum;
  if (compute_energy) store_row_energy(record, j, kin, str, n);
}

// The nodes left out of a sum hold exact zeros, whose terms are +0: leaving them out of
// the sum in node order changes no bit of it.
void ElasticBlock::store_row_energy(BlockStepRecord& record, int j, const double* kin,
                                    const double* str, int count) const {
  double kin_sum = 0, str_sum = 0;
  for (int i = 0; i < count; ++i) {
    kin_sum += kin[i];
    str_sum += str[i];
  }
  record.row_kinetic[j] = 0.5 * node_mass(j) * kin_sum;
  record.row_strain[j] = 0.5 * str_sum;
}

void ElasticBlock::finish_trip() {
  for (int j = ny_ - 1; j >= active_rows_; --j) // the highest row that may be non-zero
    if (!columns_[j].empty()) {
      active_rows_ = j + 1;
      break;
    }
}

ColumnRange ElasticBlock::sweep_columns(int j) const {
  // The interface row is always swept whole (its loads change everywhere), and so is the
  // absorbing far row once anything may reach it.
  // The rows of the perfectly matched layer are swept whole once reached: their memory
  // fields may hold values where u and v are zero.
  if (!skip_quiet_ || j == 0) return ColumnRange{0, nx_};
  const ColumnRange grown = grown_column_range(columns_, j, nx_);
  if (j == ny_ - 1 && absorbing_far() && !grown.empty()) return ColumnRange{0, nx_};
  if (layer_.damps_row(j) && (!grown.empty() || j < active_rows_)) return ColumnRange{0, nx_};
  return grown;
}

void ElasticBlock::begin_interface_row(BlockStepRecord& record) {
  const ColumnRange cols = sweep_columns(0);
  next_columns_[0] = cols;
  record.swept += cols.size();
  const double* z = zero_row_.data() + 1;
  const double* uxp = ny_ > 1 ? u_.x.row(1) : z;
  const double* uyp = ny_ > 1 ? u_.y.row(1) : z;
  for_each_node_force(stencils_.bottom, z, z, u_.x.row(0), u_.y.row(0), uxp, uyp, nx_,
                      [&](int i, double kx, double ky) {
                        kx0_[i] = kx;
                        ky0_[i] = ky;
                      });
  if (damping_a_ > 0) damping_force_row(stencils_.bottom, 0, kdx_.data(), kdy_.data());
}

void ElasticBlock::row_step(BlockStepRecord& record, int r, std::vector<double>& scratch) {
  if (r > ny_) return; // beyond this block: nothing
  if (r == ny_) {      // past the far row: only its displacement is left
    update_displacement_row(r - 1);
    return;
  }
  const ColumnRange cols = sweep_columns(r);
  next_columns_[r] = cols;
  record.swept += cols.size();
  const bool bulk = damping_a_ == 0 && !(r == ny_ - 1 && absorbing_far()) && !layer_.damps_row(r);
  if (bulk) {
    bulk_row_step(record, r, cols, scratch);
    return;
  }
  // Nothing moves in a quiet row (its energy terms stay 0).
  if (!cols.empty()) velocity_row(record, r, cols, scratch);
  update_displacement_row(r - 1);
}

void ElasticBlock::velocity_row(BlockStepRecord& record, int j, ColumnRange cols,
                                std::vector<double>& scratch) {
  if (layer_.damps_row(j)) {
    layer_row(record, j, scratch);
  } else if (j == ny_ - 1 && absorbing_far()) {
    if (damping_a_ > 0) damping_force_row(stencils_.top, j, kdx_far_.data(), kdy_far_.data());
    absorbing_far_row(record);
  } else { // a damped bulk row
    damped_interior_row(record, j, (j == ny_ - 1) ? stencils_.top : stencils_.interior, cols,
                        scratch);
  }
}

// The columns are taken in blocks of kColumnBlock: the velocity of the block in row r, then
// the displacement of row r-1 as far as it is no longer read (u of row r-1 at column i is
// read by the nodes i-1, i, i+1 of row r), so that u and v of row r-1 are advanced while
// they are in the L1 cache. Each node's arithmetic is that of whole-row sweeps.
void ElasticBlock::bulk_row_step(BlockStepRecord& record, int r, ColumnRange vel,
                                 std::vector<double>& scratch) {
  constexpr int kColumnBlock = 256;
  const ColumnRange dis = next_columns_[r - 1];
  double* kin = record.compute_energy ? scratch.data() : nullptr;
  double* str = record.compute_energy ? scratch.data() + nx_ : nullptr;
  const int lo = std::min(vel.empty() ? nx_ : vel.begin, dis.empty() ? nx_ : dis.begin);
  const int hi = std::max(vel.empty() ? 0 : vel.end, dis.empty() ? 0 : dis.end);
  int next = dis.begin; // the first column of row r-1 not yet advanced
  for (int c = lo; c < hi; c += kColumnBlock) {
    const int e = std::min(c + kColumnBlock, hi);
    const int a = std::max(c, vel.begin), b = std::min(e, vel.end);
    if (a < b)
      bulk_velocity(r, a, b - a, kin ? kin + (a - vel.begin) : nullptr,
                    str ? str + (a - vel.begin) : nullptr);
    const int stop = std::min(e - 1, dis.end);
    if (!dis.empty() && stop > next) {
      advance_displacement(r - 1, next, stop);
      next = stop;
    }
  }
  if (!dis.empty() && dis.end > next) advance_displacement(r - 1, next, dis.end);
  finish_displacement_row(r - 1);
  if (record.compute_energy && !vel.empty()) store_row_energy(record, r, kin, str, vel.size());
}

void ElasticBlock::bulk_velocity(int r, int begin, int n, double* kin, double* str) {
  const double* z = zero_row_.data() + 1;
  const double* uxm = u_.x.row(r - 1) + begin;
  const double* uym = u_.y.row(r - 1) + begin;
  const double* uxp = (r < ny_ - 1 ? u_.x.row(r + 1) : z) + begin;
  const double* uyp = (r < ny_ - 1 ? u_.y.row(r + 1) : z) + begin;
  const double* ux0 = u_.x.row(r) + begin;
  const double* uy0 = u_.y.row(r) + begin;
  double* vx = v_.x.row(r) + begin;
  double* vy = v_.y.row(r) + begin;
  if (r < ny_ - 1 && interior_symmetric_)
    symmetric_velocity_update(interior_form_, uxm, uym, ux0, uy0, uxp, uyp, vx, vy, n, dt_,
                              node_mass(r), kin, str);
  else
    stencil_velocity_update(r < ny_ - 1 ? stencils_.interior : stencils_.top, uxm, uym, ux0, uy0,
                            uxp, uyp, vx, vy, n, dt_, node_mass(r), kin, str);
}

void ElasticBlock::finish_displacement_row(int j) {
  u_.x.refresh_ghosts(j);
  u_.y.refresh_ghosts(j);
  if (damping_a_ > 0) {
    w_.x.refresh_ghosts(j);
    w_.y.refresh_ghosts(j);
  }
  // Without skipping the ranges are not read: do not scan the row for its zeros.
  columns_[j] = skip_quiet_ ? trim_column_range(u_, v_, j, next_columns_[j]) : ColumnRange{0, nx_};
  layer_.advance_memory_row(j, u_, v_);
}

void ElasticBlock::layer_row(BlockStepRecord& record, int j, std::vector<double>& scratch) {
  const bool far = j == ny_ - 1;
  const NodeStencil& stiffness = far ? stencils_.top : stencils_.interior;
  double* extra_x = nullptr;
  double* extra_y = nullptr;
  if (damping_a_ > 0) { // the mesh damping's force a K v^{n-1/2} of the row
    extra_x = scratch.data();
    extra_y = scratch.data() + nx_;
    damping_force_row(stiffness, j, extra_x, extra_y);
  }
  const double rho = material_.density;
  const double dashpot_x = far ? rho * material_.s_wave_speed() * dx_ : 0.0;
  const double dashpot_y = far ? rho * material_.p_wave_speed() * dx_ : 0.0;
  const AbsorbingLayer::RowEnergy e = layer_.velocity_row(
      j, stiffness, !far && interior_symmetric_ ? &interior_form_ : nullptr, u_, v_, extra_x,
      extra_y, node_mass(j), dashpot_x, dashpot_y, record.compute_energy);
  record.row_dissipated[j] = e.dissipated;
  if (record.compute_energy) {
    record.row_kinetic[j] = e.kinetic;
    record.row_strain[j] = e.strain;
  }
}

void ElasticBlock::update_displacement_row(int j) {
  // Outside the columns swept this step v is zero and u stays as it is.
  advance_displacement(j, next_columns_[j].begin, next_columns_[j].end);
  finish_displacement_row(j);
}

void ElasticBlock::advance_displacement(int j, int begin, int end) {
  const int n = end - begin;
  double* __restrict ux = u_.x.row(j) + begin;
  double* __restrict uy = u_.y.row(j) + begin;
  const double* __restrict vx = v_.x.row(j) + begin;
  const double* __restrict vy = v_.y.row(j) + begin;
  if (damping_a_ > 0) { // u and w = u + a v in one pass
    double* __restrict wx = w_.x.row(j) + begin;
    double* __restrict wy = w_.y.row(j) + begin;
    const double a = damping_a_;
    for (int i = 0; i < n; ++i) {
      ux[i] += dt_ * vx[i];
      uy[i] += dt_ * vy[i];
      wx[i] = ux[i] + a * vx[i];
      wy[i] = uy[i] + a * vy[i];
    }
  } else {
    for (int i = 0; i < n; ++i) {
      ux[i] += dt_ * vx[i];
      uy[i] += dt_ * vy[i];
    }
  }
}

void ElasticBlock::absorbing_far_row(BlockStepRecord& record) {
  const bool compute_energy = record.compute_energy;
  // Lysmer-Kuhlemeyer dashpots on the far nodes: force -c v with c = rho c_s dx (tangential)
  // and rho c_p dx (normal). Taken at the step's mid velocity (v^{n+1/2} + v^{n-1/2})/2,
  // which is implicit in v^{n+1/2} but diagonal:
  //   v^{n+1/2} (1 + a) = v^{n-1/2} (1 - a) - dt/m (K u)^n,  a = c dt / (2 m).
  const int j = ny_ - 1;
  const double m = node_mass(j);
  const double rho = material_.density;
  const double c_x = rho * material_.s_wave_speed() * dx_;
  const double c_y = rho * material_.p_wave_speed() * dx_;
  const double a_x = c_x * dt_ / (2 * m), a_y = c_y * dt_ / (2 * m);
  double* vx = v_.x.row(j);
  double* vy = v_.y.row(j);
  const double* uxm = u_.x.row(j - 1);
  const double* uym = u_.y.row(j - 1);
  const double* ux0 = u_.x.row(j);
  const double* uy0 = u_.y.row(j);
  const double* z = zero_row_.data() + 1;
  const bool damped = damping_a_ > 0; // then kdx_far_, kdy_far_ hold the row's damping force
  double dissipated = 0, kinetic = 0, strain = 0;
  for_each_node_force(
      stencils_.top, uxm, uym, ux0, uy0, z, z, nx_, [&](int i, double kx, double ky) {
        const double fx = damped ? kx + kdx_far_[i] : kx, fy = damped ? ky + kdy_far_[i] : ky;
        const double vx_new = (vx[i] * (1 - a_x) - dt_ / m * fx) / (1 + a_x);
        const double vy_new = (vy[i] * (1 - a_y) - dt_ / m * fy) / (1 + a_y);
        const double vx_mid = 0.5 * (vx[i] + vx_new), vy_mid = 0.5 * (vy[i] + vy_new);
        dissipated += dt_ * (c_x * vx_mid * vx_mid + c_y * vy_mid * vy_mid);
        if (damped) dissipated += dt_ * (kdx_far_[i] * vx_mid + kdy_far_[i] * vy_mid);
        vx[i] = vx_new;
        vy[i] = vy_new;
        if (compute_energy) {
          kinetic += vx_new * vx_new + vy_new * vy_new;
          strain += kx * (ux0[i] + dt_ * vx_new) + ky * (uy0[i] + dt_ * vy_new);
        }
      });
  record.row_dissipated[j] = dissipated;
  if (compute_energy) {
    record.row_kinetic[j] = 0.5 * m * kinetic;
    record.row_strain[j] = 0.5 * strain;
  }
}

} // namespace slipfront::fe
