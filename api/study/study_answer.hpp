// The headline answer of a study (docs/studies.md "The answer"): the one block every study
// page, `slipfront-client study show` and each report begin with. The verdict (L_c = ... m, in
// [a, b)), what it means in one sentence, how sure it is (which rule, which runs), and only
// then the other numbers, each labelled with what it is. A pure function of the study as the
// server serves it (GET /studies/{id}).
#pragma once

#include <nlohmann/json.hpp>

namespace slipfront::api {

// The paper's critical length for its own scene (Kammer et al. 2014 §3.2; docs/physics.md
// "The paper's published values"), read from its Fig. 4.
inline constexpr double paper_critical_length = 1e-5;

// {state, verdict, meaning, certainty, others: [{label, value, unit}]} of `study` (its
// critical_length, search, accuracy, runs, status and progress); `paper_scene`: whether the
// study's scene is the paper's, so that the paper's value is put beside ours.
nlohmann::json study_answer(const nlohmann::json& study, bool paper_scene);

} // namespace slipfront::api
