#include "server/services/study_service.hpp"

#include "api/json_number.hpp"
#include "server/core/clock.hpp"
#include "server/core/job_id.hpp"
#include "server/core/log.hpp"
#include "server/services/study_progress.hpp"

#include "api/job_methods.hpp"
#include "api/job_spec.hpp"
#include "api/json_parse.hpp"
#include "api/result_reader.hpp"
#include "api/study/failure_regimes.hpp"
#include "api/study_analysis.hpp"
#include "solver/interface/ill_posedness.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>

namespace slipfront::server {

using nlohmann::json;

namespace {

using Kind = StudyCreateResult::Kind;

struct Planned {
  std::string regime;
  json overrides;
  double L;
  double n_d;
  bool submit_now;
};

// The job one run of the request would be, validated (a placeholder study id): how the
// creation steps below read the base's canonical spec and parameters.
api::ParseResult validate_run(const StudyRequest& r, JobService& jobs, double n_d) {
  return jobs.validate(run_document(r, std::string(32, '0'), json::object(), "", r.L[0], n_d));
}

// An L search compares the arrival time where every run's front arrives (docs/metrics.md
// "Convergence status"): unless the base has stations, its runs get 32 evenly over the domain,
// their rupture threshold the front's own. Written into the stored request, so a restart and
// an idempotent replay see the same runs.
void add_search_stations(StudyRequest& r, JobService& jobs) {
  if (!r.search || r.base.contains("stations")) return;
  auto base = validate_run(r, jobs, 10);
  if (!base.spec) return; // its errors are reported by check_run
  const json& canonical = base.spec->canonical;
  const double x_min = canonical["geometry"]["x_min"].get<double>();
  const double width = canonical["geometry"]["width"].get<double>();
  constexpr int count = 32;
  json x1 = json::array();
  for (int k = 0; k < count; ++k)
    x1.push_back(x_min + (k + 0.5) * width / count);
  const json stations = {{"x1", x1}, {"rupture_threshold", canonical["probe"]["front_threshold"]}};
  r.base["stations"] = stations;
  r.body["base"]["stations"] = stations;
}

// An accuracy study (docs/studies-api.md "Accuracy target"): the method, when the request
// leaves it to the service (the cheapest method that applies to the scene, by the registry's
// cost_rank: the spectral BI method where it applies, its runs cost less at the same n_d; else
// the default), and the first mesh of the ladder, from the runs the database already has of
// the scene. Written into the stored request, so that a restart and an idempotent replay see
// the same choices.
void prepare_accuracy(StudyRequest& r, JobService& jobs, StudyStore& studies) {
  if (r.kind != StudyKind::accuracy) return;
  if (!r.base.contains("method")) {
    json chosen = r.base;
    chosen["method"] = std::string(default_method().method.name());
    if (r.method_choice != "auto") {
      chosen = api::method_document(chosen, method_entry(Method(r.method_choice)));
    } else {
      for (const MethodEntry* cheaper : api::cheaper_methods()) {
        StudyRequest trial = r;
        trial.base = api::method_document(chosen, *cheaper);
        if (validate_run(trial, jobs, r.n_d[0]).spec.has_value()) {
          chosen = std::move(trial.base);
          break;
        }
      }
    }
    r.base = chosen;
    r.body["base"] = chosen;
  }
  if (r.accuracy_start) return;
  auto base = validate_run(r, jobs, r.n_d[0]);
  if (!base.spec) return; // its errors are reported by check_run
  std::vector<api::StudyRun> known;
  for (const auto& row : studies.scene_runs(api::scene_hash(base.spec->canonical)))
    known.push_back(to_study_run(row));
  std::string why;
  const std::size_t start = api::accuracy_start(*r.accuracy, r.n_d, r.n_d_max, known, why);
  r.accuracy_start = start;
  r.body["accuracy"]["start"] = {{"n_d", r.n_d[start]}, {"reason", why}};
}

// Whether an L search refines plain Coulomb beside its L (docs/studies-api.md "L search"):
// where the request does not say, where Coulomb is well-posed for the scene. Written into the
// stored request.
void decide_search_coulomb(StudyRequest& r, JobService& jobs) {
  if (!r.search || r.search->coulomb) return;
  auto base = validate_run(r, jobs, 10);
  if (!base.spec) return; // its errors are reported by check_run
  std::string why;
  r.search->coulomb = coulomb_well_posed(base.spec->params, why);
  r.body["convergence"]["search"]["coulomb"] = *r.search->coulomb;
}

// Every run the study may submit: for a convergence study the whole ladder up to the cap
// (checked now, so that a later mesh is not refused), submitted: the first two meshes.
std::vector<Planned> plan_runs(const StudyRequest& r) {
  std::vector<Planned> out;
  switch (r.kind) {
  case StudyKind::grid:
    for (double L : r.L)
      for (double n_d : r.n_d)
        out.push_back({"", json::object(), L, n_d, true});
    break;
  case StudyKind::convergence:
    // An L search starts with its first L only; the supervisor adds the next ones.
    for (double L : r.L) {
      int first = 0;
      const bool started = !r.search || L == r.L.front();
      for (double n_d : r.n_d)
        if (n_d <= r.n_d_max) out.push_back({"", json::object(), L, n_d, started && first++ < 2});
    }
    if (r.search && r.search->coulomb.value_or(false)) {
      int first = 0;
      for (double n_d : r.n_d)
        if (n_d <= r.n_d_max)
          out.push_back({std::string(coulomb_regime), coulomb_overrides(r.base), r.search->from,
                         n_d, first++ < 2});
    }
    break;
  case StudyKind::accuracy: {
    // The ladder from its first mesh up to the cap; the supervisor adds one mesh at a time.
    const std::size_t first = r.accuracy_start.value_or(0);
    for (std::size_t i = first; i < r.n_d.size(); ++i)
      if (r.n_d[i] <= r.n_d_max)
        out.push_back({"", json::object(), r.L[0], r.n_d[i], i < first + 2});
    break;
  }
  case StudyKind::failure_regimes:
    for (const auto& regime : api::failure_regimes())
      for (double n_d : regime.n_d)
        out.push_back({regime.name, api::regime_patch(regime, r.base), regime.L, n_d, true});
    break;
  }
  return out;
}

std::string value_pointer(const StudyRequest& r, const char* axis, double value) {
  const auto& values = std::string(axis) == "L" ? r.L : r.n_d;
  if (r.kind == StudyKind::accuracy && values == r.L) return "/accuracy/L";
  const std::string group = r.kind == StudyKind::convergence ? "/convergence/"
                            : r.kind == StudyKind::accuracy  ? "/accuracy/"
                                                             : "/grid/";
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i] == value) return group + axis + "/" + std::to_string(i);
  return "/preset";
}

// A run's tags are /base/tags, then the study's /tags, then study:<id> (run_document): the
// pointer of the one the client sent, or nullopt when `pointer` is not at a run's tag.
std::optional<std::string> run_tag_pointer(const StudyRequest& r, const std::string& pointer) {
  const std::string prefix = "/tags/";
  if (pointer.rfind(prefix, 0) != 0) return std::nullopt;
  std::size_t index = 0;
  const auto digits = pointer.substr(prefix.size());
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  const std::size_t base_tags = base_tag_count(r);
  if (index < base_tags) return "/base/tags/" + std::to_string(index);
  if (index < base_tags + r.tags.size()) return "/tags/" + std::to_string(index - base_tags);
  return std::nullopt;
}

// The job validator's errors for one run, with pointers into the study body.
void check_run(JobService& jobs, const StudyRequest& r, const Planned& p,
               std::vector<api::FieldError>& errors, std::set<std::string>& seen) {
  auto parsed =
      jobs.validate(run_document(r, std::string(32, '0'), p.overrides, p.regime, p.L, p.n_d));
  for (const auto& e : parsed.errors) {
    std::string pointer;
    if (e.pointer == "/friction/L")
      pointer = value_pointer(r, "L", p.L);
    else if (e.pointer == "/geometry/nodes_per_meter")
      pointer = value_pointer(r, "n_d", p.n_d);
    else
      pointer = run_tag_pointer(r, e.pointer).value_or("/base" + e.pointer);
    std::string reason = e.reason;
    if (!p.regime.empty()) reason += " (preset regime " + p.regime + ")";
    if (seen.insert(pointer + "\n" + reason).second) errors.push_back({pointer, reason});
  }
}

} // namespace

StudyCreateResult StudyService::create(const std::string& body, const std::string& user,
                                       const std::string& idempotency_key) {
  StudyCreateResult out;
  auto body_json = api::parse_bounded_json(body);
  if (!body_json.ok()) {
    out.kind = body_json.status == api::JsonParse::Status::syntax ? Kind::bad_json : Kind::invalid;
    out.errors.push_back(body_json.error);
    return out;
  }
  auto parsed = parse_study_request(body_json.value);
  if (!parsed.request) {
    out.kind = Kind::invalid;
    out.errors = std::move(parsed.errors);
    return out;
  }
  add_search_stations(*parsed.request, jobs_);
  decide_search_coulomb(*parsed.request, jobs_);
  prepare_accuracy(*parsed.request, jobs_, studies_);
  const StudyRequest& request = *parsed.request;
  const auto planned = plan_runs(request);
  std::set<std::string> seen;
  for (const auto& p : planned)
    check_run(jobs_, request, p, out.errors, seen);
  if (!out.errors.empty()) {
    out.kind = Kind::invalid;
    return out;
  }
  std::size_t now_count = 0;
  for (const auto& p : planned)
    now_count += p.submit_now ? 1 : 0;

  StudyRecord study;
  study.id = new_job_id();
  study.name = request.name;
  study.tags = request.tags;
  study.kind = to_string(request.kind);
  study.base = request.base;
  study.request = request.body;
  study.submitted_by = user;
  study.idempotency_key = idempotency_key;
  study.priority = request.priority.value_or(0);
  study.fresh = request.fresh.value_or(false);
  study.created_at = now_iso8601();
  // The scene of the base (for the preset: of its regularised runs).
  auto base = jobs_.validate(run_document(request, study.id, json::object(), "", 5e-5, 10));
  study.scene_hash = base.spec ? api::scene_hash(base.spec->canonical) : "";

  // Under the step lock and the submission lock, in one transaction: the key is looked up
  // where the study would be inserted, and the queue limit counts the runs as they go in.
  supervisor_.exclusive([&] {
    jobs_.submit_together([&] {
      if (!idempotency_key.empty())
        if (auto earlier = studies_.find_by_idempotency_key(user, idempotency_key)) {
          out.id = earlier->id;
          out.kind = earlier->request == request.body ? Kind::replayed : Kind::key_conflict;
          return false;
        }
      studies_.insert(study);
      for (const auto& p : planned) {
        if (!p.submit_now) continue;
        auto r = submit_study_run(jobs_, studies_, study, request, p.overrides, p.regime, p.L,
                                  p.n_d, false);
        if (r.kind == SubmitResult::Kind::queue_full) {
          out.kind = Kind::queue_full;
          return false; // nothing of the study stays
        }
        if (!r.job)
          log_error("study " + study.id + ": a run was refused after validation: " +
                    (r.errors.empty() ? "" : r.errors[0].pointer + " " + r.errors[0].reason));
      }
      supervisor_.step_locked(study.id);
      return true;
    });
  });
  if (out.kind == Kind::key_conflict)
    out.errors.push_back({"", "Idempotency-Key " + idempotency_key +
                                  " was used for a different study (" + *out.id + ")"});
  if (out.kind != Kind::created) return out;
  log_info("study " + study.id + " created (" + study.kind + ", " + std::to_string(now_count) +
           " run(s) submitted) by " + user);
  out.id = study.id;
  return out;
}

StudyCancelResult StudyService::cancel(const std::string& id, const std::string& user,
                                       bool auth_enabled) {
  using CancelKind = StudyCancelResult::Kind;
  StudyCancelResult out;
  supervisor_.exclusive([&] {
    auto study = studies_.get(id);
    if (!study) {
      out.kind = CancelKind::not_found;
      return;
    }
    out.status = study->status;
    if (auth_enabled && study->submitted_by != user) {
      out.kind = CancelKind::forbidden;
      return;
    }
    if (study->status != api::StudyStatus::running) {
      out.kind = CancelKind::already_over;
      return;
    }
    // Cancelled first, under the step lock: no step can submit a further mesh after this.
    studies_.set_status(id, api::StudyStatus::cancelled, now_iso8601());
    auto runs = supervisor_.cancel_runs_locked(*study);
    out.cancelled_jobs = std::move(runs.cancelled);
    out.cancel_requested_jobs = std::move(runs.cancel_requested);
    try {
      supervisor_.step_locked(id);
    } catch (const std::exception& e) { // stored again when its runs end
      log_error("study " + id + ": analysis after the cancel: " + e.what());
    }
  });
  if (out.kind == CancelKind::cancelled)
    log_info("study " + id + " cancelled (" + std::to_string(out.cancelled_jobs.size()) +
             " queued job(s) cancelled, " + std::to_string(out.cancel_requested_jobs.size()) +
             " running job(s) asked to stop)");
  return out;
}

std::optional<MethodScenes> StudyService::method_scenes(const StudyRecord& study) {
  StudyRequest request;
  request.base = study.base;
  auto base = jobs_.validate(run_document(request, study.id, json::object(), "", 5e-5, 10));
  if (!base.spec) return std::nullopt;
  const MethodEntry& method = method_entry(base.spec->params.method);
  const auto order = [](Method m) {
    const auto& all = methods();
    return std::find(all.begin(), all.end(), &method_entry(m)) - all.begin();
  };
  return MethodScenes{std::string(method.method.name()), std::string(method.counterpart.name()),
                      order(method.method) < order(method.counterpart), study.scene_hash,
                      api::counterpart_scene_hash(base.spec->canonical)};
}

std::optional<StudyView> StudyService::view(const std::string& id) {
  auto study = studies_.get(id);
  if (!study) return std::nullopt;
  StudyView view{*study, studies_.runs(id), std::nullopt, std::nullopt};
  // The same scene by the other method, from every run the group has made of it.
  if (const auto scenes = method_scenes(*study)) {
    view.counterpart_scene_hash = scenes->other_scene;
    if (!scenes->other_scene.empty()) {
      const auto mine = studies_.scene_runs(scenes->scene);
      const auto theirs = studies_.scene_runs(scenes->other_scene);
      view.cross_method = scenes->method_first
                              ? cross_method(scenes->method, mine, scenes->other, theirs)
                              : cross_method(scenes->other, theirs, scenes->method, mine);
      // Only the study's own L (an L search's plain-Coulomb runs have none): the scene's other
      // L are other studies' runs, shown on their pages and on the shared map.
      std::set<double> own;
      for (const auto& run : view.runs)
        if (run.regime != "coulomb") own.insert(run.L);
      json kept = json::array();
      for (const auto& row : *view.cross_method) {
        if (!row.is_object()) continue;
        const json& L = row.value("L", json());
        if (L.is_number() && std::any_of(own.begin(), own.end(), [&](double l) {
              return std::abs(l - L.get<double>()) <= 1e-12 * std::abs(l);
            }))
          kept.push_back(row);
      }
      view.cross_method = std::move(kept);
    }
  }
  return view;
}

std::optional<StudyRecord> StudyService::get(const std::string& id) {
  return studies_.get(id);
}

std::vector<StudyRecord> StudyService::list(int limit, std::optional<std::int64_t> before_seq,
                                            std::optional<api::StudyStatus> status,
                                            ArchivedRuns archived) {
  return studies_.list(limit, before_seq, status, archived);
}

StudyKeepResult StudyService::annotate(const std::string& id, const std::string& user,
                                       const api::TagChange& tags,
                                       const std::optional<std::string>& note) {
  using Kind = StudyKeepResult::Kind;
  StudyKeepResult out;
  out.study = studies_.get(id);
  if (!out.study) return {};
  if (jobs_.auth_enabled() && out.study->submitted_by != user) {
    out.kind = Kind::forbidden;
    return out;
  }
  const auto after = studies_.annotate(id, tags, note);
  if (!after) return {};
  if (after->error) {
    out.kind = Kind::invalid;
    out.error = after->error;
    return out;
  }
  out.kind = Kind::done;
  out.study = studies_.get(id);
  return out;
}

StudyKeepResult StudyService::set_archived(const std::string& id, const std::string& user,
                                           bool archived) {
  using Kind = StudyKeepResult::Kind;
  StudyKeepResult out;
  out.study = studies_.get(id);
  if (!out.study) return {};
  if (jobs_.auth_enabled() && out.study->submitted_by != user) {
    out.kind = Kind::forbidden;
    return out;
  }
  // Archiving an archived study keeps its first archive time.
  if (archived == out.study->archived_at.empty()) {
    if (!studies_.set_archived(id, archived ? now_iso8601() : std::string())) return {};
    out.study = studies_.get(id);
  }
  out.kind = Kind::done;
  return out;
}

StudyKeepResult StudyService::remove(const std::string& id, const std::string& user) {
  using Kind = StudyKeepResult::Kind;
  StudyKeepResult out;
  out.study = studies_.get(id);
  if (!out.study) return {};
  if (jobs_.auth_enabled() && out.study->submitted_by != user) {
    out.kind = Kind::forbidden;
    return out;
  }
  StudyStore::Removal removal;
  // Under the step lock: no step of this study submits a run meanwhile.
  supervisor_.exclusive([&] {
    out.results_deleted = jobs_.remove_rows_and_files(
        [&] {
          removal = studies_.remove(id);
          return JobService::RowsRemoved{removal.orphaned_results, removal.intent};
        },
        "study " + id + " deleted");
  });
  using Removed = StudyStore::Removal::Kind;
  switch (removal.kind) {
  case Removed::not_found:
    return {};
  case Removed::running:
    out.kind = Kind::running;
    return out;
  case Removed::runs_not_final:
    out.kind = Kind::runs_not_final;
    return out;
  case Removed::removed:
    break;
  }
  out.kind = Kind::done;
  out.deleted_jobs = std::move(removal.job_ids);
  log_info("study " + id + " deleted by " + user + " with its " +
           std::to_string(out.deleted_jobs.size()) + " run(s) and " +
           std::to_string(out.results_deleted) + " result file(s)");
  return out;
}

json StudyService::convergence_map(const std::string& scene_hash) {
  return scene_analysis(studies_.scene_runs(scene_hash));
}

// speed_accuracy of each regime, with the relative L2 error of the slip-velocity record at
// the spectrum probe against the reference run's record (api/study/speed_accuracy.hpp);
// the records are read from the result files here.
std::optional<json> StudyService::speed_accuracy(const std::string& id) {
  auto study = studies_.get(id);
  if (!study) return std::nullopt;
  auto rows = studies_.runs(id);
  std::map<std::string, const StudyRunRow*> by_id;
  std::vector<api::RegimeRun> runs;
  for (const auto& r : rows) {
    runs.push_back({r.regime, to_study_run(r)});
    by_id[r.job_id] = &r;
  }
  // The slip-velocity record at the spectrum probe, from the run's result file.
  const std::string& data_dir = jobs_.options().data_dir;
  api::SlipVelocityErrors l2([&](const std::string& job_id, std::string& why) {
    const auto* row = by_id.at(job_id);
    std::optional<api::ProbeSeries> series;
    if (row->result_path.empty()) {
      why = "no result file (job " + row->job_status + ")";
    } else if (auto rec = api::read_probe_record(data_dir + "/" + row->result_path, why)) {
      series = api::ProbeSeries{std::move(rec->time), std::move(rec->slip_velocity), rec->x1};
    }
    return series;
  });
  json list = api::speed_accuracy_by_regime(runs, l2);
  // Both methods on one chart: every run of the study's scene and of its counterpart.
  json across = nullptr;
  std::vector<StudyRunRow> scene_rows;
  if (const auto scenes = method_scenes(*study); scenes && !scenes->other_scene.empty()) {
    scene_rows = studies_.scene_runs(scenes->scene);
    const std::size_t own = scene_rows.size();
    auto other_rows = studies_.scene_runs(scenes->other_scene);
    scene_rows.insert(scene_rows.end(), other_rows.begin(), other_rows.end());
    std::vector<api::StudyRun> mine, theirs;
    for (std::size_t k = 0; k < scene_rows.size(); ++k) {
      by_id.emplace(scene_rows[k].job_id, &scene_rows[k]);
      (k < own ? mine : theirs).push_back(to_study_run(scene_rows[k]));
    }
    const api::MethodRuns study_side{scenes->method, mine}, other_side{scenes->other, theirs};
    json across_runs = scenes->method_first
                           ? api::speed_accuracy_across_methods(study_side, other_side)
                           : api::speed_accuracy_across_methods(other_side, study_side);
    for (auto& entry : across_runs)
      l2.add_to(entry);
    across = {{"runs", across_runs},
              {"reference", "the finest reference run of the same L by either method (" +
                                (scenes->method_first ? scenes->other : scenes->method) +
                                " on a tie), from every run of the two scenes"}};
  }
  return json{{"study_id", id},
              {"runs", list},
              {"probe",
               {{"dataset", "/probes/slip_velocity_spectrum"},
                {"x1", api::json_number(l2.probe_x1())},
                {"description", "relative L2 error over time of the slip velocity at the "
                                "spectrum probe (probe.spectrum_x1, default 6 m)"}}},
              {"reference", "the finest non-diverged run of the same L, when that L has a "
                            "mesh-converged run (docs/studies.md)"},
              {"across_methods", across}};
}

} // namespace slipfront::server
