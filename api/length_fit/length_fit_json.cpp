#include "api/length_fit/length_fit_json.hpp"

#include "api/json_number.hpp"

#include <cmath>

namespace slipfront::api {

namespace {

nlohmann::json numbers(const std::vector<double>& values) {
  nlohmann::json out = nlohmann::json::array();
  for (double v : values)
    out.push_back(json_number(v));
  return out;
}

const char* source_name(RecordSource::Kind kind) {
  switch (kind) {
  case RecordSource::Kind::csv:
    return "csv";
  case RecordSource::Kind::stations_csv:
    return "stations_csv";
  case RecordSource::Kind::json:
    break;
  }
  return "json";
}

nlohmann::json record_json(const InterfaceRecord& record, const LengthFit& r) {
  const RecordSource& s = record.source;
  return {
      {"source", source_name(s.kind)},
      {"station_x1", s.station_x1 ? json_number(*s.station_x1) : nlohmann::json()},
      {"stations_in_file", s.station_x1 ? nlohmann::json(s.stations_in_file) : nlohmann::json()},
      {"samples", record.size()},
      {"duration", json_number(record.time.back() - record.time.front())},
      {"slipping_samples", r.slipping.count},
      {"slip_threshold", json_number(r.slipping.threshold)},
      {"peak_slip_rate", json_number(r.peak_slip_rate)}};
}

nlohmann::json fit_json(const LawFit& f) {
  const auto interval = [](double lo, double hi) {
    return nlohmann::json::array({json_number(lo), json_number(hi)});
  };
  return {
      {"L", json_number(f.law.L)},
      {"L_interval_95", interval(f.L_low, f.L_high)},
      {"ln_L_standard_error", json_number(f.ln_L_standard_error)},
      {"ln_L_statistical_error", json_number(f.ln_L_statistical_error)},
      {"ln_L_sampling_error", json_number(f.ln_L_sampling_error)},
      {"v_star", json_number(f.law.v_star)},
      {"v_star_fitted", f.v_star_fitted},
      {"v_star_interval_95",
       f.v_star_fitted ? interval(f.v_star_low, f.v_star_high) : nlohmann::json()},
      {"mu", json_number(f.law.mu)},
      {"mu_fitted", f.mu_fitted},
      {"mu_standard_error", f.mu_fitted ? json_number(f.mu_standard_error) : nlohmann::json()},
      {"rms_misfit", json_number(f.rms_misfit)},
      {"misfit_correlation_time", json_number(f.misfit_correlation_time)},
      {"effective_samples", json_number(f.effective_samples)},
      {"fitted_samples", f.fitted_samples},
      {"scan",
       {{"L_min", json_number(f.L_min)},
        {"L_max", json_number(f.L_max)},
        {"at_limit", f.at_scan_limit}}},
      {"iterations", f.iterations},
  };
}

nlohmann::json spectrum_json(const LengthFit& r) {
  const RecordSpectrum& s = r.spectrum;
  return {{"signal", "contact_pressure"},
          {"sample_interval", json_number(s.sample_interval)},
          {"samples", s.samples},
          {"resampled", s.resampled},
          {"frequency_99", json_number(s.frequency_99)},
          {"power_above_f_m", json_number(r.verdict.power_above_f_m)},
          {"frequency", numbers(s.spectrum.frequency)},
          {"power", numbers(s.spectrum.power)}};
}

nlohmann::json verdict_json(const LengthFitVerdict& v) {
  return {{"rich_enough", v.rich_enough},
          {"L_m_is", v.rich_enough ? "physical_length" : "upper_bound"},
          {"text", v.text},
          {"reason", v.reason},
          {"power_above_f_m", json_number(v.power_above_f_m)},
          {"power_threshold", json_number(v.power_threshold)},
          {"event_critical_length", json_number(v.event_critical_length)},
          {"upper_bound", json_number(v.upper_bound)},
          {"borderline", v.borderline}};
}

nlohmann::json series_json(const InterfaceRecord& record, const LengthFit& r) {
  std::vector<double> stress, coulomb;
  nlohmann::json slipping = nlohmann::json::array();
  for (std::size_t k = 0; k < record.size(); ++k) {
    stress.push_back(std::abs(record.frictional_stress[k]));
    coulomb.push_back(r.fit.law.mu * std::max(0.0, record.contact_pressure[k]));
    slipping.push_back(bool(r.slipping.slipping[k]));
  }
  return {{"time", numbers(record.time)},
          {"frictional_stress", numbers(stress)},
          {"fitted_stress", numbers(r.fit.fitted_stress)},
          {"coulomb_strength", numbers(coulomb)},
          {"slip_rate", numbers(record.slip_rate)},
          {"slipping", std::move(slipping)}};
}

} // namespace

nlohmann::json length_fit_json(const InterfaceRecord& record, const LengthFit& r) {
  return {{"law", "simplified Prakash-Clifton (paper eq. 1): d tau_s/dt = -(|V| + V*)/L "
                  "(tau_s - mu max(0, p))"},
          {"record", record_json(record, r)},
          {"fit", fit_json(r.fit)},
          {"critical_frequency",
           {{"f_m", json_number(r.critical_frequency)},
            {"attenuation_ratio", critical_attenuation_ratio},
            {"slip_rate", json_number(r.peak_slip_rate)},
            {"v_star", json_number(r.fit.law.v_star)}}},
          {"spectrum", spectrum_json(r)},
          {"verdict", verdict_json(r.verdict)},
          {"series", series_json(record, r)}};
}

} // namespace slipfront::api
