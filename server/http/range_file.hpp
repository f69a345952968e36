// A file for http::basic_file_body that serves one byte range [offset, offset + length):
// the body writer reads from the current position for size() bytes, so seeking first and
// reporting the range length as the size is all a 206 needs. It may hold a reservation of a
// byte budget (an export's disk), released when the file is closed.
#pragma once

#include "server/core/byte_budget.hpp"

#include <boost/beast/core/file.hpp>

#include <cstdint>

namespace slipfront::server {

class RangeFile {
public:
  using native_handle_type = boost::beast::file::native_handle_type;

  bool is_open() const { return file_.is_open(); }
  void close(boost::beast::error_code& ec) {
    file_.close(ec);
    held_.reset();
  }
  void open(const char* path, boost::beast::file_mode mode, boost::beast::error_code& ec) {
    file_.open(path, mode, ec);
    if (!ec) length_ = file_.size(ec);
  }
  // Takes an open descriptor over (ResultFiles::open), read from its current position.
  void adopt(native_handle_type fd, boost::beast::error_code& ec) {
    file_.native_handle(fd);
    length_ = file_.size(ec);
  }
  // Counts the file in a budget until it is closed or destroyed (with the answer's body).
  void hold(ByteReservation reservation) { held_ = std::move(reservation); }
  // Restrict to [offset, offset + length); call after open().
  void set_range(std::uint64_t offset, std::uint64_t length, boost::beast::error_code& ec) {
    file_.seek(offset, ec);
    length_ = length;
  }
  std::uint64_t size(boost::beast::error_code& ec) const {
    ec = {};
    return length_;
  }
  std::uint64_t pos(boost::beast::error_code& ec) const { return file_.pos(ec); }
  void seek(std::uint64_t offset, boost::beast::error_code& ec) { file_.seek(offset, ec); }
  std::size_t read(void* buffer, std::size_t n, boost::beast::error_code& ec) const {
    return file_.read(buffer, n, ec);
  }
  std::size_t write(const void* buffer, std::size_t n, boost::beast::error_code& ec) {
    return file_.write(buffer, n, ec);
  }

private:
  ByteReservation held_; // declared first: released after the file is closed
  boost::beast::file file_;
  std::uint64_t length_ = 0;
};

} // namespace slipfront::server
