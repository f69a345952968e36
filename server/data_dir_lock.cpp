#include "server/data_dir_lock.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace slipfront::server {

DataDirLock::DataDirLock(const std::string& data_dir) {
  const std::string path = data_dir + "/slipfront.lock";
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error("cannot open the lock file " + path + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int err = errno;
    char holder[32] = {};
    const ssize_t n = ::pread(fd_, holder, sizeof holder - 1, 0);
    std::string pid = n > 0 ? std::string(holder, static_cast<std::size_t>(n)) : "";
    while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
      pid.pop_back();
    ::close(fd_);
    fd_ = -1;
    if (err == EWOULDBLOCK)
      throw std::runtime_error("data dir " + data_dir + " is in use by another slipfront server" +
                               (pid.empty() ? "" : " (pid " + pid + ")") +
                               "; one data dir belongs to one server (lock file " + path + ")");
    throw std::runtime_error("cannot lock " + path + ": " + std::strerror(err));
  }
  // The holder's pid, for the message above and for operators; the lock is the flock.
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The lock is held; only the informative pid is missing.
  }
}

DataDirLock::~DataDirLock() {
  if (fd_ >= 0) ::close(fd_); // releases the flock
}

} // namespace slipfront::server
