// Reading the job's interface sections (docs/api-job-spec.md): `friction` (the law, its
// regularisation and values), `nucleation` (the ellipse or the overstressed patch) and
// `profiles` (overrides along x1). Part of the reader of api/job_reader.hpp.
#pragma once

#include "api/json_fields.hpp"
#include "solver/params.hpp"

#include <vector>

namespace slipfront::api {

constexpr std::size_t max_profiles = 64;

void read_friction(ObjectReader& in, Friction& friction);
void read_nucleation(ObjectReader& in, Nucleation& nucleation);
// `friction`: the job's, already read (an entry may set only the values its law uses).
void read_profiles(ObjectReader& in, const Friction& friction, std::vector<Profile>& profiles);

} // namespace slipfront::api
