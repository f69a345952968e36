#include "server/core/byte_budget.hpp"

#include <utility>

namespace slipfront::server {

bool ByteBudget::reserve(std::uint64_t n) {
  auto held = held_.load();
  do {
    if (n > always_allowed_ && held + n > limit_) return false;
  } while (!held_.compare_exchange_weak(held, held + n));
  return true;
}

std::optional<ByteReservation> ByteReservation::take(std::shared_ptr<ByteBudget> budget,
                                                     std::uint64_t n) {
  if (!budget->reserve(n)) return std::nullopt;
  ByteReservation r;
  r.budget_ = std::move(budget);
  r.bytes_ = n;
  return r;
}

ByteReservation& ByteReservation::operator=(ByteReservation&& other) noexcept {
  if (this != &other) {
    reset();
    budget_ = std::move(other.budget_);
    bytes_ = std::exchange(other.bytes_, 0);
  }
  return *this;
}

void ByteReservation::reset() {
  if (budget_ && bytes_ > 0) budget_->release(bytes_);
  budget_.reset();
  bytes_ = 0;
}

} // namespace slipfront::server
