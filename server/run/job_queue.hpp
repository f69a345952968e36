// The run queue: highest priority first, FIFO within a priority, bounded by a limit.
// Worker threads block in pop(); close() wakes them all and makes pop() return nothing.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>

namespace slipfront::server {

class JobQueue {
public:
  explicit JobQueue(std::size_t limit) : limit_(limit) {}

  enum class PushResult { queued, full, closed, duplicate };
  // Adds a job unless the queue holds `limit` jobs already (then `full`).
  PushResult push(const std::string& id, int priority);
  // Adds a job whatever the limit (jobs recovered at start-up: nothing accepted is lost).
  PushResult push_unbounded(const std::string& id, int priority);

  // Blocks until a job is available (returns its id) or the queue is closed (nullopt).
  std::optional<std::string> pop();
  // Like pop(), but gives up after `timeout_ms` milliseconds.
  std::optional<std::string> pop_for(int timeout_ms);

  bool remove(const std::string& id); // false if not queued here
  bool contains(const std::string& id) const;
  std::size_t size() const;
  std::size_t limit() const { return limit_; }
  bool full() const;
  void close();
  bool closed() const;

private:
  using Key = std::tuple<int, std::uint64_t>; // (-priority, arrival)
  PushResult push_locked(const std::string& id, int priority);
  std::optional<std::string> take_locked();

  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::set<std::pair<Key, std::string>> order_;
  std::unordered_map<std::string, Key> index_;
  std::uint64_t arrivals_ = 0;
  std::size_t limit_;
  bool closed_ = false;
};

} // namespace slipfront::server
