// Study analysis (SPEC §2): mesh-convergence status of runs, the L × n_d convergence map,
// the critical length L_c, speed/accuracy and the next mesh of a convergence request.
//
// Pure functions on the runs of one study (runs that differ only in friction.L and
// geometry.nodes_per_meter, i.e. that share a scene_hash): no I/O, no database.
// The rules and their edge cases are documented in docs/studies.md.
#pragma once

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// One run of a study, as the server knows it.
struct StudyRun {
  std::string id;
  double L = 0.0;     // friction.L (m)
  double n_d = 0.0;   // geometry.nodes_per_meter
  std::string status; // job status: queued | running | succeeded | failed | cancelled
  std::optional<nlohmann::json> metrics; // the metrics JSON of SPEC §2, when the run has one
  double wall_time_s = 0.0;
  double memory_bytes = 0.0;
};

enum class ConvergenceStatus { converged, not_converged, unknown, diverged, pending, failed };

std::string to_string(ConvergenceStatus status);

// SPEC §2 / paper §3.1: refining the mesh changes propagation_distance by < 0.5 % and
// arrival_time_at_probe by < 0.1 %. Relative changes, strict inequalities.
struct ConvergenceTolerances {
  double propagation_distance = 0.005;
  double arrival_time = 0.001;
};

constexpr double not_available = std::numeric_limits<double>::quiet_NaN();

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

// L_c of the study (SPEC §2) with the per-L reference runs, the comparison table and the
// spectral estimate of the smallest mesh-converged L.
nlohmann::json critical_length(const std::vector<StudyRun>& runs,
                               const ConvergenceTolerances& tol = {});

// The same L by both methods: the reference (finest, mesh-converged) run of each, its
// metrics, and the relative differences (fe - spectral_bi) / spectral_bi. One row per L of
// either set; a side is null where that method has no mesh-converged run of the L.
nlohmann::json cross_method_table(const std::vector<StudyRun>& fe_runs,
                                  const std::vector<StudyRun>& bi_runs,
                                  const ConvergenceTolerances& tol = {});

// Per finished run: cost and errors relative to the reference run of its L.
nlohmann::json speed_accuracy(const std::vector<StudyRun>& runs,
                              const ConvergenceTolerances& tol = {});

// As speed_accuracy, over the runs of both methods of one scene: each entry names its
// "method", and its errors are against the finest reference run of its L by either method
// (spectral_bi on a tie), named by "reference_run_id" and "reference_method".
nlohmann::json speed_accuracy_across_methods(const std::vector<StudyRun>& fe_runs,
                                             const std::vector<StudyRun>& bi_runs,
                                             const ConvergenceTolerances& tol = {});

// ||v_a - v_ref|| / ||v_ref|| in L2 over time, on the samples of `a` that lie in the common
// time range; the reference is interpolated linearly onto them (trapezoidal rule).
// NaN when fewer than two samples of `a` lie in the common range or ||v_ref|| = 0.
// Throws std::invalid_argument on size mismatch or times that do not increase.
double relative_l2_error(const std::vector<double>& t_a, const std::vector<double>& v_a,
                         const std::vector<double>& t_ref, const std::vector<double>& v_ref);

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
