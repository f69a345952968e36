#include "server/run/job_queue.hpp"

#include <chrono>

namespace slipfront::server {

JobQueue::PushResult JobQueue::push_locked(const std::string& id, int priority) {
  if (closed_) return PushResult::closed;
  if (index_.count(id)) return PushResult::duplicate;
  Key key{-priority, arrivals_++};
  order_.emplace(key, id);
  index_.emplace(id, key);
  ready_.notify_one();
  return PushResult::queued;
}

JobQueue::PushResult JobQueue::push(const std::string& id, int priority) {
  std::lock_guard lock(mutex_);
  if (!closed_ && order_.size() >= limit_) return PushResult::full;
  return push_locked(id, priority);
}

JobQueue::PushResult JobQueue::push_unbounded(const std::string& id, int priority) {
  std::lock_guard lock(mutex_);
  return push_locked(id, priority);
}

std::optional<std::string> JobQueue::take_locked() {
  if (closed_ || order_.empty()) return std::nullopt;
  auto first = order_.begin();
  std::string id = first->second;
  index_.erase(id);
  order_.erase(first);
  return id;
}

std::optional<std::string> JobQueue::pop() {
  std::unique_lock lock(mutex_);
  ready_.wait(lock, [&] { return closed_ || !order_.empty(); });
  return take_locked();
}

std::optional<std::string> JobQueue::pop_for(int timeout_ms) {
  std::unique_lock lock(mutex_);
  ready_.wait_for(lock, std::chrono::milliseconds(timeout_ms),
                  [&] { return closed_ || !order_.empty(); });
  return take_locked();
}

bool JobQueue::remove(const std::string& id) {
  std::lock_guard lock(mutex_);
  auto it = index_.find(id);
  if (it == index_.end()) return false;
  order_.erase({it->second, id});
  index_.erase(it);
  return true;
}

bool JobQueue::contains(const std::string& id) const {
  std::lock_guard lock(mutex_);
  return index_.count(id) != 0;
}

std::size_t JobQueue::size() const {
  std::lock_guard lock(mutex_);
  return order_.size();
}

bool JobQueue::full() const {
  std::lock_guard lock(mutex_);
  return order_.size() >= limit_;
}

void JobQueue::close() {
  std::lock_guard lock(mutex_);
  closed_ = true;
  ready_.notify_all();
}

bool JobQueue::closed() const {
  std::lock_guard lock(mutex_);
  return closed_;
}

} // namespace slipfront::server
