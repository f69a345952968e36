// Mesh convergence (docs/metrics.md "Convergence status"): the status of each run of a study, the L
// × n_d convergence map (paper Fig. 3c) and the next mesh of a convergence request.
//
// Pure functions on the runs of one study (runs that differ only in friction.L and
// geometry.nodes_per_meter, i.e. that share a scene_hash): no I/O, no database.
// The rules and their edge cases are documented in docs/studies.md.
#pragma once

#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slipfront::api {

enum class ConvergenceStatus { converged, not_converged, unknown, diverged, pending, failed };

std::string to_string(ConvergenceStatus status);

// The mesh-convergence status of one run, judged against its partner (the next finer mesh).
struct RunConvergence {
  std::string run_id;
  double L = 0.0;
  double n_d = 0.0;
  ConvergenceStatus status = ConvergenceStatus::unknown;
  std::string partner_id;                             // "" when no partner was used
  double partner_n_d = not_available;                 // NaN when no partner was used
  double propagation_distance_change = not_available; // |this - partner| / |partner|
  double arrival_time_change = not_available;         // |this - partner| / |partner|
  std::string reason;                                 // one sentence for the reader
};

// Status of every run, in the order of `runs` (rules: docs/studies.md).
std::vector<RunConvergence> convergence_statuses(const std::vector<StudyRun>& runs,
                                                 const ConvergenceTolerances& tol = {});

// The L × n_d map: {"L": [...], "n_d": [...], "cells": [...], "converged_n_d": {L: n_d|null}}.
nlohmann::json convergence_map(const std::vector<StudyRun>& runs,
                               const ConvergenceTolerances& tol = {});

// What a convergence request for one L should do next.
struct RefinementPlan {
  enum class State { run_next, waiting, converged, not_converged_at_cap };
  State state = State::run_next;
  double next_n_d = not_available;      // set when state == run_next
  double converged_n_d = not_available; // smallest converged n_d when state == converged
  std::string reason;
};

std::string to_string(RefinementPlan::State state);

// Refine along `ladder` (e.g. {10, 20, 40, 80, 160}) until the criterion holds between two
// successive meshes, never beyond `cap`. Runs of other L in `runs` are ignored.
RefinementPlan refinement_plan(double L, const std::vector<StudyRun>& runs,
                               const std::vector<double>& ladder, double cap,
                               const ConvergenceTolerances& tol = {});

} // namespace slipfront::api
