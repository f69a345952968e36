#include "server/http/work_pools.hpp"

#include <boost/asio/post.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <stdexcept>
#include <string>

namespace slipfront::server {

BoundedPool::BoundedPool(int limit, std::string what, std::string flag, int nice)
    : limit_(limit), what_(std::move(what)), flag_(std::move(flag)), nice_(nice),
      pool_(static_cast<std::size_t>(limit > 0 ? limit : 1)) {
  if (limit < 1)
    throw std::invalid_argument("a bounded pool needs at least 1 thread, got " +
                                std::to_string(limit));
}

std::string BoundedPool::busy_reason() const {
  return std::to_string(limit_) + " " + what_ + (limit_ == 1 ? " is" : "s are") +
         " running, the most this server runs at once (" + flag_ + ")";
}

bool BoundedPool::try_post(std::function<void()> task, std::function<void()> then) {
  int busy = busy_.load();
  do {
    if (busy >= limit_) return false;
  } while (!busy_.compare_exchange_weak(busy, busy + 1));
  boost::asio::post(pool_, [this, task = std::move(task), then = std::move(then)] {
    // Once per thread (a thread belongs to one pool): Linux gives each thread its own nice.
    thread_local bool lowered = false;
    if (nice_ > 0 && !lowered) {
      ::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), nice_);
      lowered = true;
    }
    {
      struct Done {
        std::atomic<int>& busy;
        ~Done() { --busy; }
      } done{busy_};
      task();
    }
    if (then) then();
  });
  return true;
}

} // namespace slipfront::server
