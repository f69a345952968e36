#include "api/length_fit/law_fit.hpp"

// GCC 12 warns of an uninitialised register inside its own AVX-512 intrinsics when Eigen's
// dense code is built with -march=native (GCC bug 105593, a false positive).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Dense>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/LevenbergMarquardt>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <utility>
#include <vector>

namespace slipfront::api {

namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double max_scan_decades = 40;

// What the fit varies, as a vector x = [ln L, ln V* (if fitted), mu (if fitted)], and the
// values of the others. ln L and ln V* are kept inside generous bounds so that a flat misfit
// cannot carry them to overflow.
struct Unknowns {
  bool v_star = false, mu = false;
  LawParameters fixed;
  double ln_L_lo = 0, ln_L_hi = 0;

  int count() const { return 1 + int(v_star) + int(mu); }
  LawParameters law(const Eigen::VectorXd& x) const {
    LawParameters p = fixed;
    p.L = std::exp(std::clamp(x[0], ln_L_lo, ln_L_hi));
    int i = 1;
    if (v_star) p.v_star = std::exp(std::clamp(x[i++], std::log(1e-12), std::log(1e6)));
    if (mu) p.mu = x[i];
    return p;
  }
  Eigen::VectorXd vector(const LawParameters& p) const {
    Eigen::VectorXd x(count());
    x[0] = std::log(p.L);
    int i = 1;
    if (v_star) x[i++] = std::log(p.v_star);
    if (mu) x[i] = p.mu;
    return x;
  }
};

// The misfit (model - measured) / scale at the slipping samples.
class Misfit {
public:
  Misfit(const InterfaceRecord& record, const SlippingSamples& slipping, double scale)
      : record_(record), slipping_(slipping), scale_(scale) {}

  std::size_t size() const { return slipping_.count; }
  double scale() const { return scale_; }
  Eigen::VectorXd operator()(const LawParameters& law) const {
    const std::vector<double> model = prakash_clifton_strength(record_, law);
    Eigen::VectorXd r(static_cast<Eigen::Index>(size()));
    Eigen::Index i = 0;
    for (std::size_t k = 0; k < model.size(); ++k)
      if (slipping_.slipping[k])
        r[i++] = (model[k] - std::abs(record_.frictional_stress[k])) / scale_;
    return r;
  }

private:
  const InterfaceRecord& record_;
  const SlippingSamples& slipping_;
  double scale_;
};

// The functor Eigen's Levenberg-Marquardt minimises: residuals and their Jacobian by central
// differences.
struct LeastSquares : Eigen::DenseFunctor<double> {
  LeastSquares(const Misfit& misfit, const Unknowns& unknowns)
      : Eigen::DenseFunctor<double>(unknowns.count(), int(misfit.size())), misfit(misfit),
        unknowns(unknowns) {}
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    f = misfit(unknowns.law(x));
    return 0;
  }
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jacobian) const {
    jacobian.resize(values(), inputs());
    for (int j = 0; j < inputs(); ++j) {
      const double h = 1e-5 * std::max(1.0, std::abs(x[j]));
      Eigen::VectorXd plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      jacobian.col(j) = (misfit(unknowns.law(plus)) - misfit(unknowns.law(minus))) / (2 * h);
    }
    return 0;
  }
  const Misfit& misfit;
  const Unknowns& unknowns;
};

// For a fitted mu the model is mu times the model at mu = 1 (eq. 1 is linear in mu), so the
// best mu of each L is a projection.
LawParameters best_mu(const Misfit& misfit, LawParameters law) {
  law.mu = 1.0;
  const Eigen::VectorXd unit = misfit(law); // (g - tau) / scale
  law.mu = 0.0;
  const Eigen::VectorXd minus_tau = misfit(law); // -tau / scale
  const Eigen::VectorXd g = unit - minus_tau;
  const double gg = g.squaredNorm();
  law.mu = gg > 0 ? -g.dot(minus_tau) / gg : 1.0;
  return law;
}

// The misfit's integrated correlation time in samples, tau = 1 + 2 sum_k rho_k over the lags
// k = 1, 2, ... up to the first rho_k <= 0 (rho_k: the autocorrelation of the slipping
// samples' misfit taken in order, by FFT), within [1, m]: m / tau samples are independent.
double correlation_time(const Eigen::VectorXd& r) {
  const std::size_t m = std::size_t(r.size());
  const double sum = r.squaredNorm();
  if (m < 2 || !(sum > 0)) return 1.0;
  std::vector<double> padded(2 * m, 0.0);
  for (std::size_t i = 0; i < m; ++i)
    padded[i] = r[Eigen::Index(i)];
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);
  for (auto& c : spectrum)
    c = std::norm(c);
  std::vector<double> lagged;
  fft.inv(lagged, spectrum);
  double tau = 1.0;
  for (std::size_t k = 1; k < m; ++k) {
    const double rho = lagged[k] / lagged[0];
    if (!(rho > 0)) break;
    tau += 2 * rho;
  }
  return std::clamp(tau, 1.0, double(m));
}

// The search over ln L, ln V* and mu on one record.
class Search {
public:
  Search(const InterfaceRecord& record, const SlippingSamples& slipping,
         const LawFitSettings& settings, double L_min, double L_max)
      : misfit_(record, slipping, stress_scale(record, slipping)) {
    unknowns_.v_star = settings.fit_v_star;
    unknowns_.mu = !settings.mu.has_value();
    unknowns_.fixed = {L_min, settings.v_star, settings.mu.value_or(1.0)};
    unknowns_.ln_L_lo = std::log(L_min) - 2 * std::log(10.0);
    unknowns_.ln_L_hi = std::log(L_max) + 2 * std::log(10.0);
  }

  const Misfit& misfit() const { return misfit_; }
  const Unknowns& unknowns() const { return unknowns_; }

  // Eight lengths per decade over [L_min, L_max], mu projected when fitted, V* as given.
  LawParameters scan(double L_min, double L_max) const {
    LawParameters best = unknowns_.fixed;
    double best_sum = infinity;
    const double step = std::log(10.0) / 8;
    const int points = int(std::ceil(std::log(L_max / L_min) / step)) + 1;
    for (int i = 0; i < points; ++i) {
      LawParameters law = unknowns_.fixed;
      law.L = std::min(L_max, L_min * std::exp(i * step));
      if (unknowns_.mu) law = best_mu(misfit_, law);
      const double sum = misfit_(law).squaredNorm();
      if (sum < best_sum) {
        best_sum = sum;
        best = law;
      }
    }
    return best;
  }

  // Levenberg-Marquardt from `start`; `start` again when it does not lower the misfit or
  // leaves [L_min, L_max] (the misfit is flat there). `iterations` gets its count.
  LawParameters refine(const LawParameters& start, double L_min, double L_max,
                       int& iterations) const {
    LeastSquares functor(misfit_, unknowns_);
    Eigen::LevenbergMarquardt<LeastSquares> solver(functor);
    solver.setMaxfev(400);
    solver.setXtol(1e-12);
    solver.setFtol(1e-14);
    Eigen::VectorXd x = unknowns_.vector(start);
    solver.minimize(x);
    iterations = int(solver.iterations());
    const LawParameters law = unknowns_.law(x);
    const bool inside = x.allFinite() && law.L >= L_min && law.L <= L_max;
    if (!inside || !(misfit_(law).squaredNorm() <= misfit_(start).squaredNorm())) return start;
    return law;
  }

  // The standard errors of x = [ln L, ln V*, mu] (those fitted), infinite when the record
  // does not determine them: cov = s^2 (J^T J)^-1, s^2 = |r|^2 / (m - p), not yet widened.
  Eigen::VectorXd standard_errors(const LawParameters& law) const {
    const int p = unknowns_.count();
    const LeastSquares functor(misfit_, unknowns_);
    Eigen::MatrixXd jacobian;
    functor.df(unknowns_.vector(law), jacobian);
    const Eigen::VectorXd r = misfit_(law);
    const double s2 = r.squaredNorm() / std::max(1.0, double(r.size() - p));
    Eigen::VectorXd out = Eigen::VectorXd::Constant(p, infinity);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(jacobian);
    if (qr.rank() < p) return out;
    const Eigen::MatrixXd R =
        qr.matrixR().topLeftCorner(p, p).triangularView<Eigen::Upper>().toDenseMatrix();
    const Eigen::MatrixXd r_inverse = R.inverse();
    const Eigen::MatrixXd covariance = qr.colsPermutation() * (r_inverse * r_inverse.transpose()) *
                                       qr.colsPermutation().transpose();
    for (int j = 0; j < p; ++j)
      out[j] = std::sqrt(s2 * covariance(j, j));
    return out;
  }

private:
  static double stress_scale(const InterfaceRecord& record, const SlippingSamples& slipping) {
    double scale = 0;
    for (std::size_t k = 0; k < record.size(); ++k)
      if (slipping.slipping[k]) scale = std::max(scale, std::abs(record.frictional_stress[k]));
    return scale > 0 ? scale : 1.0;
  }

  Misfit misfit_;
  Unknowns unknowns_;
};

// Every second sample of a record from `first` (0 or 1), with its slipping flags.
std::pair<InterfaceRecord, SlippingSamples>
every_second(const InterfaceRecord& record, const SlippingSamples& slipping, std::size_t first) {
  std::pair<InterfaceRecord, SlippingSamples> out;
  out.second.threshold = slipping.threshold;
  for (std::size_t k = first; k < record.size(); k += 2) {
    for (std::size_t c = 0; c < record_column_count; ++c)
      out.first.column(RecordColumn(c)).push_back(record.column(RecordColumn(c))[k]);
    out.second.slipping.push_back(slipping.slipping[k]);
    out.second.count += std::size_t(slipping.slipping[k]);
  }
  return out;
}

// For each fitted parameter of x = [ln L, ln V*, mu], the largest change of it over the fits
// of the two halves of the record (every second sample), started from the full record's fit:
// how much the record's sampling moves it.
Eigen::VectorXd sampling_errors(const InterfaceRecord& record, const SlippingSamples& slipping,
                                const LawFitSettings& settings, const LawParameters& law,
                                double L_min, double L_max) {
  const Search whole(record, slipping, settings, L_min, L_max);
  const Eigen::VectorXd x = whole.unknowns().vector(law);
  Eigen::VectorXd worst = Eigen::VectorXd::Zero(x.size());
  for (std::size_t first : {0, 1}) {
    const auto [half, half_slipping] = every_second(record, slipping, first);
    if (half_slipping.count <= std::size_t(x.size()))
      return Eigen::VectorXd::Constant(x.size(), infinity);
    const Search search(half, half_slipping, settings, L_min, L_max);
    int iterations = 0;
    const LawParameters refit = search.refine(law, L_min, L_max, iterations);
    worst = worst.cwiseMax((search.unknowns().vector(refit) - x).cwiseAbs());
  }
  return worst;
}

} // namespace

LawFit fit_prakash_clifton(const InterfaceRecord& record, const SlippingSamples& slipping,
                           const LawFitSettings& settings) {
  LawFit fit;
  fit.v_star_fitted = settings.fit_v_star;
  fit.mu_fitted = !settings.mu.has_value();
  fit.fitted_samples = slipping.count;
  double peak_speed = 0, shortest_step = infinity;
  for (std::size_t k = 0; k < record.size(); ++k) {
    peak_speed = std::max(peak_speed, std::abs(record.slip_rate[k]));
    if (k > 0) shortest_step = std::min(shortest_step, record.time[k] - record.time[k - 1]);
  }
  // The lengths a record resolves: the law's rate (|V| + V*)/L is 1000 per shortest step at
  // L_min (tau_s follows mu p within it) and 1/1000 per record at L_max (tau_s frozen).
  const double speed = peak_speed + settings.v_star;
  fit.L_max = 1e3 * speed * (record.time.back() - record.time.front());
  // At most max_scan_decades: a record whose steps span more is scanned at its top.
  fit.L_min = std::max(1e-3 * speed * shortest_step, fit.L_max * std::pow(10.0, -max_scan_decades));

  // 1. The scan, 2. Levenberg-Marquardt from its best.
  const Search search(record, slipping, settings, fit.L_min, fit.L_max);
  const LawParameters start = search.scan(fit.L_min, fit.L_max);
  const LawParameters law = search.refine(start, fit.L_min, fit.L_max, fit.iterations);
  fit.law = law;
  const bool at_min = law.L <= fit.L_min * (1 + 1e-9), at_max = law.L >= fit.L_max * (1 - 1e-9);
  fit.at_scan_limit = at_min || at_max;

  // 3. The uncertainty of each parameter: the statistical standard error widened by sqrt(tau) for
  // the misfit's correlation time tau (m / tau independent samples), and the sampling error in
  // quadrature; 95 % intervals from z = 1.96.
  const Eigen::VectorXd r = search.misfit()(law);
  const double m = double(r.size());
  fit.rms_misfit = std::sqrt(r.squaredNorm() / m) * search.misfit().scale();
  fit.misfit_correlation_time = correlation_time(r);
  fit.effective_samples = m / fit.misfit_correlation_time;
  const double widen = std::sqrt(fit.misfit_correlation_time);
  const Eigen::VectorXd statistical = search.standard_errors(law) * widen;
  const Eigen::VectorXd sampling =
      sampling_errors(record, slipping, settings, law, fit.L_min, fit.L_max);
  const Eigen::VectorXd standard_error =
      statistical.binaryExpr(sampling, [](double a, double b) { return std::hypot(a, b); });
  fit.ln_L_statistical_error = statistical[0];
  fit.ln_L_sampling_error = sampling[0];
  fit.ln_L_standard_error = standard_error[0];
  fit.L_low = at_min ? 0.0 : law.L * std::exp(-interval_z * fit.ln_L_standard_error);
  fit.L_high = at_max ? infinity : law.L * std::exp(interval_z * fit.ln_L_standard_error);
  int j = 1;
  if (settings.fit_v_star) {
    fit.ln_v_star_standard_error = standard_error[j++];
    fit.v_star_low = law.v_star * std::exp(-interval_z * fit.ln_v_star_standard_error);
    fit.v_star_high = law.v_star * std::exp(interval_z * fit.ln_v_star_standard_error);
  }
  if (fit.mu_fitted) fit.mu_standard_error = standard_error[j];
  fit.fitted_stress = prakash_clifton_strength(record, law);
  return fit;
}

} // namespace slipfront::api
