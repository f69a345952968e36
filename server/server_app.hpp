// The whole server: store, queue, workers, HTTP. serve_main() builds one from the flags;
// tests may build one with another JobRunner.
//
// start(): bind the listener (first: a port in use is the first thing said), lock the data
// dir (DataDirLock: one server per directory), open (and migrate) the database, re-queue jobs
// a crash left running (with the SLURM executor: those not in SLURM; it re-attaches to the
// others), queue every queued job, start the executor, accept. shutdown(): stop accepting, stop the
// running jobs at their next step and put them back to queued, close the database.
#pragma once

#include "server/core/server_stats.hpp"
#include "server/data_dir_lock.hpp"
#include "server/db/job_store.hpp"
#include "server/db/study_store.hpp"
#include "server/http/auth.hpp"
#include "server/http/handlers.hpp"
#include "server/http/listener.hpp"
#include "server/http/router.hpp"
#include "server/run/job_queue.hpp"
#include "server/run/job_runner.hpp"
#include "server/run/running_jobs.hpp"
#include "server/run/slurm/slurm_executor.hpp"
#include "server/run/worker_pool.hpp"
#include "server/server_config.hpp"
#include "server/services/job_service.hpp"
#include "server/services/study_service.hpp"
#include "server/services/study_supervisor.hpp"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/thread_pool.hpp>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace slipfront::server {

class ServerApp {
public:
  // runner: nullptr = the solver (SolverJobRunner). code_version: "" = the solver's.
  explicit ServerApp(ServerConfig config, std::unique_ptr<JobRunner> runner = nullptr,
                     std::string code_version = "");
  ~ServerApp();

  void start();
  boost::asio::ip::tcp::endpoint endpoint() const { return listener_->local_endpoint(); }
  // Blocks until request_stop() (from any thread or a signal handler), then shuts down.
  void run_until_stopped();
  void request_stop();
  void shutdown();
  // SIGHUP: reads --token-file again; on an error the tokens in use stay (logged).
  void reload_tokens();
  // The routes (after start()): for the test that they and the OpenAPI paths are one set.
  const Router& router() const { return router_; }

private:
  void listen();
  SlurmExecutorOptions slurm_options(std::function<void(const std::string&)> on_finished) const;

  ServerConfig config_;
  std::string code_version_;
  std::unique_ptr<JobRunner> runner_;
  std::optional<TokenTable> tokens_;
  std::unique_ptr<DataDirLock> data_dir_lock_; // released last, after the store is closed
  std::unique_ptr<JobStore> store_;
  std::unique_ptr<JobQueue> queue_;
  RunningJobs running_;
  ServerStats stats_;
  std::atomic<bool> draining_{false};
  std::unique_ptr<JobService> service_;
  std::unique_ptr<StudyStore> study_store_;
  std::unique_ptr<StudySupervisor> supervisor_;
  std::unique_ptr<StudyService> studies_;
  std::unique_ptr<Executor> executor_; // WorkerPool or SlurmExecutor (--executor)
  std::unique_ptr<ServerContext> context_;
  Router router_;
  boost::asio::io_context ioc_;
  std::optional<boost::asio::executor_work_guard<boost::asio::io_context::executor_type>> work_;
  std::shared_ptr<Listener> listener_;
  std::vector<std::thread> io_threads_;
  // The handlers that may block (Router::runs): reads over many rows or an HDF5 file,
  // database writes, exports (at most --max-exports at once) and length fits (--max-fits).
  std::unique_ptr<boost::asio::thread_pool> read_pool_;
  std::unique_ptr<boost::asio::thread_pool> write_pool_;
  std::unique_ptr<BoundedPool> export_pool_;
  std::unique_ptr<BoundedPool> fit_pool_;
  std::mutex stop_mutex_;
  std::condition_variable stop_cv_;
  bool stop_requested_ = false;
  bool shut_down_ = false;
  bool started_ = false; // start() finished: shutdown() logs what it does
};

} // namespace slipfront::server
