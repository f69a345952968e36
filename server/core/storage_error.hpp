// A failure of the server's storage, as every floor above the store sees it (the store throws
// its own kind: server/db/database.hpp's SqliteError): whether it is worth a retry later.
#pragma once

#include <exception>
#include <stdexcept>
#include <string>

namespace slipfront::server {

class StorageError : public std::runtime_error {
public:
  StorageError(const std::string& what, bool unavailable)
      : std::runtime_error(what), unavailable_(unavailable) {}
  // The storage cannot take writes now (disk full, I/O error, read-only, busy): worth a
  // retry later (HTTP 503), unlike an error in the SQL or a broken constraint.
  bool unavailable() const { return unavailable_; }

private:
  bool unavailable_;
};

// True when `e` is a StorageError whose storage is unavailable.
inline bool storage_unavailable(const std::exception& e) {
  auto* storage = dynamic_cast<const StorageError*>(&e);
  return storage && storage->unavailable();
}

} // namespace slipfront::server
