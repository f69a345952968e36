// What the study handlers ask of the server: create a study (validate its request, submit
// its first runs as ordinary jobs), view one, list them, cancel one, its speed-accuracy
// analysis and the shared convergence map. It answers with the core's values and the
// analyses' JSON; the handlers write the API's JSON (server/http/study_json.hpp).
#pragma once

#include "server/db/study_store.hpp"
#include "server/services/job_service.hpp"
#include "server/services/study_supervisor.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

struct StudyCreateResult {
  enum class Kind {
    created,      // 201
    replayed,     // 200: the same Idempotency-Key and request as an earlier study: that study
    bad_json,     // 400
    invalid,      // 422 (errors)
    key_conflict, // 422: the Idempotency-Key was used for another request
    queue_full,   // 503
  } kind = Kind::created;
  std::vector<api::FieldError> errors;
  std::optional<std::string> id;
};

struct StudyCancelResult {
  enum class Kind { cancelled, not_found, forbidden, already_over } kind = Kind::cancelled;
  api::StudyStatus status = api::StudyStatus::running; // the study's status before the call
  std::vector<std::string> cancelled_jobs;             // were queued: cancelled now
  std::vector<std::string> cancel_requested_jobs;      // were running: they stop at their next step
};

// The answer to an owner's change to a study (study_service.cpp; docs/server.md "Keep,
// annotate, share").
struct StudyKeepResult {
  enum class Kind {
    done,
    not_found,
    forbidden,      // a token file is configured and the study is another user's
    running,        // delete: the study still runs (cancel it first)
    runs_not_final, // delete: cancelled, but a run of it has not stopped yet
    invalid,        // the change cannot be made (error); nothing changed
  } kind = Kind::not_found;
  std::optional<StudyRecord> study; // done: the study as it is now (delete: as it was)
  std::optional<api::FieldError> error;
  std::vector<std::string> deleted_jobs; // delete: its runs, gone with it
  std::size_t results_deleted = 0;       // delete: result files removed (none shared elsewhere)
};

// The study's scene and the same physics by its method's counterpart (docs/studies.md).
struct MethodScenes {
  std::string method;      // the study's: "fe"
  std::string other;       // its counterpart's: "spectral_bi"
  bool method_first;       // the study's method comes first in the registry (solver/methods.hpp)
  std::string scene;       // the study's own scene hash
  std::string other_scene; // "" when the swapped spec is not valid
};

// A study as GET /studies/{id} shows it (written as JSON by server/http/study_json.hpp).
struct StudyView {
  StudyRecord study;
  std::vector<StudyRunRow> runs;
  // The same scene by the other method (docs/studies.md): unset when the study's base is not
  // valid, "" when the swapped spec is not.
  std::optional<std::string> counterpart_scene_hash;
  std::optional<nlohmann::json> cross_method; // api::cross_method_table of the two scenes
};

class StudyService {
public:
  StudyService(StudyStore& studies, JobService& jobs, StudySupervisor& supervisor)
      : studies_(studies), jobs_(jobs), supervisor_(supervisor) {}

  // One transaction: the study, its first runs and their analysis are stored together or not
  // at all (a crash mid-creation leaves nothing), and the runs are queued once it commits.
  // `idempotency_key` ("" = none): a second request with the same key and the same body gets
  // the first one's study.
  StudyCreateResult create(const std::string& body, const std::string& user,
                           const std::string& idempotency_key = "");
  std::optional<StudyView> view(const std::string& id); // GET /studies/{id}
  std::optional<StudyRecord> get(const std::string& id);
  // Newest first, at most `limit`; `before_seq` is the cursor of the previous page.
  std::vector<StudyRecord> list(int limit, std::optional<std::int64_t> before_seq,
                                std::optional<api::StudyStatus> status,
                                ArchivedRuns archived = ArchivedRuns::include);
  // POST /studies/{id}/cancel: no further runs, and every queued or running run of the
  // study is cancelled. `user` must be the submitter when tokens are in use.
  StudyCancelResult cancel(const std::string& id, const std::string& user, bool auth_enabled);
  // GET /studies/{id}/speed-accuracy (docs/studies-api.md); nullopt for an unknown study.
  std::optional<nlohmann::json> speed_accuracy(const std::string& id);
  // Owner-only changes (docs/server.md "Keep, annotate, share"): tags and note, archive and
  // restore, delete with its runs (a study that is over: finished, or cancelled and stopped).
  StudyKeepResult annotate(const std::string& id, const std::string& user,
                           const api::TagChange& tags, const std::optional<std::string>& note);
  StudyKeepResult set_archived(const std::string& id, const std::string& user, bool archived);
  StudyKeepResult remove(const std::string& id, const std::string& user);
  // GET /convergence-map: the map and L_c of every run of a scene (scene_analysis).
  nlohmann::json convergence_map(const std::string& scene_hash);

private:
  // The study's method and the counterpart scene; nullopt when its base is not valid.
  std::optional<MethodScenes> method_scenes(const StudyRecord& study);

  StudyStore& studies_;
  JobService& jobs_;
  StudySupervisor& supervisor_;
};

} // namespace slipfront::server
