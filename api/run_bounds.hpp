// The quantities a job implies, bounded at validation before anything is estimated or run
// (docs/api-job-spec.md, "Limits of a run"): the wave speeds, the time step, the number of
// steps, the stations' record and a method's limit of the wave-speed ratio (spectral_bi: its
// kernel's; solver/method_entry.hpp). Each field may
// be in range while together they make an impossible run (a step of 1e-302 s, 1e302 steps, an
// infinite wave speed); the error names the field that alone moves the quantity furthest from the
// paper's scene.
#pragma once

#include "api/job_spec.hpp"

#include <vector>

namespace slipfront::api {

// The shortest time step a run may take [s]: below it omega_max^2 ~ (2 / dt)^2 of the FE
// stable-step iteration could overflow a double.
constexpr double min_time_step = 1e-100;
// The most bytes the stations' series may hold (every step, in memory until the run ends).
constexpr double max_station_record_bytes = 2.5e8;

// Appends an error for each bound a job breaks. Call it only for a job without other errors
// (every field in its range, the mesh consistent).
void check_run_bounds(const JobSpec& job, std::vector<FieldError>& errors);

} // namespace slipfront::api
