// Finding the job of a request path and its result file, for the handlers that answer from a
// finished job (result_handlers.cpp, station_handlers.cpp): the errors they share (404 unknown
// job or no result, 409 not finished, 410 file gone or damaged).
#pragma once

#include "server/http/router.hpp"
#include "server/http/server_context.hpp"

#include <string>
#include <variant>

namespace slipfront::server {

// The job of the path, or the response to send instead (404 for malformed or unknown ids:
// a malformed id never reaches the store or the file system).
std::variant<Job, Response> find_job(ServerContext& ctx, RequestContext& rc);

// 409: the job has not finished, so it has no `what` yet.
Response not_finished(const Request& req, const Job& job, const std::string& what);

// A finished job's result file, open and verified (ResultFiles).
struct ResultOnDisk {
  Job job;
  OpenedResult file;
  std::string path; // absolute, for HDF5: the stored path is relative to the data dir
};

// The result file of the path's job, or the response to send instead: 404 (unknown job, or
// a job that ended without a result file), 409 (not finished yet), 410 (file deleted,
// damaged or not a regular file). Verifying may hash the file: only on the blocking pool.
std::variant<ResultOnDisk, Response> find_result(ServerContext& ctx, RequestContext& rc);

// 410 for a result file that is intact (its size and SHA-256 are the stored ones) but cannot
// be read as a result (`why`: the HDF5 reader's words, the path already removed): a file
// imported before imports checked the layout, or written by a broken build. Never a 500.
Response result_unreadable(const Request& req, const Job& job, const std::string& what,
                           const std::string& why);

// `text` (an error from the HDF5 reader) without the server's path of the file.
std::string without_path(std::string text, const std::string& path, const Job& job);

} // namespace slipfront::server
