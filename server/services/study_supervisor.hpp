// The study supervisor: one thread that brings studies up to date when their runs finish.
//
// A step of a study (always under one lock, so two steps never submit the same mesh):
// for a convergence study, ask api::refinement_plan for every L and submit the next mesh
// where it says run_next (repeat while reused results settle plans at once); then
// recompute the convergence statuses, map and L_c (analyse_study) and store them.
// Triggers: a job of the study finishing (worker pool), a queued job cancelled, the
// study's creation, and start-up (every study still `running` is stepped again, so a
// server restarted mid-study picks up where it stopped). A `cancelled` study submits
// nothing; at start-up its runs that a restart queued again are cancelled.
#pragma once

#include "server/core/study_request.hpp"
#include "server/db/study_store.hpp"
#include "server/services/job_service.hpp"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace slipfront::server {

// Submits one run of a study as an ordinary job (reusing an identical succeeded one as
// POST /jobs does) and records it in study_runs. Returns the submission result.
SubmitResult submit_study_run(JobService& jobs, StudyStore& studies, const StudyRecord& study,
                              const StudyRequest& request, const nlohmann::json& overrides,
                              const std::string& regime, double L, double n_d,
                              bool ignore_queue_limit);

// The runs of a study that a cancel ended (queued ones) or asked to stop (running ones).
struct CancelledRuns {
  std::vector<std::string> cancelled;
  std::vector<std::string> cancel_requested;
};

class StudySupervisor {
public:
  StudySupervisor(StudyStore& studies, JobService& jobs);
  ~StudySupervisor();
  StudySupervisor(const StudySupervisor&) = delete;
  StudySupervisor& operator=(const StudySupervisor&) = delete;

  void start(); // the thread; queues a step of every running study
  void stop();  // finishes the step under way, joins

  void job_finished(const std::string& job_id); // any thread; cheap
  void request_step(const std::string& study_id);

  // Runs f() under the step lock (study creation submits its first runs this way).
  template <class F> auto exclusive(F&& f) {
    std::lock_guard lock(step_mutex_);
    return f();
  }
  void step_locked(const std::string& study_id); // the caller holds exclusive()
  // Cancels every unfinished run of `study` (as its submitter); a run that cannot be
  // cancelled is logged and skipped. The caller holds exclusive().
  CancelledRuns cancel_runs_locked(const StudyRecord& study);

private:
  void loop();
  bool start_L(const StudyRecord& study, const StudyRequest& request, double L);
  // An accuracy study's next mesh, if its verdict asks for one and `may_submit` (not once
  // cancelled), and the verdict as JSON (docs/studies-api.md "Accuracy target");
  // `plans_open` while a mesh is queued or running.
  nlohmann::json accuracy_step(const StudyRecord& study, const StudyRequest& request,
                               std::vector<StudyRunRow>& rows, bool may_submit, bool& plans_open);

  StudyStore& studies_;
  JobService& jobs_;
  std::mutex step_mutex_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::string> pending_;
  std::set<std::string> queued_;
  bool stopping_ = false;
  std::thread thread_;
};

} // namespace slipfront::server
