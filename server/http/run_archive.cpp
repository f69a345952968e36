#include "server/http/run_archive.hpp"

#include "api/free_text.hpp"
#include "api/json_fields.hpp"
#include "api/json_number.hpp"
#include "api/json_parse.hpp"
#include "api/metrics_reader.hpp"
#include "api/number_text.hpp"
#include "api/run_annotations.hpp"
#include "server/core/clock.hpp"
#include "server/core/file_descriptor.hpp"
#include "server/core/job_id.hpp"
#include "server/core/study_request.hpp"
#include "server/core/tar_archive.hpp"
#include "server/http/job_json.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace slipfront::server {

namespace {

using nlohmann::json;

constexpr const char* study_member = "study.json";

std::string job_member(const std::string& id) {
  return "runs/" + id + "/job.json";
}
std::string result_member(const std::string& id) {
  return "runs/" + id + "/result.h5";
}

bool has_result(const Job& job) {
  return job.status == JobStatus::succeeded && !job.result.path.empty();
}

OpenedResult open_intact(JobService& service, const Job& job) {
  OpenedResult file = service.result_files().open(job.result);
  if (file.state != OpenedResult::State::intact)
    throw ArchiveRefusal(
        job.id, "the result file of job " + job.id + " is " +
                    (file.state == OpenedResult::State::missing ? "missing" : file.reason) +
                    ": it cannot be exported");
  return file;
}

} // namespace

ArchivePlan plan_run_archive(JobService& service, const std::vector<Job>& jobs,
                             const nlohmann::json* study) {
  // Every file is checked (and every job.json made) before a byte is written; the result
  // files are opened again, one at a time, when they are copied.
  ArchivePlan plan;
  json runs = json::array(), files = json::array();
  std::vector<std::uint64_t> sizes;
  for (const Job& job : jobs) {
    json record = job_to_json(job);
    record["front"] = service.front(job.id).value_or(json());
    plan.job_texts.push_back(record.dump(2) + "\n");
    const std::string& text = plan.job_texts.back();
    files.push_back(
        {{"name", job_member(job.id)}, {"size", text.size()}, {"sha256", api::sha256_hex(text)}});
    sizes.push_back(text.size());
    json run = {{"id", job.id}, {"job", job_member(job.id)}, {"result", nullptr}};
    if (has_result(job)) {
      open_intact(service, job);
      files.push_back({{"name", result_member(job.id)},
                       {"size", job.result.size},
                       {"sha256", job.result.sha256}});
      sizes.push_back(job.result.size);
      run["result"] = result_member(job.id);
    }
    runs.push_back(std::move(run));
  }
  if (study) {
    plan.study_text = study->dump(2) + "\n";
    files.push_back({{"name", study_member},
                     {"size", plan.study_text.size()},
                     {"sha256", api::sha256_hex(plan.study_text)}});
    sizes.push_back(plan.study_text.size());
  }
  json manifest = {
      {"format", archive_format},
      {"version", archive_version},
      {"exported_at", now_iso8601()},
      {"server", {{"host", host_name()}, {"code_version", service.options().code_version}}},
      {"runs", std::move(runs)},
      {"files", std::move(files)}};
  if (study) manifest["study"] = study_member;
  plan.manifest = manifest.dump(2) + "\n";
  sizes.push_back(plan.manifest.size());
  plan.size = TarWriter::archive_size(sizes);
  return plan;
}

nlohmann::json study_archive_json(const StudyRecord& s, const std::vector<StudyRunRow>& runs) {
  json rows = json::array();
  for (const auto& r : runs)
    rows.push_back(
        {{"job_id", r.job_id},
         {"regime", r.regime},
         {"L", r.L},
         {"n_d", r.n_d},
         {"convergence_status", r.convergence_status},
         {"partner_n_d", api::json_number(r.partner_n_d)},
         {"propagation_distance_change", api::json_number(r.propagation_distance_change)},
         {"arrival_time_change", api::json_number(r.arrival_time_change)},
         {"reason", r.reason}});
  return {{"id", s.id},
          {"name", s.name},
          {"tags", s.tags},
          {"note", s.note},
          {"kind", s.kind},
          {"status", api::to_string(s.status)},
          {"base", s.base},
          {"request", s.request},
          {"scene_hash", s.scene_hash},
          {"submitted_by", s.submitted_by},
          {"priority", s.priority},
          {"fresh", s.fresh},
          {"created_at", s.created_at},
          {"updated_at", s.updated_at.empty() ? json(nullptr) : json(s.updated_at)},
          {"finished_at", s.finished_at.empty() ? json(nullptr) : json(s.finished_at)},
          {"runs_done", s.runs_done},
          {"runs_total", s.runs_total},
          {"L_c", api::json_number(s.L_c)},
          {"spectral_critical_length", api::json_number(s.spectral_critical_length)},
          {"result", s.result},
          {"runs", std::move(rows)}};
}

void write_run_archive(int fd, JobService& service, const std::vector<Job>& jobs,
                       const ArchivePlan& plan) {
  TarWriter tar(fd);
  tar.add("manifest.json", plan.manifest);
  if (!plan.study_text.empty()) tar.add(study_member, plan.study_text);
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    tar.add(job_member(jobs[i].id), plan.job_texts[i]);
    if (has_result(jobs[i])) {
      OpenedResult file = open_intact(service, jobs[i]);
      tar.add_from(result_member(jobs[i].id), file.fd.get(), file.size);
    }
  }
  tar.finish();
}

namespace {

// A job.json read field by field; every refusal names the member and the JSON pointer.
class RecordReader {
public:
  // `prefix`: where the record is inside the member ("runs/0/"), for the pointers.
  RecordReader(const json& record, std::string member, std::string prefix = "")
      : record_(record), member_(std::move(member)), prefix_(std::move(prefix)) {}

  [[noreturn]] void refuse(const std::string& key, const std::string& reason) const {
    throw ArchiveRefusal(member_ + "#/" + prefix_ + key, reason);
  }
  const json& field(const std::string& key) const {
    static const json null;
    auto it = record_.find(key);
    return it == record_.end() ? null : *it;
  }
  // A string of at most max_length bytes without control characters, or "" for null.
  std::string text(const std::string& key, std::size_t max_length = 256) const {
    const json& v = field(key);
    if (v.is_null()) return {};
    if (!v.is_string() || v.get_ref<const std::string&>().size() > max_length)
      refuse(key, "must be a string of at most " + std::to_string(max_length) + " bytes");
    if (auto reason = api::free_text_error(v.get_ref<const std::string&>())) refuse(key, *reason);
    return v.get<std::string>();
  }
  // A number from 0 to `max` (0 for null), as the job parser checks a job's.
  double number(const json& v, const std::string& key, double max = 1e15) const {
    if (v.is_null()) return 0.0;
    if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= max))
      refuse(key, "must be a number from 0 to " + api::number_text(max) + " or null");
    return v.get<double>();
  }
  // A whole number from 0 to 2^53 (0 for null): a count an int64 holds exactly.
  std::int64_t count(const json& v, const std::string& key) const {
    const double n = number(v, key, 9007199254740992.0);
    if (std::floor(n) != n) refuse(key, "must be a whole number");
    return static_cast<std::int64_t>(n);
  }
  // A time as this server writes them, "" for null unless `required`.
  std::string time(const std::string& key, bool required) const {
    const std::string t = text(key, 64);
    if (t.empty() ? required : !is_utc_iso8601(t))
      refuse(key, "must be a UTC time in ISO 8601, as 2024-05-01T12:00:00.123Z");
    return t;
  }
  // An object or null whose JSON text is at most `max_bytes` (provenance of other servers).
  const json& small_object(const std::string& key, std::size_t max_bytes) const {
    const json& v = field(key);
    if (!v.is_null() && (!v.is_object() || v.dump().size() > max_bytes))
      refuse(key, "must be an object of at most " + std::to_string(max_bytes) + " bytes or null");
    return v;
  }

private:
  const json& record_;
  std::string member_;
  std::string prefix_;
};

// Why a stored front ({x1, arrival_time, rupture_speed}: lists of numbers or null of one
// length) is not one, or nullopt (null is no front).
std::optional<std::string> front_error(const json& front) {
  if (front.is_null()) return std::nullopt;
  if (!front.is_object() || front.size() != 3)
    return "must be {\"x1\", \"arrival_time\", \"rupture_speed\"} or null";
  const json& x1 = front.value("x1", json());
  if (!x1.is_array()) return std::string("x1 must be a list");
  for (const char* key : {"x1", "arrival_time", "rupture_speed"}) {
    const json& list = front.value(key, json());
    if (!list.is_array() || list.size() != x1.size())
      return std::string(key) + " must be a list as long as x1";
    for (const json& v : list)
      if (!v.is_null() && !(v.is_number() && std::isfinite(v.get<double>())))
        return std::string(key) + " must hold numbers or null";
  }
  return std::nullopt;
}

// The run of one manifest entry, checked; nothing stored. Names this server does not keep
// (metrics of other versions) are left out and said in `warnings`.
RunToImport read_run(const json& entry, const std::map<std::string, std::string_view>& members,
                     const std::map<std::string, json>& listed, const json& origin,
                     std::vector<std::string>& warnings) {
  if (!entry.is_object() || !entry.value("id", json()).is_string() ||
      !entry.value("job", json()).is_string())
    throw ArchiveRefusal("manifest.json#/runs", "each run needs \"id\" and \"job\" (strings)");
  const std::string original_id = entry["id"].get<std::string>();
  if (!is_safe_member_name(original_id) || original_id.find('/') != std::string::npos)
    throw ArchiveRefusal("manifest.json#/runs", "run id " + api::describe_value(original_id) +
                                                    " is not a name of plain characters");
  const std::string name = entry["job"].get<std::string>();
  // Each run has its own members, used once: a member named by many runs would be stored
  // many times, and the bytes stored would no longer be bounded by the bytes uploaded.
  if (name != job_member(original_id))
    throw ArchiveRefusal("manifest.json#/runs",
                         "the job of run " + original_id + " must be its own member " +
                             job_member(original_id) + ", not " + api::describe_value(name));
  auto member = members.find(name);
  if (member == members.end())
    throw ArchiveRefusal(name, "the manifest names it but the archive does not hold it");
  auto parsed = api::parse_bounded_json(member->second);
  if (!parsed.ok() || !parsed.value.is_object())
    throw ArchiveRefusal(name, "not a JSON object: " + parsed.error.reason);
  const json& record = parsed.value;
  RecordReader in(record, name);
  if (in.text("id", 64) != original_id) in.refuse("id", "is not the manifest's " + original_id);

  RunToImport run;
  Job& job = run.job;
  const auto status = parse_status(in.text("status", 16));
  if (!status || !is_final(*status))
    in.refuse("status", "must be succeeded, failed or cancelled (only finished runs move)");
  job.status = *status;
  api::ValidationLimits limits;
  limits.max_memory_bytes = std::numeric_limits<double>::infinity(); // not run here
  auto spec = api::parse_job(in.field("spec"), limits);
  if (!spec.ok())
    in.refuse("spec" + spec.errors.front().pointer, "invalid spec: " + spec.errors.front().reason);
  job.spec = spec.spec->canonical;
  job.spec_sha256 = spec.spec->sha256;
  job.scene_hash = api::scene_hash(spec.spec->canonical);
  job.L = spec.spec->params.friction.L;
  job.n_d = spec.spec->params.geometry.nodes_per_meter;
  job.memory_estimate_bytes = spec.spec->memory_estimate_bytes;
  job.name = in.text("name");
  json kept = {{"tags", in.field("tags").is_null() ? json::array() : in.field("tags")},
               {"note", in.field("note").is_null() ? json("") : in.field("note")}};
  auto annotations = api::parse_annotations(kept);
  if (!annotations.ok())
    in.refuse(annotations.errors.front().pointer.substr(1), annotations.errors.front().reason);
  job.tags = annotations.annotations.tags.replace.value_or(std::vector<std::string>());
  job.note = annotations.annotations.note.value_or("");
  job.created_at = in.time("created_at", true);
  job.started_at = in.time("started_at", false);
  job.finished_at = in.time("finished_at", false);
  job.error = in.text("error", 4096);
  job.code_version = in.text("code_version");
  job.host = in.text("host");
  job.wall_time_s = in.number(in.field("wall_time_s"), "wall_time_s");
  const json& progress = in.field("progress");
  if (!progress.is_null() && !progress.is_object()) in.refuse("progress", "must be an object");
  if (progress.is_object()) {
    job.progress.fraction = in.number(progress.value("fraction", json()), "progress/fraction", 1.0);
    job.progress.time = in.number(progress.value("time", json()), "progress/time");
    job.progress.duration = in.number(progress.value("duration", json()), "progress/duration");
    job.progress.steps = in.count(progress.value("steps", json()), "progress/steps");
  }
  // Only the metrics this server writes, each of its kind (docs/metrics.md): other names are
  // left out with a warning, so that no archive adds columns to every run table.
  json metrics = in.field("metrics");
  if (!metrics.is_null()) {
    if (!metrics.is_object()) in.refuse("metrics", "must be an object or null");
    auto read = api::read_metrics(metrics);
    if (!read.errors.empty())
      in.refuse("metrics" + read.errors.front().pointer, read.errors.front().reason);
    if (!read.dropped.empty()) {
      std::string names;
      for (std::size_t i = 0; i < read.dropped.size() && i < 3; ++i)
        names += (i ? ", " : "") + api::describe_value(read.dropped[i]);
      warnings.push_back(name + "#/metrics: " + std::to_string(read.dropped.size()) +
                         " name(s) this server does not write were left out (" + names +
                         (read.dropped.size() > 3 ? ", ..." : "") + "; docs/metrics.md)");
    }
    metrics = std::move(read.metrics);
  }
  const json& front = in.field("front");
  if (auto why = front_error(front)) in.refuse("front", *why);
  job.imported_from = {{"server", origin.value("server", json())},
                       {"id", original_id},
                       {"submitted_by", in.text("submitted_by")},
                       {"exported_at", origin.value("exported_at", json())}};
  if (const json& earlier = in.small_object("imported_from", 16 * 1024); !earlier.is_null())
    job.imported_from["imported_from"] = earlier;

  const json& result_name = entry.value("result", json());
  if (job.status == JobStatus::succeeded) {
    if (!result_name.is_string())
      throw ArchiveRefusal("manifest.json#/runs",
                           "run " + original_id + " succeeded but has no \"result\" member");
    const std::string result = result_name.get<std::string>();
    if (result != result_member(original_id))
      throw ArchiveRefusal("manifest.json#/runs",
                           "the result of run " + original_id + " must be its own member " +
                               result_member(original_id) + " (one member holds one run's " +
                               "result), not " + api::describe_value(result));
    auto file = members.find(result);
    auto listing = listed.find(result);
    if (file == members.end() || listing == listed.end())
      throw ArchiveRefusal(result, "the manifest names it but the archive does not hold it");
    const json& stated = in.field("result");
    if (!stated.is_object() || stated.value("sha256", json()) != listing->second["sha256"])
      in.refuse("result/sha256", "is not the SHA-256 of " + result + " in the manifest");
    run.result = file->second;
    run.member = result;
    job.result.size = file->second.size();
    job.result.sha256 = listing->second["sha256"].get<std::string>();
  } else if (!result_name.is_null()) {
    throw ArchiveRefusal("manifest.json#/runs",
                         "run " + original_id + " did not succeed but names a result file");
  }
  job.id = original_id;
  run.record.status = job.status;
  run.record.metrics = std::move(metrics);
  run.record.front = front;
  run.record.wall_time_s = job.wall_time_s;
  run.record.finished_at = job.finished_at;
  run.record.error = job.error;
  return run;
}

// The study of a study's archive (study.json), checked as a run's job.json is: its request
// must parse as this server reads studies, its texts and numbers in range, its runs runs of
// the archive. Nothing stored.
StudyToImport read_study(const std::map<std::string, std::string_view>& members,
                         const std::set<std::string>& run_ids) {
  auto member = members.find(study_member);
  if (member == members.end())
    throw ArchiveRefusal(study_member, "the manifest names it but the archive does not hold it");
  auto parsed = api::parse_bounded_json(member->second);
  if (!parsed.ok() || !parsed.value.is_object())
    throw ArchiveRefusal(study_member, "not a JSON object: " + parsed.error.reason);
  const json& doc = parsed.value;
  RecordReader in(doc, study_member);
  StudyToImport out;
  StudyRecord& s = out.study;
  s.id = in.text("id", 64);
  if (!is_valid_job_id(s.id)) in.refuse("id", "must be a study id (32 lower-case hex characters)");
  s.name = in.text("name");
  json kept = {{"tags", in.field("tags").is_null() ? json::array() : in.field("tags")},
               {"note", in.field("note").is_null() ? json("") : in.field("note")}};
  auto annotations = api::parse_annotations(kept);
  if (!annotations.ok())
    in.refuse(annotations.errors.front().pointer.substr(1), annotations.errors.front().reason);
  s.tags = annotations.annotations.tags.replace.value_or(std::vector<std::string>());
  s.note = annotations.annotations.note.value_or("");
  s.kind = in.text("kind", 32);
  if (s.kind != "grid" && s.kind != "convergence" && s.kind != "failure_regimes" &&
      s.kind != "accuracy")
    in.refuse("kind", "must be grid, convergence, failure_regimes or accuracy");
  const auto status = api::parse_study_status(in.text("status", 16));
  if (!status || *status == api::StudyStatus::running)
    in.refuse("status", "must be finished or cancelled (only a study that is over moves)");
  s.status = *status;
  s.request = in.field("request");
  if (auto request = parse_study_request(s.request); !request.request)
    in.refuse("request" + (request.errors.empty() ? "" : request.errors.front().pointer),
              "is not a study request this server reads: " +
                  (request.errors.empty() ? std::string() : request.errors.front().reason));
  s.base = in.field("base");
  if (!s.base.is_object()) in.refuse("base", "must be an object (the study's base job)");
  s.scene_hash = in.text("scene_hash", 64);
  s.created_at = in.time("created_at", true);
  s.updated_at = in.time("updated_at", false);
  s.finished_at = in.time("finished_at", false);
  s.runs_done = static_cast<int>(in.count(in.field("runs_done"), "runs_done"));
  s.runs_total = static_cast<int>(in.count(in.field("runs_total"), "runs_total"));
  if (s.runs_done > 100000 || s.runs_total > 100000)
    in.refuse("runs_total", "must be at most 100000");
  auto length = [&](const char* key) {
    const json& v = in.field(key);
    if (v.is_null()) return api::not_available;
    return in.number(v, key, 1e6);
  };
  s.L_c = length("L_c");
  s.spectral_critical_length = length("spectral_critical_length");
  s.result = in.field("result");
  if (!s.result.is_null() && !s.result.is_object())
    in.refuse("result", "must be an object (the stored analysis) or null");
  const json& runs = in.field("runs");
  if (!runs.is_array() || runs.size() > run_ids.size())
    in.refuse("runs", "must be a list of the study's runs, each a run of the archive");
  std::set<std::string> listed;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const json& r = runs[i];
    const std::string at = "runs/" + std::to_string(i);
    if (!r.is_object()) in.refuse(at, "must be an object");
    RecordReader row(r, study_member, at + "/");
    StudyRunRow run;
    run.job_id = row.text("job_id", 64);
    if (!run_ids.contains(run.job_id)) row.refuse("job_id", "is not a run of the archive");
    if (!listed.insert(run.job_id).second) row.refuse("job_id", "is listed twice");
    run.regime = row.text("regime", 32);
    run.L = row.number(row.field("L"), "L", 1e6);
    run.n_d = row.number(row.field("n_d"), "n_d", 1e9);
    run.convergence_status = row.text("convergence_status", 32);
    if (run.convergence_status.empty()) run.convergence_status = "pending";
    auto optional = [&](const char* key) {
      const json& v = row.field(key);
      if (v.is_null()) return api::not_available;
      if (!v.is_number() || !std::isfinite(v.get<double>()))
        row.refuse(key, "must be a number or null");
      return v.get<double>();
    };
    run.partner_n_d = optional("partner_n_d");
    run.propagation_distance_change = optional("propagation_distance_change");
    run.arrival_time_change = optional("arrival_time_change");
    run.reason = row.text("reason", 4096);
    out.runs.push_back(std::move(run));
  }
  return out;
}

// Every member but the manifest is listed in it, every listed file is there with its size and
// SHA-256. Returns the listing by name.
std::map<std::string, json> check_files(const json& manifest,
                                        const std::map<std::string, std::string_view>& members) {
  const json& files = manifest.value("files", json());
  if (!files.is_array() || files.size() > 2 * max_archive_runs)
    throw ArchiveRefusal("manifest.json#/files", "must be an array of at most " +
                                                     std::to_string(2 * max_archive_runs) +
                                                     " files");
  std::map<std::string, json> listed;
  for (const json& f : files) {
    if (!f.is_object() || !f.value("name", json()).is_string() ||
        !f.value("sha256", json()).is_string() || !f.value("size", json()).is_number_unsigned())
      throw ArchiveRefusal("manifest.json#/files",
                           "each file needs \"name\", \"size\" and \"sha256\"");
    if (!listed.emplace(f["name"].get<std::string>(), f).second)
      throw ArchiveRefusal("manifest.json#/files",
                           api::describe_value(f["name"]) + " is listed twice");
  }
  for (const auto& [name, content] : members)
    if (name != "manifest.json" && !listed.contains(name))
      throw ArchiveRefusal(name, "not listed in manifest.json: the archive was altered");
  for (const auto& [name, f] : listed) {
    auto member = members.find(name);
    if (member == members.end())
      throw ArchiveRefusal(name, "listed in manifest.json but not in the archive");
    if (member->second.size() != f["size"].get<std::uint64_t>())
      throw ArchiveRefusal(name, std::to_string(member->second.size()) +
                                     " bytes, the manifest says " + f["size"].dump() +
                                     ": the archive was altered or damaged");
    if (api::sha256_hex(member->second) != f["sha256"].get<std::string>())
      throw ArchiveRefusal(name, "its SHA-256 is not the manifest's: the archive was altered "
                                 "or damaged");
  }
  return listed;
}

} // namespace

ImportResult import_run_archive(std::string_view archive, JobService& service,
                                const std::string& user, bool again) {
  std::vector<TarMember> members;
  try {
    members = read_tar(archive, {2 * max_archive_runs + 1});
  } catch (const TarError& e) {
    throw ArchiveRefusal("", e.what());
  }
  std::map<std::string, std::string_view> by_name;
  for (const auto& m : members)
    by_name[m.name] = m.content;
  auto manifest_member = by_name.find("manifest.json");
  if (manifest_member == by_name.end())
    throw ArchiveRefusal("manifest.json", "the archive has no manifest.json");
  auto parsed = api::parse_bounded_json(manifest_member->second);
  if (!parsed.ok() || !parsed.value.is_object())
    throw ArchiveRefusal("manifest.json", "not a JSON object: " + parsed.error.reason);
  const json& manifest = parsed.value;
  if (manifest.value("format", json()) != archive_format ||
      manifest.value("version", json()) != archive_version)
    throw ArchiveRefusal("manifest.json#/format", std::string("not a run archive (format \"") +
                                                      archive_format + "\", version " +
                                                      std::to_string(archive_version) + ")");
  const auto listed = check_files(manifest, by_name);
  const json& runs = manifest.value("runs", json());
  if (!runs.is_array() || runs.empty() || runs.size() > max_archive_runs)
    throw ArchiveRefusal("manifest.json#/runs",
                         "must be an array of 1 to " + std::to_string(max_archive_runs) + " runs");
  // What the manifest says of the exporting server, kept with each run.
  if (const json& at = manifest.value("exported_at", json());
      !at.is_string() || !is_utc_iso8601(at.get<std::string>()))
    throw ArchiveRefusal("manifest.json#/exported_at",
                         "must be a UTC time in ISO 8601, as 2024-05-01T12:00:00.123Z");
  if (const json& server = manifest.value("server", json());
      !server.is_object() || server.dump().size() > 1024)
    throw ArchiveRefusal("manifest.json#/server", "must be an object of at most 1024 bytes");
  std::vector<RunToImport> pending;
  std::vector<std::string> warnings;
  std::set<std::string> ids;
  for (const json& entry : runs) {
    pending.push_back(read_run(entry, by_name, listed, manifest, warnings));
    if (!ids.insert(pending.back().job.id).second)
      throw ArchiveRefusal("manifest.json#/runs", "run " + pending.back().job.id + " given twice");
  }
  // A study's archive names its study.json in the manifest.
  std::optional<StudyToImport> study;
  if (const json& named = manifest.value("study", json()); !named.is_null()) {
    if (named != study_member)
      throw ArchiveRefusal("manifest.json#/study",
                           std::string("must be \"") + study_member + "\" (or absent: no study)");
    study = read_study(by_name, ids);
  }
  // Everything checked: store, all runs or none (with the study, if any).
  ImportResult result = service.import_runs(std::move(pending), user, again, std::move(study));
  result.warnings = std::move(warnings);
  return result;
}

} // namespace slipfront::server
