#include "server/core/study_request.hpp"

#include "api/free_text.hpp"
#include "api/friction_fields.hpp"
#include "api/job_methods.hpp"
#include "api/number_text.hpp"
#include "server/core/priority.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace slipfront::server {

using nlohmann::json;

const char* to_string(StudyKind kind) {
  switch (kind) {
  case StudyKind::grid:
    return "grid";
  case StudyKind::convergence:
    return "convergence";
  case StudyKind::failure_regimes:
    return "failure_regimes";
  case StudyKind::accuracy:
    return "accuracy";
  }
  return "grid";
}

std::optional<StudyKind> parse_study_kind(const std::string& text) {
  for (auto k :
       {StudyKind::grid, StudyKind::convergence, StudyKind::failure_regimes, StudyKind::accuracy})
    if (text == to_string(k)) return k;
  return std::nullopt;
}

namespace {

// The base's friction as a job reads it (a preset expanded, the defaults filled in); a base
// that does not validate gets the paper's (its errors are the study's to report).
Friction base_friction(const nlohmann::json& base) {
  const api::ParseResult parsed = api::parse_job(base);
  return parsed.spec ? parsed.spec->params.friction : Friction();
}

} // namespace

nlohmann::json coulomb_overrides(const nlohmann::json& base) {
  return {{"friction", api::unregularized_patch(base_friction(base))}};
}

std::string companion_label(const nlohmann::json& base) {
  return api::unregularized_label(base_friction(base));
}

const std::vector<double>& default_ladder() {
  static const std::vector<double> ladder = {10, 20, 40, 80, 160};
  return ladder;
}

namespace {

using Errors = std::vector<api::FieldError>;

// A non-empty array of distinct positive numbers; `whole` bounds the n_d values.
std::vector<double> positive_list(const json& parent, const std::string& key,
                                  const std::string& pointer, std::size_t max_size, Errors& errors,
                                  bool required = true) {
  std::vector<double> out;
  auto it = parent.find(key);
  if (it == parent.end()) {
    if (required) errors.push_back({pointer, "is required (an array of numbers > 0)"});
    return out;
  }
  if (!it->is_array() || it->empty()) {
    errors.push_back({pointer, "must be a non-empty array of numbers > 0"});
    return out;
  }
  if (it->size() > max_size) {
    errors.push_back({pointer, "at most " + std::to_string(max_size) + " values"});
    return out;
  }
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& v = (*it)[i];
    const std::string at = pointer + "/" + std::to_string(i);
    if (!v.is_number()) {
      errors.push_back({at, "must be a number"});
    } else if (!(v.get<double>() > 0.0) || !std::isfinite(v.get<double>())) {
      errors.push_back({at, "must be > 0"});
    } else if (std::find(out.begin(), out.end(), v.get<double>()) != out.end()) {
      errors.push_back({at, "duplicate value"});
    } else {
      out.push_back(v.get<double>());
    }
  }
  return out;
}

void reject_unknown(const json& object, const std::string& pointer,
                    const std::set<std::string>& known, Errors& errors) {
  for (const auto& [key, value] : object.items())
    if (!known.count(key)) errors.push_back({pointer + "/" + key, "unknown field"});
}

void parse_base(const json& body, StudyRequest& r, Errors& errors) {
  auto it = body.find("base");
  if (it == body.end()) return; // the paper's scene
  if (!it->is_object()) {
    errors.push_back({"/base", "must be a job spec (JSON object)"});
    return;
  }
  r.base = *it;
  if (r.base.contains("friction") && r.base["friction"].is_object() &&
      r.base["friction"].contains("L"))
    errors.push_back({"/base/friction/L", "is set by the study (its L values): remove it"});
  if (r.base.contains("geometry") && r.base["geometry"].is_object() &&
      r.base["geometry"].contains("nodes_per_meter"))
    errors.push_back(
        {"/base/geometry/nodes_per_meter", "is set by the study (its n_d values): remove it"});
  for (const char* key : {"fresh", "priority"})
    if (r.base.contains(key))
      errors.push_back({std::string("/base/") + key, "belongs at the top level of the study"});
}

void parse_grid(const json& grid, StudyRequest& r, Errors& errors) {
  if (!grid.is_object()) {
    errors.push_back({"/grid", "must be an object {\"L\": [...], \"n_d\": [...]}"});
    return;
  }
  reject_unknown(grid, "/grid", {"L", "n_d"}, errors);
  r.L = positive_list(grid, "L", "/grid/L", max_study_L, errors);
  r.n_d = positive_list(grid, "n_d", "/grid/n_d", max_study_n_d, errors);
  if (r.L.size() * r.n_d.size() > max_study_runs)
    errors.push_back({"/grid", "at most " + std::to_string(max_study_runs) + " runs per study"});
}

// A number member of `object` within [low, high] (`what` says so in the error), or `fallback`.
double bounded_number(const json& object, const char* key, const std::string& pointer, double low,
                      double high, const std::string& what, double fallback, Errors& errors) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_number() || !(it->get<double>() >= low && it->get<double>() <= high)) {
    errors.push_back({pointer + "/" + key, "must be " + what});
    return fallback;
  }
  return it->get<double>();
}

// "search": {"from", "factor", "floor", "confirm"} (docs/studies-api.md "L search").
void parse_search(const json& s, StudyRequest& r, Errors& errors) {
  const std::string at = "/convergence/search";
  if (!s.is_object()) {
    errors.push_back({at, "must be an object {\"from\", \"factor\", \"floor\", \"confirm\"} "
                          "(each optional)"});
    return;
  }
  reject_unknown(s, at, {"from", "factor", "floor", "confirm", "coulomb"}, errors);
  api::LSearch search;
  search.from =
      bounded_number(s, "from", at, 1e-12, 1.0, "a number in [1e-12, 1] (m)", search.from, errors);
  search.factor =
      bounded_number(s, "factor", at, 1.1, 100.0, "a number in [1.1, 100]", search.factor, errors);
  search.floor = bounded_number(s, "floor", at, 1e-12, 1.0, "a number in [1e-12, 1] (m)",
                                search.from / 1000.0, errors);
  const double confirm =
      bounded_number(s, "confirm", at, 2.0, 5.0, "an integer in [2, 5]", 2.0, errors);
  if (confirm != std::floor(confirm))
    errors.push_back({at + "/confirm", "must be an integer in [2, 5]"});
  search.confirm = static_cast<int>(confirm);
  if (auto it = s.find("coulomb"); it != s.end()) {
    if (it->is_boolean())
      search.coulomb = it->get<bool>();
    else
      errors.push_back({at + "/coulomb", "must be a boolean (default: where Coulomb is "
                                         "well-posed)"});
  }
  if (!(search.floor < search.from))
    errors.push_back({at + "/floor", "must be below from (" + api::number_text(search.from) + ")"});
  r.search = search;
  r.L = api::search_ladder(search, max_study_L);
  if (errors.empty() && r.L.size() < search.confirm + 1u)
    errors.push_back({at, "from, factor and floor allow " + std::to_string(r.L.size()) +
                              " L values; the rule needs at least confirm + 1 = " +
                              std::to_string(search.confirm + 1)});
}

// "n_d" (a ladder, default default_ladder()) and "n_d_max" (default its last mesh) of the
// object at `at`.
void parse_ladder(const json& c, const std::string& at, StudyRequest& r, Errors& errors) {
  r.n_d = c.contains("n_d") ? positive_list(c, "n_d", at + "/n_d", max_study_n_d, errors)
                            : default_ladder();
  if (!std::is_sorted(r.n_d.begin(), r.n_d.end()))
    errors.push_back({at + "/n_d", "the ladder must increase"});
  if (c.contains("n_d") && r.n_d.size() < 2)
    errors.push_back({at + "/n_d", "needs at least two meshes"});
  r.n_d_max = r.n_d.empty() ? 0.0 : r.n_d.back();
  if (auto it = c.find("n_d_max"); it != c.end()) {
    if (!it->is_number() || !(it->get<double>() > 0.0))
      errors.push_back({at + "/n_d_max", "must be a number > 0"});
    else
      r.n_d_max = it->get<double>();
  }
  if (r.n_d.size() >= 2 && r.n_d_max < r.n_d[1])
    errors.push_back({at + "/n_d_max", "must allow at least the first two meshes of the ladder"});
}

void parse_convergence(const json& c, StudyRequest& r, Errors& errors) {
  if (!c.is_object()) {
    errors.push_back({"/convergence", "must be an object {\"L\": [...], \"n_d\": [...], "
                                      "\"n_d_max\": ...}"});
    return;
  }
  reject_unknown(c, "/convergence", {"L", "n_d", "n_d_max", "search"}, errors);
  if (c.contains("L") == c.contains("search"))
    errors.push_back({"/convergence", "give exactly one of \"L\" (the L values) or \"search\" "
                                      "(an L search: docs/studies-api.md)"});
  else if (c.contains("L"))
    r.L = positive_list(c, "L", "/convergence/L", max_study_L, errors);
  else
    parse_search(c["search"], r, errors);
  parse_ladder(c, "/convergence", r, errors);
  if (r.L.size() * r.n_d.size() > max_study_runs)
    errors.push_back(
        {"/convergence", "at most " + std::to_string(max_study_runs) + " runs per study"});
}

// "accuracy": {"metric", "tolerance", "L", "method", "n_d", "n_d_max"} (docs/studies-api.md
// "Accuracy target").
void parse_accuracy(const json& a, StudyRequest& r, Errors& errors) {
  const std::string at = "/accuracy";
  if (!a.is_object()) {
    errors.push_back({at, "must be an object {\"metric\", \"tolerance\", \"L\", \"method\", "
                          "\"n_d\", \"n_d_max\"}"});
    return;
  }
  reject_unknown(a, at, {"metric", "tolerance", "L", "method", "n_d", "n_d_max", "start"}, errors);
  api::AccuracyTarget target;
  const auto& known = api::accuracy_metrics();
  std::string names;
  for (const auto& name : known)
    names += (names.empty() ? "" : ", ") + name;
  const auto metric = a.find("metric");
  if (metric == a.end())
    errors.push_back({at + "/metric", "is required (one of " + names + ")"});
  else if (!metric->is_string() ||
           std::find(known.begin(), known.end(), metric->get<std::string>()) == known.end())
    errors.push_back({at + "/metric", "must be one of " + names});
  else
    target.metric = metric->get<std::string>();
  if (!a.contains("tolerance"))
    errors.push_back({at + "/tolerance", "is required (the relative error allowed, e.g. 0.005)"});
  target.tolerance =
      bounded_number(a, "tolerance", at, 1e-6, 0.5,
                     "a relative error in [1e-6, 0.5] (0.005 is 0.5 %)", 0.0, errors);
  target.L = bounded_number(a, "L", at, 1e-12, 1.0, "a number in [1e-12, 1] (m)", 5e-5, errors);
  if (auto it = a.find("method"); it != a.end()) {
    if (!it->is_string() || (*it != "auto" && find_method(it->get<std::string>()) == nullptr)) {
      std::vector<std::string> choices = {"\"auto\""};
      for (const std::string& name : api::method_names())
        choices.push_back("\"" + name + "\"");
      errors.push_back({at + "/method", "must be " + api::or_list(choices)});
    } else {
      r.method_choice = it->get<std::string>();
    }
  }
  if (r.method_choice != "auto" && r.base.contains("method") && r.base["method"] != r.method_choice)
    errors.push_back({at + "/method", "differs from /base/method: give the method once"});
  parse_ladder(a, at, r, errors);
  if (auto it = a.find("start"); it != a.end()) {
    const json* n_d = it->is_object() && it->contains("n_d") ? &(*it)["n_d"] : nullptr;
    const auto rung = n_d && n_d->is_number()
                          ? std::find(r.n_d.begin(), r.n_d.end(), n_d->get<double>())
                          : r.n_d.end();
    if (rung == r.n_d.end() || rung + 1 == r.n_d.end() || *(rung + 1) > r.n_d_max)
      errors.push_back({at + "/start/n_d", "must be a mesh of the ladder with a finer one at or "
                                           "below n_d_max"});
    else
      r.accuracy_start = static_cast<std::size_t>(rung - r.n_d.begin());
    if (it->is_object()) {
      reject_unknown(*it, at + "/start", {"n_d", "reason"}, errors);
      const auto reason = it->find("reason");
      if (reason != it->end() && (!reason->is_string() || reason->get<std::string>().size() > 1000))
        errors.push_back({at + "/start/reason", "must be a string of at most 1000 characters"});
    }
  }
  r.L = {target.L};
  r.accuracy = target;
}

// Each run carries /base/tags, the study's tags and "study:<id>" (run_document), and a job
// has at most 32 tags (api/job_reader.cpp): the study's and the base's share 31.
void check_tag_count(const StudyRequest& r, Errors& errors) {
  constexpr std::size_t max_job_tags = 32;
  const std::size_t base_tags = base_tag_count(r);
  if (r.tags.size() + base_tags <= max_job_tags - 1) return;
  errors.push_back(
      {"/tags", "has " + std::to_string(r.tags.size()) + " tags" +
                    (base_tags ? ", and " + std::to_string(base_tags) + " in /base/tags" : "") +
                    ": at most " + std::to_string(max_job_tags - 1) +
                    " tags are allowed (together with /base/tags; each run also "
                    "gets the tag study:<id>, and a job has at most " +
                    std::to_string(max_job_tags) + ")"});
}

} // namespace

StudyRequestParse parse_study_request(const json& body) {
  StudyRequestParse out;
  Errors& errors = out.errors;
  if (!body.is_object()) {
    errors.push_back({"", "the study must be a JSON object"});
    return out;
  }
  StudyRequest r;
  r.body = body;
  reject_unknown(
      body, "",
      {"name", "tags", "base", "grid", "convergence", "preset", "accuracy", "priority", "fresh"},
      errors);
  if (auto it = body.find("name"); it != body.end()) {
    if (!it->is_string() || it->get<std::string>().size() > 200)
      errors.push_back({"/name", "must be a string of at most 200 characters"});
    else if (auto reason = api::free_text_error(it->get<std::string>()))
      errors.push_back({"/name", std::move(*reason)});
    else
      r.name = it->get<std::string>();
  }
  if (auto it = body.find("tags"); it != body.end()) {
    if (!it->is_array()) {
      errors.push_back({"/tags", "must be an array of strings"});
    } else {
      for (std::size_t i = 0; i < it->size(); ++i) {
        const std::string at = "/tags/" + std::to_string(i);
        if (!(*it)[i].is_string())
          errors.push_back({at, "must be a string"});
        else if (auto reason = api::free_text_error((*it)[i].get<std::string>()))
          errors.push_back({at, std::move(*reason)});
        else
          r.tags.push_back((*it)[i].get<std::string>());
      }
    }
  }
  if (auto it = body.find("priority"); it != body.end()) {
    r.priority = priority_of(*it);
    if (!r.priority) errors.push_back({"/priority", priority_rule()});
  }
  if (auto it = body.find("fresh"); it != body.end()) {
    if (it->is_boolean())
      r.fresh = it->get<bool>();
    else
      errors.push_back({"/fresh", "must be a boolean"});
  }
  parse_base(body, r, errors);
  check_tag_count(r, errors);

  const bool grid = body.contains("grid"), convergence = body.contains("convergence"),
             preset = body.contains("preset"), accuracy = body.contains("accuracy");
  if (int(grid) + int(convergence) + int(preset) + int(accuracy) != 1) {
    errors.push_back(
        {"", "give exactly one of \"grid\", \"convergence\", \"preset\" or \"accuracy\""});
  } else if (accuracy) {
    r.kind = StudyKind::accuracy;
    parse_accuracy(body["accuracy"], r, errors);
  } else if (grid) {
    r.kind = StudyKind::grid;
    parse_grid(body["grid"], r, errors);
  } else if (convergence) {
    r.kind = StudyKind::convergence;
    parse_convergence(body["convergence"], r, errors);
    if (r.search) r.search->companion = companion_label(r.base);
  } else if (body["preset"] != "failure_regimes") {
    errors.push_back({"/preset", "unknown preset (known: \"failure_regimes\")"});
  } else {
    r.kind = StudyKind::failure_regimes;
  }
  if (errors.empty()) out.request = std::move(r);
  return out;
}

std::size_t base_tag_count(const StudyRequest& request) {
  const auto it = request.base.find("tags");
  return it != request.base.end() && it->is_array() ? it->size() : 0;
}

using api::number_text;

json run_document(const StudyRequest& request, const std::string& study_id, const json& overrides,
                  const std::string& regime, double L, double n_d) {
  json doc = request.base;
  doc.merge_patch(overrides);
  // An unregularised companion whose law takes no L (overrides with friction.L null: the
  // patch removed it) runs without one; every other run takes the study's L.
  const json* friction = overrides.contains("friction") ? &overrides["friction"] : nullptr;
  const bool takes_no_L = friction && friction->contains("L") && (*friction)["L"].is_null();
  if (!takes_no_L) doc["friction"]["L"] = L;
  doc["geometry"]["nodes_per_meter"] = n_d;
  if (!request.base.contains("name") || !request.base["name"].is_string()) {
    std::string name = request.name.empty() ? "study " + study_id.substr(0, 8) : request.name;
    if (!regime.empty()) name += " " + regime;
    doc["name"] = name + " L=" + number_text(L) + " n_d=" + number_text(n_d);
  }
  json tags = base_tag_count(request) ? request.base["tags"] : json::array();
  for (const auto& tag : request.tags)
    tags.push_back(tag);
  tags.push_back("study:" + study_id);
  doc["tags"] = tags;
  return doc;
}

} // namespace slipfront::server
