#include "server/run/running_jobs.hpp"

namespace slipfront::server {

std::shared_ptr<RunningJob> RunningJobs::add(const std::string& id) {
  std::lock_guard lock(mutex_);
  auto entry = std::make_shared<RunningJob>();
  jobs_[id] = entry;
  return entry;
}

void RunningJobs::remove(const std::string& id) {
  std::lock_guard lock(mutex_);
  jobs_.erase(id);
}

std::shared_ptr<RunningJob> RunningJobs::find(const std::string& id) const {
  std::lock_guard lock(mutex_);
  auto it = jobs_.find(id);
  return it == jobs_.end() ? nullptr : it->second;
}

std::optional<JobProgress> RunningJobs::progress(const std::string& id) const {
  auto entry = find(id);
  if (!entry) return std::nullopt;
  std::lock_guard lock(entry->mutex);
  if (entry->progress.updated_at.empty()) return std::nullopt;
  return entry->progress;
}

RunningJobs::CancelRequest RunningJobs::request_cancel(const std::string& id,
                                                       const std::string& user) {
  auto entry = find(id);
  if (!entry) return CancelRequest::not_running;
  std::lock_guard lock(entry->mutex);
  if (entry->finishing) return CancelRequest::finishing;
  entry->cancelled_by = user;
  entry->user_cancelled = true;
  entry->cancel = true;
  return CancelRequest::requested;
}

void RunningJobs::cancel_all_for_drain() {
  std::lock_guard lock(mutex_);
  for (auto& [id, entry] : jobs_)
    entry->cancel = true;
}

std::size_t RunningJobs::size() const {
  std::lock_guard lock(mutex_);
  return jobs_.size();
}

} // namespace slipfront::server
