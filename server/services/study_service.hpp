// What the study handlers ask of the server: create a study (validate its request, submit
// its first runs as ordinary jobs), read one, list them, the shared convergence map.
#pragma once

#include "server/db/study_store.hpp"
#include "server/run/job_queue.hpp"
#include "server/services/job_service.hpp"
#include "server/services/study_supervisor.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

struct StudyCreateResult {
  enum class Kind { created, bad_json, invalid, queue_full } kind = Kind::created;
  std::vector<api::FieldError> errors;
  std::optional<std::string> id;
};

struct StudyCancelResult {
  enum class Kind { cancelled, not_found, forbidden, already_over } kind = Kind::cancelled;
  api::StudyStatus status = api::StudyStatus::running; // the study's status before the call
  std::vector<std::string> cancelled_jobs;             // were queued: cancelled now
  std::vector<std::string> cancel_requested_jobs;      // were running: they stop at their next step
};

// The study's scene and the same physics by the other method (docs/studies.md).
struct MethodScenes {
  bool is_fe = true;
  std::string scene;       // the study's own scene hash
  std::string other_scene; // "" when the swapped spec is not valid
};

class StudyService {
public:
  StudyService(StudyStore& studies, JobService& jobs, JobQueue& queue, StudySupervisor& supervisor)
      : studies_(studies), jobs_(jobs), queue_(queue), supervisor_(supervisor) {}

  StudyCreateResult create(const std::string& body, const std::string& user);
  std::optional<nlohmann::json> view(const std::string& id); // GET /studies/{id}
  // POST /studies/{id}/cancel: no further runs, and every queued or running run of the
  // study is cancelled. `user` must be the submitter when tokens are in use.
  StudyCancelResult cancel(const std::string& id, const std::string& user, bool auth_enabled);
  StudyStore& store() { return studies_; }
  // The study's method and the counterpart scene; nullopt when its base is not valid.
  std::optional<MethodScenes> method_scenes(const StudyRecord& study);

private:
  StudyStore& studies_;
  JobService& jobs_;
  JobQueue& queue_;
  StudySupervisor& supervisor_;
};

// The study as GET /studies/{id} shows it; `summary` leaves out the runs and the analysis.
nlohmann::json study_to_json(const StudyRecord& study, const std::vector<StudyRunRow>& runs,
                             bool summary = false);

} // namespace slipfront::server
