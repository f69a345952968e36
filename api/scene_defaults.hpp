// The defaults with a unit, at the job's own scale (docs/api-job-spec.md "Defaults and the
// scene's scale").
//
// Every default of the job schema is the paper's scene, in its scaled units: rho = 1 kg/m^3
// and E = 2.5 Pa, so c_s = 1 m/s and a shear modulus of 1 Pa. A job of the paper's material
// keeps them all. For another material the defaults that only watch the run are derived from
// the scene instead (the arrest window, the output interval, the probes, the front
// threshold), and those that are the physics (stresses, lengths, times of the scene) keep the
// paper's value with a warning (api/scene_checks.hpp). At every scale the stations' rupture
// threshold is the front's unless the job gives it.
#pragma once

#include "api/job_spec.hpp"
#include "solver/interface/nucleation.hpp"

#include <nlohmann/json.hpp>

namespace slipfront::api {

// Whether a material is the paper's (rho, E and nu those of the job schema's defaults, to
// 1e-9 relative: the wave-speed form of the same solid counts).
bool paper_material(const Material& material);

// Fills the defaults a job did not give that belong to its scale (above) into job.params and
// job.canonical, and records in job.provenance every number with a unit the run takes and
// where it came from. `given` is the job as sent, `document` the job after its preset was
// expanded (api/presets.hpp). Call it for a job whose fields have no error.
void apply_scene_defaults(const nlohmann::json& given, const nlohmann::json& document,
                          JobSpec& job);

// "[0, 3.65] m": a nucleation patch as people read it (an end within 1e-9 of the patch's
// length of 0, the ellipse's round-off, shown as 0).
std::string patch_text(const slipfront::Interval& patch);

} // namespace slipfront::api
