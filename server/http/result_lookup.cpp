// Finding the job of a request path and its result file (result_lookup.hpp).
#include "server/http/result_lookup.hpp"

#include "server/core/job_id.hpp"
#include "server/core/log.hpp"
#include "server/http/responses.hpp"

#include <stdexcept>

namespace slipfront::server {

namespace {

// The answer for a result file that cannot be served as the database describes it. Its words
// never hold the server's paths (the log has the full story).
Response result_gone(const Request& req, const Job& job, const OpenedResult& file) {
  using State = OpenedResult::State;
  std::string why;
  switch (file.state) {
  case State::missing:
    why = "is no longer on the server (deleted from its data dir)";
    break;
  case State::not_regular:
    why = "is not a regular file on the server";
    break;
  case State::damaged:
    why = "is " + file.reason;
    break;
  case State::unreadable:
    why = "cannot be read on the server (" + file.reason + ")";
    break;
  case State::intact:
    throw std::logic_error("result_gone for an intact file");
  }
  log_error("job " + job.id + ": result file " + job.result.path + " " + why + "; answered 410");
  return problem_response(req, http::status::gone,
                          "the result file of job " + job.id + " " + why +
                              "; submit the job again with fresh=true to recompute it");
}

} // namespace

std::variant<Job, Response> find_job(ServerContext& ctx, RequestContext& rc) {
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return Response(problem_response(rc.request, http::status::not_found, "no job with id " + id));
  auto job = ctx.service.get(id);
  if (!job)
    return Response(problem_response(rc.request, http::status::not_found, "no job with id " + id));
  return *job;
}

Response not_finished(const Request& req, const Job& job, const std::string& what) {
  return problem_response(req, http::status::conflict,
                          "job " + job.id + " is " + to_string(job.status) + "; no " + what +
                              " yet");
}

std::variant<ResultOnDisk, Response> find_result(ServerContext& ctx, RequestContext& rc) {
  auto found = find_job(ctx, rc);
  if (auto* r = std::get_if<Response>(&found)) return std::move(*r);
  Job& job = std::get<Job>(found);
  const auto& req = rc.request;
  if (!is_final(job.status)) return not_finished(req, job, "result file");
  if (job.status != JobStatus::succeeded || job.result.path.empty())
    return problem_response(req, http::status::not_found,
                            "job " + job.id + " has no result file (" + to_string(job.status) +
                                (job.error.empty() ? "" : ": " + job.error) + ")");
  auto& files = ctx.service.result_files();
  auto file = files.open(job.result);
  if (file.state != OpenedResult::State::intact) return result_gone(req, job, file);
  std::string path = files.absolute_path(job.result);
  return ResultOnDisk{std::move(job), std::move(file), std::move(path)};
}

Response result_unreadable(const Request& req, const Job& job, const std::string& what,
                           const std::string& why) {
  log_error(what + " of job " + job.id + ": " + why + "; answered 410");
  return problem_response(req, http::status::gone,
                          "the result file of job " + job.id +
                              " is damaged: it cannot be read as a result file (" + why +
                              "); submit the job again with fresh=true to recompute it");
}

std::string without_path(std::string text, const std::string& path, const Job& job) {
  const std::string name = job.id + ".h5";
  for (auto at = text.find(path); at != std::string::npos; at = text.find(path, at + name.size()))
    text.replace(at, path.size(), name);
  return text;
}

} // namespace slipfront::server
