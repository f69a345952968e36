#include "api/cost_estimate.hpp"

#include "api/json_number.hpp"
#include "api/number_text.hpp"
#include "solver/methods.hpp"
#include "solver/simulation.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <thread>

namespace slipfront::api {

namespace {

constexpr std::size_t terms = 5; // setup and the method's four kinds of work

// The method of that name, or an error naming it.
const MethodEntry& entry_of(const std::string& method) {
  const MethodEntry* entry = find_method(method);
  if (!entry) throw std::runtime_error("unknown method " + method);
  return *entry;
}

// The work of a run as the terms its method's model times.
std::array<double, terms> terms_of(const std::string& method, const RunWork& w) {
  const MethodEntry& entry = entry_of(method);
  std::array<double, terms> x{1.0};
  for (std::size_t t = 1; t < terms; ++t)
    x[t] = w.*(entry.cost_terms[t - 1].work);
  return x;
}

// The names of the terms in the model's file.
std::array<const char*, terms> term_names(const std::string& method) {
  const MethodEntry& entry = entry_of(method);
  std::array<const char*, terms> names{"setup_s"};
  for (std::size_t t = 1; t < terms; ++t)
    names[t] = entry.cost_terms[t - 1].name;
  return names;
}

// Solves the n x n system a x = b (Gaussian elimination with partial pivoting); false if it
// is singular.
bool solve(std::vector<std::vector<double>> a, std::vector<double> b, std::vector<double>& x) {
  const std::size_t n = b.size();
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    for (std::size_t r = col + 1; r < n; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (!(std::abs(a[pivot][col]) > 1e-300)) return false;
    std::swap(a[pivot], a[col]);
    std::swap(b[pivot], b[col]);
    for (std::size_t r = col + 1; r < n; ++r) {
      const double f = a[r][col] / a[col][col];
      for (std::size_t c = col; c < n; ++c)
        a[r][c] -= f * a[col][c];
      b[r] -= f * b[col];
    }
  }
  x.assign(n, 0.0);
  for (std::size_t r = n; r-- > 0;) {
    double s = b[r];
    for (std::size_t c = r + 1; c < n; ++c)
      s -= a[r][c] * x[c];
    x[r] = s / a[r][r];
  }
  return true;
}

// Least squares on the relative error over the samples, with every coefficient >= 0: the best
// fit among the subsets of terms whose unconstrained fit is non-negative.
std::array<double, terms> fit(const std::string& method, const std::vector<const CostSample*>& s) {
  std::array<double, terms> best{};
  double best_residual = std::numeric_limits<double>::infinity();
  for (unsigned subset = 1; subset < (1u << terms); ++subset) {
    std::vector<std::size_t> used;
    for (std::size_t t = 0; t < terms; ++t)
      if (subset & (1u << t)) used.push_back(t);
    if (used.size() > s.size()) continue;
    // Rows x / T against 1, each column scaled to at most 1 (the counts span many decades).
    std::vector<double> scale(used.size(), 0.0);
    for (const CostSample* sample : s) {
      const auto x = terms_of(method, sample->work);
      for (std::size_t i = 0; i < used.size(); ++i)
        scale[i] = std::max(scale[i], x[used[i]] / sample->wall_time_s);
    }
    if (std::any_of(scale.begin(), scale.end(), [](double v) { return !(v > 0); })) continue;
    std::vector<std::vector<double>> a(used.size(), std::vector<double>(used.size(), 0.0));
    std::vector<double> b(used.size(), 0.0), c;
    for (const CostSample* sample : s) {
      const auto x = terms_of(method, sample->work);
      for (std::size_t i = 0; i < used.size(); ++i) {
        const double xi = x[used[i]] / sample->wall_time_s / scale[i];
        b[i] += xi;
        for (std::size_t j = 0; j < used.size(); ++j)
          a[i][j] += xi * x[used[j]] / sample->wall_time_s / scale[j];
      }
    }
    if (!solve(a, b, c)) continue;
    std::array<double, terms> candidate{};
    bool non_negative = true;
    for (std::size_t i = 0; i < used.size(); ++i) {
      candidate[used[i]] = c[i] / scale[i];
      non_negative = non_negative && candidate[used[i]] >= 0;
    }
    if (!non_negative) continue;
    double residual = 0;
    for (const CostSample* sample : s) {
      const auto x = terms_of(method, sample->work);
      double model = 0;
      for (std::size_t t = 0; t < terms; ++t)
        model += candidate[t] * x[t];
      residual += std::pow(model / sample->wall_time_s - 1.0, 2);
    }
    if (residual < best_residual) {
      best_residual = residual;
      best = candidate;
    }
  }
  return best;
}

nlohmann::json coefficients_json(const std::string& method, const CostCoefficients& k) {
  const auto& v = k.seconds;
  const auto names = term_names(method);
  nlohmann::json j = nlohmann::json::object();
  for (std::size_t t = 0; t < terms; ++t)
    j[names[t]] = v[t];
  return j;
}

} // namespace

CostModel CostModel::built_in() {
  // Calibrated by `slipfront calibrate` on the development machine (docs/performance.md
  // "Cost estimate"), for a server that was never calibrated.
  CostModel m;
  m.machine = "the development machine (2 cores shared with other work, load about 3)";
  m.calibrated_at = "2026-11-28T16:11:29Z";
  m.source = "built-in";
  // FE {setup, node_step, row_step, interface_step, rate_solve} [s]
  m.coefficients["fe"][1] = {{0.03497, 4.804e-09, 6.267e-07, 2.773e-07, 2.743e-07}};
  m.coefficients["fe"][2] = {{0, 2.632e-09, 7.089e-07, 2.9e-07, 4.484e-07}};
  // BI {setup, lag_step, transform_step, interface_step, rate_solve} [s]
  m.coefficients["spectral_bi"][1] = {{0, 2.413e-09, 1.739e-08, 3.081e-07, 2.378e-07}};
  m.coefficients["spectral_bi"][2] = {{0, 3.768e-09, 1.36e-08, 1.228e-07, 3.458e-07}};
  return m;
}

nlohmann::json CostModel::to_json() const {
  nlohmann::json methods = nlohmann::json::object();
  for (const auto& [method, by_threads] : coefficients)
    for (const auto& [threads, k] : by_threads)
      methods[method][std::to_string(threads)] = coefficients_json(method, k);
  return {{"machine", machine}, {"calibrated_at", calibrated_at}, {"coefficients", methods}};
}

std::optional<CostModel> CostModel::from_json(const nlohmann::json& json, std::string& error) {
  CostModel m;
  try {
    m.machine = json.value("machine", std::string());
    m.calibrated_at = json.value("calibrated_at", std::string());
    for (const auto& [method, by_threads] : json.at("coefficients").items()) {
      entry_of(method); // throws for a method this code does not have
      for (const auto& [threads, k] : by_threads.items()) {
        const int t = std::stoi(threads);
        if (t < 1) throw std::runtime_error("thread count " + threads);
        std::array<double, terms> v{};
        const auto names = term_names(method);
        for (std::size_t i = 0; i < terms; ++i) {
          if (!k.contains(names[i])) { // a file of an older slipfront: the built-in model's term
            v[i] = built_in().at(method, t)->seconds[i];
            m.outdated = true;
            continue;
          }
          v[i] = k.at(names[i]).get<double>();
          if (!(v[i] >= 0 && std::isfinite(v[i])))
            throw std::runtime_error(std::string(names[i]) + " is not a number >= 0");
        }
        m.coefficients[method][t] = {v};
      }
    }
  } catch (const std::exception& e) {
    error = std::string("not a cost model: ") + e.what();
    return std::nullopt;
  }
  return m;
}

CostModel CostModel::read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path + ": " + std::strerror(errno));
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": not JSON: " + e.what());
  }
  std::string error;
  auto model = from_json(json, error);
  if (!model) throw std::runtime_error(path + ": " + error);
  model->source = path;
  if (model->outdated)
    model->source += " (written by an older slipfront: the terms it lacks are the built-in "
                     "model's; run slipfront calibrate again)";
  return *model;
}

std::optional<CostCoefficients> CostModel::at(const std::string& method, int threads) const {
  const auto found = coefficients.find(method);
  if (found == coefficients.end() || found->second.empty()) return std::nullopt;
  const auto& by_threads = found->second;
  if (const auto exact = by_threads.find(threads); exact != by_threads.end()) return exact->second;
  // The nearest calibrated count, its work terms scaled as if the threads shared it evenly.
  auto nearest = by_threads.begin();
  for (auto it = by_threads.begin(); it != by_threads.end(); ++it)
    if (std::abs(it->first - threads) < std::abs(nearest->first - threads)) nearest = it;
  CostCoefficients k = nearest->second;
  const double ratio = double(nearest->first) / threads;
  for (std::size_t t = 1; t < terms; ++t) // the set-up is not shared
    k.seconds[t] *= ratio;
  return k;
}

double modelled_wall_time(const CostModel& model, const std::string& method, int threads,
                          const RunWork& work) {
  const auto k = model.at(method, threads);
  if (!k) return std::numeric_limits<double>::quiet_NaN();
  const auto x = terms_of(method, work);
  const auto& c = k->seconds;
  double wall = 0;
  for (std::size_t t = 0; t < terms; ++t)
    wall += c[t] * x[t];
  return wall;
}

CostEstimate estimate_cost(const SimulationParams& params, double memory_bytes,
                           const CostModel& model) {
  const RunWork work = estimated_work(params);
  CostEstimate e;
  e.steps = work.steps;
  e.dt = work.dt;
  e.memory_bytes = memory_bytes;
  e.threads =
      params.threads > 0 ? params.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  const std::string method(params.method.name());
  e.wall_time_s = modelled_wall_time(model, method, e.threads, work);
  e.stops_on_arrest = params.time.stop_on_arrest;
  e.model = model.source + (model.machine.empty() ? "" : ", " + model.machine) +
            (model.calibrated_at.empty() ? "" : ", calibrated " + model.calibrated_at);
  return e;
}

nlohmann::json estimate_json(const CostEstimate& e) {
  return {{"steps", json_number(e.steps)},
          {"dt", json_number(e.dt)},
          {"memory_bytes", json_bytes(e.memory_bytes)},
          {"wall_time_s", json_number(e.wall_time_s)},
          {"threads", e.threads},
          {"stops_on_arrest", e.stops_on_arrest},
          {"model", e.model}};
}

std::string wall_time_text(double seconds) {
  if (!std::isfinite(seconds)) return "an unknown time";
  if (seconds < 120) return number_text(seconds, 2) + " s";
  if (seconds < 7200) return number_text(seconds / 60, 2) + " min";
  if (seconds < 2 * 86400) return number_text(seconds / 3600, 2) + " h";
  return number_text(seconds / 86400, 2) + " days";
}

CostModel fit_cost_model(const std::vector<CostSample>& samples) {
  CostModel model;
  std::map<std::pair<std::string, int>, std::vector<const CostSample*>> groups;
  for (const CostSample& s : samples)
    if (s.wall_time_s > 0) groups[{s.method, s.threads}].push_back(&s);
  for (const auto& [key, group] : groups)
    model.coefficients[key.first][key.second] = {fit(key.first, group)};
  return model;
}

} // namespace slipfront::api
