// The thread pools that run the handlers that may block (Router's `Runs`, docs/server.md
// "Threads"), owned by ServerApp and shared by every session. Reads and writes wait in
// separate queues, so a submission never waits behind listings or HDF5 reads; exports have
// threads of their own and a bound, so that anonymous clients looping exports take at most
// that many threads and get a 503 past it (docs/reliability.md).
#pragma once

#include <boost/asio/thread_pool.hpp>

#include <atomic>
#include <functional>

namespace slipfront::server {

// `limit` threads running at most `limit` tasks at once; a task is never queued.
class BoundedPool {
public:
  explicit BoundedPool(int limit);
  // Runs `task` on a thread of the pool; false (and nothing done) if `limit` tasks run.
  bool try_post(std::function<void()> task);
  int limit() const { return limit_; }
  void join() { pool_.join(); }

private:
  int limit_;
  std::atomic<int> busy_{0};
  boost::asio::thread_pool pool_;
};

struct WorkPools {
  // Null: the route runs on the I/O thread instead.
  boost::asio::thread_pool* reads = nullptr;  // Runs::read_pool
  boost::asio::thread_pool* writes = nullptr; // Runs::write_pool
  BoundedPool* exports = nullptr;             // Runs::export_pool
};

} // namespace slipfront::server
