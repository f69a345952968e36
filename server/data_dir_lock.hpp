// Exclusive ownership of a data directory: flock(2) on the directory itself, held on an open
// descriptor for the life of the object, and on DATA_DIR/slipfront.lock (which names the
// holder's pid). The kernel drops both when the process dies, even on SIGKILL, so a crash never
// leaves a stale lock; and the directory's lock does not depend on a file that can be deleted
// (a second server after `rm slipfront.lock` would otherwise lock a new file of that name).
// A second server on the same directory would re-queue the first one's running jobs and delete
// their temporary files: it must not start.
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
  void release();

  int dir_fd_ = -1;
  int file_fd_ = -1;
};

} // namespace slipfront::server
