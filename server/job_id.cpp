#include "server/job_id.hpp"

#include <cstdint>
#include <mutex>
#include <random>

namespace slipfront::server {

std::string new_job_id() {
  static std::mutex mutex;
  static std::mt19937_64 engine{[] {
    std::random_device device;
    std::seed_seq seq{device(), device(), device(), device(), device(), device()};
    return std::mt19937_64(seq);
  }()};
  std::uint64_t a, b;
  {
    std::lock_guard lock(mutex);
    a = engine();
    b = engine();
  }
  static const char* hex = "0123456789abcdef";
  std::string id(32, '0');
  for (int i = 0; i < 16; ++i) {
    id[i] = hex[(a >> (4 * i)) & 0xf];
    id[16 + i] = hex[(b >> (4 * i)) & 0xf];
  }
  return id;
}

bool is_valid_job_id(std::string_view text) {
  if (text.size() != 32) return false;
  for (char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

} // namespace slipfront::server
