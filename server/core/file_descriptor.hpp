// An open file descriptor that closes with its owner, and reading a whole regular file without
// ever blocking on a FIFO or a device in its place.
#pragma once

#include <cstddef>
#include <string>

namespace slipfront::server {

class FileDescriptor {
public:
  FileDescriptor() = default;
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(other.release()) {}
  FileDescriptor& operator=(FileDescriptor&& other) noexcept;
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor();
  int get() const { return fd_; }
  int release(); // the caller closes it now

private:
  int fd_ = -1;
};

// The content of `path`, opened with O_NONBLOCK and read only if it is a regular file of at
// most `max_bytes`; throws std::runtime_error naming the path and the reason otherwise.
std::string read_regular_file(const std::string& path, std::size_t max_bytes);

} // namespace slipfront::server
