// Exclusive ownership of a data directory: an flock(2) on DATA_DIR/slipfront.lock, held
// for the life of the object (the kernel drops it when the process dies, even on SIGKILL,
// so a crash never leaves a stale lock). A second server on the same directory would
// re-queue the first one's running jobs and delete their temporary files: it must not
// start.
#pragma once

#include <string>

namespace slipfront::server {

class DataDirLock {
public:
  // Throws std::runtime_error naming the directory (and the holder's pid when known) if
  // another process holds the lock.
  explicit DataDirLock(const std::string& data_dir);
  ~DataDirLock();
  DataDirLock(const DataDirLock&) = delete;
  DataDirLock& operator=(const DataDirLock&) = delete;

private:
  int fd_ = -1;
};

} // namespace slipfront::server
