#include "server/data_dir_lock.hpp"

#include "server/core/log.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace slipfront::server {

namespace {

// The pid written in the lock file by its holder ("" if there is none to read).
std::string holder_pid(const std::string& lock_path) {
  const int fd = ::open(lock_path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return "";
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  ::close(fd);
  std::string pid = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : "";
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
    pid.pop_back();
  return pid;
}

std::runtime_error in_use(const std::string& data_dir, const std::string& lock_path) {
  const std::string pid = holder_pid(lock_path);
  return std::runtime_error("data dir " + data_dir + " is in use by another slipfront server" +
                            (pid.empty() ? "" : " (pid " + pid + ")") +
                            "; one data dir belongs to one server (lock file " + lock_path + ")");
}

} // namespace

DataDirLock::DataDirLock(const std::string& data_dir) {
  const std::string path = data_dir + "/slipfront.lock";
  dir_fd_ = ::open(data_dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd_ < 0)
    throw std::runtime_error("cannot open the data dir " + data_dir + ": " + std::strerror(errno));
  if (::flock(dir_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    ::close(dir_fd_);
    dir_fd_ = -1;
    if (err == EWOULDBLOCK) throw in_use(data_dir, path);
    // A file system without locks on directories (some network mounts): the lock file below
    // is then the only guard, and deleting it defeats it.
    log_error("data dir " + data_dir + ": cannot lock the directory (" + std::strerror(err) +
              "); only the lock file guards it: do not delete " + path + " while a server runs");
  }
  file_fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (file_fd_ < 0) {
    const int err = errno;
    release();
    throw std::runtime_error("cannot open the lock file " + path + ": " + std::strerror(err));
  }
  if (::flock(file_fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    release();
    if (err == EWOULDBLOCK) throw in_use(data_dir, path);
    throw std::runtime_error("cannot lock " + path + ": " + std::strerror(err));
  }
  // The holder's pid, for the message above and for operators; the locks are the flocks.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(file_fd_, 0) != 0 || ::pwrite(file_fd_, pid.data(), pid.size(), 0) < 0) {
    // The lock is held; only the informative pid is missing.
  }
}

DataDirLock::~DataDirLock() {
  release();
}

void DataDirLock::release() {
  // Closing releases the flocks.
  if (file_fd_ >= 0) ::close(file_fd_);
  if (dir_fd_ >= 0) ::close(dir_fd_);
  file_fd_ = dir_fd_ = -1;
}

} // namespace slipfront::server
