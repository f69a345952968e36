// A fresh directory under the system temp dir, removed with everything in it at scope exit.
#pragma once

#include "server/core/job_id.hpp"

#include <filesystem>
#include <string>
#include <system_error>

namespace slipfront::server::testing {

class TempDir {
public:
  explicit TempDir(const std::string& prefix)
      : path_(std::filesystem::temp_directory_path() / (prefix + new_job_id())) {
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
  std::filesystem::path path_;
};

} // namespace slipfront::server::testing
