// A bound on the bytes many holders keep at once (docs/reliability.md "What bounds the
// disk"): answers built in memory and not yet read by their clients, export files not yet
// sent. A holder reserves before it holds and releases when it is done; a ByteReservation
// releases by itself when it goes (with the answer or the file that holds it).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>

namespace slipfront::server {

class ByteBudget {
public:
  // A reservation of at most `always_allowed` bytes is never refused (errors, status, health).
  explicit ByteBudget(std::uint64_t limit, std::uint64_t always_allowed = 0)
      : limit_(limit), always_allowed_(always_allowed) {}
  ByteBudget(const ByteBudget&) = delete;
  ByteBudget& operator=(const ByteBudget&) = delete;

  // Counts `n` in, unless that would pass the limit (then false, nothing counted).
  bool reserve(std::uint64_t n);
  void release(std::uint64_t n) { held_ -= n; }
  std::uint64_t held() const { return held_; }
  std::uint64_t limit() const { return limit_; }

private:
  std::uint64_t limit_;
  std::uint64_t always_allowed_;
  std::atomic<std::uint64_t> held_{0};
};

// Bytes counted in a budget until this object (or the one it was moved to) goes.
class ByteReservation {
public:
  ByteReservation() = default;
  // Reserves `n` bytes of `budget`; nullopt when the budget refuses them.
  static std::optional<ByteReservation> take(std::shared_ptr<ByteBudget> budget, std::uint64_t n);
  ~ByteReservation() { reset(); }
  ByteReservation(ByteReservation&& other) noexcept { *this = std::move(other); }
  ByteReservation& operator=(ByteReservation&& other) noexcept;
  ByteReservation(const ByteReservation&) = delete;
  ByteReservation& operator=(const ByteReservation&) = delete;

  void reset(); // releases the bytes now
  std::uint64_t bytes() const { return bytes_; }

private:
  std::shared_ptr<ByteBudget> budget_;
  std::uint64_t bytes_ = 0;
};

} // namespace slipfront::server
