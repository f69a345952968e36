#include "server/http/work_pools.hpp"

#include <boost/asio/post.hpp>

#include <stdexcept>
#include <string>

namespace slipfront::server {

BoundedPool::BoundedPool(int limit)
    : limit_(limit), pool_(static_cast<std::size_t>(limit > 0 ? limit : 1)) {
  if (limit < 1)
    throw std::invalid_argument("a bounded pool needs at least 1 thread, got " +
                                std::to_string(limit));
}

bool BoundedPool::try_post(std::function<void()> task) {
  int busy = busy_.load();
  do {
    if (busy >= limit_) return false;
  } while (!busy_.compare_exchange_weak(busy, busy + 1));
  boost::asio::post(pool_, [this, task = std::move(task)] {
    struct Done {
      std::atomic<int>& busy;
      ~Done() { --busy; }
    } done{busy_};
    task();
  });
  return true;
}

} // namespace slipfront::server
