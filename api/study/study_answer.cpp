#include "api/study/study_answer.hpp"

#include "api/number_text.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace slipfront::api {

namespace {

using nlohmann::json;

std::string text(double value) {
  return number_text(value, 3);
}

std::string percent(double fraction) {
  return number_text(100 * fraction, 3) + " %";
}

double number_at(const json& j, const char* key) {
  const auto found = j.find(key);
  return found != j.end() && found->is_number() ? found->get<double>() : std::nan("");
}

// The smallest of `values` above `L`, NaN if none.
double next_above(const json& values, double L) {
  double next = std::nan("");
  if (!values.is_array()) return next;
  for (const json& v : values)
    if (v.is_number() && v.get<double>() > L * (1 + 1e-9) && !(v.get<double>() >= next))
      next = v.get<double>();
  return next;
}

// "L = 8e-07, 4e-07 (n_d 80, 80)": the mesh-converged L of the rule, with their meshes.
std::string references_text(const json& critical) {
  const json& refs = critical.value("references", json::array());
  if (!refs.is_array() || refs.empty()) return "no mesh-converged L";
  std::string Ls, meshes;
  for (const json& r : refs) {
    Ls += (Ls.empty() ? "" : ", ") + text(number_at(r, "L"));
    meshes += (meshes.empty() ? "" : ", ") + text(number_at(r, "n_d"));
  }
  return std::to_string(refs.size()) + " mesh-converged L (" + Ls + " m; reference n_d " + meshes +
         ")";
}

std::string tolerances_text(const json& critical) {
  const json& tol = critical.value("tolerances", json::object());
  const double d = number_at(tol, "propagation_distance"), t = number_at(tol, "arrival_time");
  return "propagation distance within " + percent(std::isnan(d) ? 0.005 : d) +
         " and arrival time at the probe within " + percent(std::isnan(t) ? 0.001 : t);
}

struct Answer {
  std::string state, verdict, meaning, certainty;
};

const char* found_meaning =
    "below L_c the regularisation no longer changes the rupture: the mesh-converged answers of "
    "L_c and every smaller L agree, as the event would run under plain Coulomb friction (paper "
    "§4–5), while a larger L changes it";

// A convergence or grid study: the critical-length rule over its L (docs/metrics.md).
Answer rule_answer(const json& critical, std::size_t runs) {
  Answer a;
  const double L_c = number_at(critical, "L_c");
  const double next = number_at(critical, "next_larger_L");
  const std::string rule = "the critical-length rule (docs/metrics.md \"Critical length\": " +
                           tolerances_text(critical) + ", between mesh-converged L) over " +
                           references_text(critical) + ", from " + std::to_string(runs) + " runs";
  if (!std::isnan(L_c) && !std::isnan(next)) {
    a.state = "found";
    a.verdict = "L_c = " + text(L_c) + " m, in [" + text(L_c) + ", " + text(next) + ") m";
    a.meaning =
        std::string(found_meaning) + "; the next larger L of the study, " + text(next) + " m, does";
  } else if (!std::isnan(L_c)) {
    a.state = "at_least";
    a.verdict = "L_c ≥ " + text(L_c) + " m";
    a.meaning = "every L of the study gives the same mesh-converged rupture: L_c is at least the "
                "largest of them; add larger L to bound it";
  } else if (!std::isnan(next)) {
    const double smallest = next;
    a.state = "none";
    a.verdict = "no L meets the rule: L_c < " + text(smallest) + " m, if it exists";
    a.meaning = "even the smallest mesh-converged L still change the rupture from one to the "
                "next: the critical length, if this event has one, lies below them; add smaller "
                "L (or compare with plain Coulomb friction)";
  } else {
    a.state = "undetermined";
    a.verdict = "L_c undetermined";
    a.meaning = "the rule needs at least two mesh-converged L: add L values or refine meshes";
  }
  a.certainty = rule;
  return a;
}

// An L search (docs/studies-api.md "L search").
Answer search_answer(const json& search, std::size_t runs, const std::string& companion) {
  Answer a;
  const std::string state = search.value("state", std::string());
  const double L_c = number_at(search, "L_c");
  const double next = next_above(search.value("searched_L", json::array()), L_c);
  const std::string how = "the L search's rule (docs/studies-api.md \"L search\": the " +
                          std::to_string(search.value("confirm", 2)) +
                          " smallest mesh-converged L agree pairwise within the paper's mesh "
                          "tolerances, 0.5 % on the propagation distance and 0.1 % on the "
                          "arrival time, and the next larger L does not), L divided by " +
                          text(number_at(search, "factor")) + " each step, from " +
                          std::to_string(runs) +
                          " runs; the search says: " + search.value("reason", std::string());
  a.certainty = how;
  if ((state == "found" || state == "meets_coulomb") && !std::isnan(L_c)) {
    a.state = "found";
    a.verdict = "L_c = " + text(L_c) + " m" +
                (std::isnan(next) ? "" : ", in [" + text(L_c) + ", " + text(next) + ") m");
    a.meaning = state == "found"
                    ? std::string(found_meaning)
                    : "from L_c down the rupture is that of " + companion +
                          " (paper §5: below L_c the event is that of the law without its "
                          "regularisation)";
  } else if (state == "all_agree" && !std::isnan(L_c)) {
    a.state = "at_least";
    a.verdict = "L_c ≥ " + text(L_c) + " m";
    a.meaning = "every L searched gives the same mesh-converged rupture: start the search at a "
                "larger L to bound it";
  } else if (state == "floor" || state == "mesh_cap") {
    a.state = "none";
    a.verdict = state == "floor" ? "no L_c above the search's floor"
                                 : "L_c not found: the meshes reached the study's cap";
    a.meaning = state == "floor"
                    ? "down to the floor the smallest mesh-converged L still differ: L_c, if this "
                      "event has one, is below it"
                    : "the smallest L tried do not converge on the meshes allowed, so smaller L "
                      "cannot be judged; raise the cap or use the spectral BI method";
  } else {
    a.state = "running";
    a.verdict = "L_c not known yet";
    a.meaning = "the search is still refining or adding L";
  }
  return a;
}

// An accuracy study (docs/studies-api.md "Accuracy target").
Answer accuracy_answer(const json& accuracy, const json& request) {
  Answer a;
  const double value = number_at(accuracy, "value"), error = number_at(accuracy, "error");
  const json target = request.value("accuracy", json::object());
  const std::string metric = target.value("metric", std::string("the metric"));
  a.state = accuracy.value("state", std::string());
  a.verdict = std::isnan(value) ? metric + " not known yet"
                                : metric + " = " + text(value) + " ± " + text(error) + " (" +
                                      percent(number_at(accuracy, "relative_error")) + ")";
  a.meaning = "the value of the finest mesh run, with the error the refinement estimates; "
              "state: " +
              a.state;
  a.certainty = accuracy.value("reason", std::string());
  return a;
}

} // namespace

json study_answer(const json& study, bool paper_scene) {
  const std::size_t runs = study.value("runs", json::array()).size();
  const json& critical = study.value("critical_length", json::object());
  Answer a;
  if (study.contains("accuracy") && study["accuracy"].is_object())
    a = accuracy_answer(study["accuracy"], study.value("request", json::object()));
  else if (study.contains("search") && study["search"].is_object())
    a = search_answer(study["search"], runs,
                      study.value("companion_label", std::string("plain Coulomb")));
  else
    a = rule_answer(critical.is_object() ? critical : json::object(), runs);
  const json progress = study.value("progress", json::object());
  if (study.value("status", std::string()) == "running")
    a.verdict = "so far (" + std::to_string(progress.value("done", 0)) + " of " +
                std::to_string(progress.value("total", 0)) + " runs final): " + a.verdict;

  json others = json::array();
  const double spectral = number_at(study, "spectral_critical_length");
  if (!std::isnan(spectral))
    others.push_back(
        {{"label", "spectral estimate: an order of magnitude of L_c from the paper's filter law "
                   "(eq. 6) at the frequencies of the smallest mesh-converged L (L = " +
                       text(number_at(critical, "spectral_from_L")) +
                       " m), not the rule's answer (docs/metrics.md \"Spectral estimate\")"},
         {"value", spectral},
         {"unit", "m"}});
  // An L search also has the study-wide rule over every L it ran (each L against every smaller).
  const double rule_L_c = number_at(critical, "L_c");
  if (study.contains("search") && !std::isnan(rule_L_c))
    others.push_back({{"label", "the study-wide critical-length rule over every L run (each "
                                "against every smaller L)"},
                      {"value", rule_L_c},
                      {"unit", "m"}});
  if (paper_scene)
    others.push_back({{"label", "the paper's value (Kammer et al. 2014 §3.2, read from its Fig. "
                                "4, FE up to n_d = 120, five L from 1e-3 to 5e-6 m)"},
                      {"value", paper_critical_length},
                      {"unit", "m"}});
  return {{"state", a.state},
          {"verdict", a.verdict},
          {"meaning", a.meaning},
          {"certainty", a.certainty},
          {"others", others}};
}

} // namespace slipfront::api
