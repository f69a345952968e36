#include "server/run/job_queue.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

using namespace slipfront::server;

TEST(JobQueue, PriorityThenFifo) {
  JobQueue q(10);
  EXPECT_EQ(q.push("a", 0), JobQueue::PushResult::queued);
  EXPECT_EQ(q.push("b", 5), JobQueue::PushResult::queued);
  EXPECT_EQ(q.push("c", 0), JobQueue::PushResult::queued);
  EXPECT_EQ(q.push("d", 5), JobQueue::PushResult::queued);
  EXPECT_EQ(q.push("e", -1), JobQueue::PushResult::queued);
  std::vector<std::string> order;
  while (auto id = q.pop_for(10))
    order.push_back(*id);
  EXPECT_EQ(order, (std::vector<std::string>{"b", "d", "a", "c", "e"}));
}

TEST(JobQueue, LimitAndUnboundedPush) {
  JobQueue q(2);
  EXPECT_EQ(q.push("a", 0), JobQueue::PushResult::queued);
  EXPECT_EQ(q.push("b", 0), JobQueue::PushResult::queued);
  EXPECT_TRUE(q.full());
  EXPECT_EQ(q.push("c", 0), JobQueue::PushResult::full);
  EXPECT_EQ(q.push_unbounded("c", 0), JobQueue::PushResult::queued); // recovery
  EXPECT_EQ(q.size(), 3u);
  EXPECT_EQ(q.push_unbounded("c", 0), JobQueue::PushResult::duplicate);
}

TEST(JobQueue, RemoveQueued) {
  JobQueue q(10);
  q.push("a", 0);
  q.push("b", 0);
  EXPECT_TRUE(q.remove("a"));
  EXPECT_FALSE(q.remove("a"));
  EXPECT_FALSE(q.contains("a"));
  EXPECT_EQ(q.pop_for(10), "b");
  EXPECT_FALSE(q.pop_for(10).has_value());
}

TEST(JobQueue, CloseWakesBlockedWorkers) {
  JobQueue q(10);
  std::atomic<int> returned{0};
  std::vector<std::thread> workers;
  for (int i = 0; i < 3; ++i)
    workers.emplace_back([&] {
      while (q.pop()) {
      }
      ++returned;
    });
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  q.close();
  for (auto& t : workers)
    t.join();
  EXPECT_EQ(returned, 3);
  EXPECT_EQ(q.push("x", 0), JobQueue::PushResult::closed);
}

TEST(JobQueue, EveryJobPoppedOnceUnderContention) {
  JobQueue q(100000);
  constexpr int n = 2000;
  std::atomic<int> popped{0};
  std::vector<std::thread> workers;
  for (int i = 0; i < 4; ++i)
    workers.emplace_back([&] {
      while (auto id = q.pop_for(200))
        ++popped;
    });
  for (int i = 0; i < n; ++i)
    q.push(std::string("job").append(std::to_string(i)), i % 3);
  for (auto& t : workers)
    t.join();
  EXPECT_EQ(popped, n);
  EXPECT_EQ(q.size(), 0u);
}
