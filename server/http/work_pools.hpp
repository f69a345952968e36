// The thread pools that run the handlers that may block (Router's `Runs`, docs/server.md
// "Threads"), owned by ServerApp and shared by every session. Reads and writes wait in
// separate queues, so a submission never waits behind listings or HDF5 reads; exports and
// length fits have threads of their own and a bound each, so that anonymous clients looping
// them take at most that many threads and get a 503 past it (docs/reliability.md).
#pragma once

#include <boost/asio/thread_pool.hpp>

#include <atomic>
#include <functional>
#include <string>

namespace slipfront::server {

// `limit` threads running at most `limit` tasks at once; a task is never queued.
class BoundedPool {
public:
  // `what` names a task in the 503 past the limit ("export"), `flag` the limit's setting.
  // `nice` > 0 lowers the priority of the pool's threads (setpriority on each thread): pure
  // computation that may take every core yields them to the I/O threads and submissions.
  explicit BoundedPool(int limit, std::string what = "export", std::string flag = "--max-exports",
                       int nice = 0);
  // Runs `task` on a thread of the pool, then `then` once the task no longer counts against
  // the limit (an answer handed back there frees its place before its client can ask again);
  // false (and nothing done) if `limit` tasks run.
  bool try_post(std::function<void()> task, std::function<void()> then = {});
  int limit() const { return limit_; }
  // "2 exports are running, the most this server runs at once (--max-exports)"
  std::string busy_reason() const;
  void join() { pool_.join(); }

private:
  int limit_;
  std::string what_, flag_;
  int nice_;
  std::atomic<int> busy_{0};
  boost::asio::thread_pool pool_;
};

struct WorkPools {
  // Null: the route runs on the I/O thread instead.
  boost::asio::thread_pool* reads = nullptr;  // Runs::read_pool
  boost::asio::thread_pool* writes = nullptr; // Runs::write_pool
  BoundedPool* exports = nullptr;             // Runs::export_pool
  BoundedPool* fits = nullptr;                // Runs::fit_pool
};

} // namespace slipfront::server
