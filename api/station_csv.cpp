#include "api/station_csv.hpp"

#include <charconv>

namespace slipfront::api {

namespace {

// The shortest decimal text that reads back as exactly `value` ("nan" for NaN).
void put(std::ostream& out, double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  out.write(text, end - text);
}

} // namespace

void write_stations_csv(std::ostream& out, const StationRecords& r) {
  out << "# slipfront stations: one row per station and time step, every step of the run\n"
         "# units: station_x1 [m], time [s], slip [m], slip_rate [m/s], shear_traction [Pa], "
         "normal_traction [Pa] (negative in compression)\n"
         "# rupture_time [s]: the first time |slip_rate| > rupture_threshold = ";
  put(out, r.rupture_threshold);
  out << " m/s, linear in time between steps (nan: never)\n";
  for (std::size_t s = 0; s < r.x1.size(); ++s) {
    out << "# station_x1 = ";
    put(out, r.x1[s]);
    out << ": rupture_time = ";
    put(out, r.rupture_time[s]);
    out << '\n';
  }
  out << "station_x1,time,slip,slip_rate,shear_traction,normal_traction\n";
  const std::size_t n = r.x1.size();
  for (std::size_t s = 0; s < n; ++s) {
    for (std::size_t k = 0; k < r.time.size(); ++k) {
      const std::size_t at = k * n + s;
      for (double value : {r.x1[s], r.time[k], r.slip[at], r.slip_rate[at], r.shear_traction[at]}) {
        put(out, value);
        out << ',';
      }
      put(out, r.normal_traction[at]);
      out << '\n';
    }
  }
}

} // namespace slipfront::api
