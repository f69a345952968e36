// Result files checked against what the database says before they are served or reused by the
// cache (docs/reliability.md): a regular file of the stored size whose SHA-256 is the stored
// one. A file is hashed once per change: while its inode, size, mtime and ctime stay what they
// were when it was hashed, the verdict is kept and a check costs one open and one fstat.
#pragma once

#include "api/run_record.hpp" // api::ResultFile
#include "server/core/file_descriptor.hpp"
#include "server/db/file_intents.hpp" // ResultReferences

#include <sys/stat.h>

#include <cstdint>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace slipfront::server {

struct OpenedResult {
  enum class State {
    intact,      // fd is open at offset 0
    missing,     // no file at the stored path
    not_regular, // a directory, FIFO, device... in its place (never opened for reading)
    damaged,     // another size or another SHA-256 than stored
    unreadable,  // open or read failed otherwise (reason says why)
  } state = State::missing;
  FileDescriptor fd;
  std::uint64_t size = 0;
  std::string reason; // for the log and the answer: never the server's path
};

class ResultFiles {
public:
  explicit ResultFiles(std::string data_dir) : data_dir_(std::move(data_dir)) {}

  // Opens the stored file (its path is relative to the data dir) without blocking on a FIFO
  // and verifies it. May hash the whole file: call it off the I/O threads.
  OpenedResult open(const api::ResultFile& stored);
  bool intact(const api::ResultFile& stored) {
    return open(stored).state == OpenedResult::State::intact;
  }
  std::string absolute_path(const api::ResultFile& stored) const;

private:
  // What identifies one version of a file's bytes without reading them.
  struct Identity {
    dev_t device = 0;
    ino_t inode = 0;
    off_t size = 0;
    std::int64_t mtime_ns = 0, ctime_ns = 0;
    bool operator==(const Identity&) const = default;
  };
  struct Verdict {
    Identity identity;
    std::string sha256; // stored hash it was checked against
    bool intact = false;
  };
  static Identity identity_of(const struct stat& st);

  std::string data_dir_;
  std::mutex mutex_;
  std::unordered_map<std::string, Verdict> verdicts_; // by stored path
};

// A file of results/ that no row refers to (docs/reliability.md "What bounds the disk").
struct StrayResult {
  std::string path;       // relative to the data dir: results/<name>
  bool temporary = false; // a ".tmp" name: a run or an import that did not finish
};

// The files of DATA_DIR/results that no row refers to, leaving out those of queued and
// running jobs (named after their id: a run in progress writes them).
std::vector<StrayResult> find_stray_results(const std::string& data_dir,
                                            const ResultReferences& refs);

} // namespace slipfront::server
