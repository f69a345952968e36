// A fixed team of threads that runs one task at a time on all its members.
//
//   ThreadTeam team(2);
//   team.run([&](int member, int size) { ... });   // returns when every member is done
//
// The caller's thread is member 0. Idle members sleep on a condition variable (no spin
// wait: a time-sliced machine does not collapse). Members flush denormal numbers to zero
// if asked (the quiet far field otherwise fills with denormals that are slow to compute).
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace slipfront {

class ThreadTeam {
public:
  explicit ThreadTeam(int size, bool flush_denormals = true);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return size_; }
  void run(const std::function<void(int member, int size)>& task);

private:
  void member_loop(int member);

  int size_;
  bool flush_denormals_;
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(int, int)>* task_ = nullptr;
  long generation_ = 0;
  int pending_ = 0;
  bool stopping_ = false;
};

// Set flush-to-zero and denormals-are-zero on the calling thread; returns the old state.
unsigned set_flush_denormals(bool on);
void restore_float_mode(unsigned state);

// Flushes denormals on the calling thread while it lives; restores the caller's
// floating-point mode when it goes, however the scope ends.
struct FloatModeGuard {
  unsigned saved = set_flush_denormals(true);
  ~FloatModeGuard() { restore_float_mode(saved); }
};

} // namespace slipfront
