// The thread team (thread_team.hpp) and the floating-point mode of the calling thread.
#include "solver/thread_team.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif

namespace slipfront {

unsigned set_flush_denormals(bool on) {
#if defined(__x86_64__) || defined(__i386__)
  const unsigned old = _mm_getcsr();
  if (on) _mm_setcsr(old | 0x8040u); // FTZ (bit 15) | DAZ (bit 6)
  return old;
#else
  (void)on;
  return 0;
#endif
}

void restore_float_mode(unsigned state) {
#if defined(__x86_64__) || defined(__i386__)
  _mm_setcsr(state);
#else
  (void)state;
#endif
}

ThreadTeam::ThreadTeam(int size, bool flush_denormals)
    : size_(size < 1 ? 1 : size), flush_denormals_(flush_denormals) {
  for (int m = 1; m < size_; ++m)
    threads_.emplace_back([this, m] { member_loop(m); });
}

ThreadTeam::~ThreadTeam() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (auto& t : threads_)
    t.join();
}

void ThreadTeam::run(const std::function<void(int, int)>& task) {
  if (size_ > 1) {
    std::lock_guard lock(mutex_);
    task_ = &task;
    pending_ = size_ - 1;
    ++generation_;
  }
  wake_.notify_all();
  const unsigned mode = set_flush_denormals(flush_denormals_);
  task(0, size_);
  restore_float_mode(mode);
  if (size_ > 1) {
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
    task_ = nullptr;
  }
}

void ThreadTeam::member_loop(int member) {
  set_flush_denormals(flush_denormals_);
  long seen = 0;
  for (;;) {
    const std::function<void(int, int)>* task = nullptr;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      task = task_;
    }
    (*task)(member, size_);
    {
      std::lock_guard lock(mutex_);
      if (--pending_ == 0) done_.notify_one();
    }
  }
}

} // namespace slipfront
