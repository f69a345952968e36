#include "server/server_app.hpp"

#include "server/core/clock.hpp"
#include "server/core/log.hpp"
#include "server/http/static_files.hpp"
#include "solver/simulation.hpp"

#include <boost/asio/ip/address.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <limits>
#include <sstream>

namespace slipfront::server {

namespace net = boost::asio;

namespace {
// The descriptors a process may open: the soft limit raised to the hard one. Connections
// are capped below it, leaving room for the database, result files and the listener itself.
int connection_cap(int wanted) {
  constexpr rlim_t reserve = 64;
  struct rlimit lim {};
  if (getrlimit(RLIMIT_NOFILE, &lim) != 0) return wanted;
  if (lim.rlim_cur < lim.rlim_max) {
    lim.rlim_cur = lim.rlim_max;
    setrlimit(RLIMIT_NOFILE, &lim);
    getrlimit(RLIMIT_NOFILE, &lim);
  }
  if (lim.rlim_cur == RLIM_INFINITY) return wanted;
  const rlim_t room = lim.rlim_cur > 2 * reserve ? lim.rlim_cur - reserve : lim.rlim_cur / 2;
  if (static_cast<rlim_t>(wanted) <= room) return wanted;
  log_info("--max-connections " + std::to_string(wanted) + " lowered to " + std::to_string(room) +
           ": the process may open " + std::to_string(lim.rlim_cur) + " file descriptors");
  return static_cast<int>(room);
}

// The cost model of the estimates: the file given, else DATA_DIR/cost_model.json if it is
// there, else the built-in one (docs/performance.md "Cost estimate"). A file that is given or
// there but cannot be read stops the start.
api::CostModel load_cost_model(const std::string& given, const std::string& data_dir) {
  const std::string path = given.empty() ? data_dir + "/cost_model.json" : given;
  if (given.empty() && !std::filesystem::exists(path)) {
    log_info("cost model: built-in (no " + path + "; `slipfront calibrate --data-dir " + data_dir +
             "` measures this machine)");
    return api::CostModel::built_in();
  }
  const api::CostModel model = api::CostModel::read_file(path); // throws: the start stops
  log_info("cost model: " + path + " (" + model.machine + ", calibrated " + model.calibrated_at +
           ")");
  return model;
}
} // namespace

ServerApp::ServerApp(ServerConfig config, std::unique_ptr<JobRunner> runner,
                     std::string code_version)
    : config_(std::move(config)), code_version_(std::move(code_version)),
      runner_(std::move(runner)) {
  resolve_defaults(config_);
  if (!runner_) runner_ = std::make_unique<SolverJobRunner>();
  if (code_version_.empty()) code_version_ = slipfront::code_version();
}

ServerApp::~ServerApp() {
  shutdown();
}

// The address and port first: a server that cannot listen (a port in use, a host that is
// not an address) says so before it opens the data dir or writes a line of log.
void ServerApp::listen() {
  beast::error_code aec;
  auto address = net::ip::make_address(config_.host, aec);
  if (aec) throw std::runtime_error("--host " + config_.host + ": " + aec.message());
  SessionLimits limits;
  limits.max_body_bytes = config_.max_body_bytes;
  limits.max_import_bytes = config_.max_import_bytes;
  limits.request_timeout = std::chrono::seconds(config_.request_timeout_s);
  limits.send_timeout = std::chrono::seconds(config_.send_timeout_s);
  limits.max_connections = connection_cap(config_.max_connections);
  read_pool_ = std::make_unique<net::thread_pool>(2);
  write_pool_ = std::make_unique<net::thread_pool>(2);
  export_pool_ = std::make_unique<BoundedPool>(config_.max_exports, "export", "--max-exports");
  // Fits are pure computation that may take every core: at a lower priority (nice 10), so
  // that submissions and status reads never wait for a core behind them.
  fit_pool_ = std::make_unique<BoundedPool>(config_.max_fits, "length fit", "--max-fits", 10);
  limits.pools = {read_pool_.get(), write_pool_.get(), export_pool_.get(), fit_pool_.get()};
  // Answers built in memory and not yet read by their clients, over all connections.
  limits.unsent = std::make_shared<ByteBudget>(config_.max_unsent_bytes, 64 * 1024);
  listener_ = std::make_shared<Listener>(
      ioc_, net::ip::tcp::endpoint(address, static_cast<unsigned short>(config_.port)), router_,
      stats_, limits);
}

void ServerApp::start() {
  namespace fs = std::filesystem;
  listen();
  std::error_code ec;
  fs::create_directories(fs::path(config_.data_dir) / "results", ec);
  if (ec)
    throw std::runtime_error("cannot create data dir " + config_.data_dir +
                             "/results: " + ec.message());
  config_.data_dir = fs::canonical(config_.data_dir).string();
  // A read-only data dir (a read-only mount, a directory without write permission) is
  // refused at once: the database, the lock and every result are written there, and a server
  // that could only answer reads would accept nothing (docs/reliability.md).
  for (const auto& dir : {config_.data_dir, config_.data_dir + "/results"})
    if (::access(dir.c_str(), W_OK) != 0)
      throw std::runtime_error("data dir " + dir + " is not writable (" + std::strerror(errno) +
                               "): the server keeps its database, lock and result files there; "
                               "give it a writable directory (to read the data of a read-only "
                               "copy, open slipfront.db with sqlite3 and results/ with h5py)");
  if (config_.executor == "slurm") {
    if (config_.shared_dir.empty()) config_.shared_dir = config_.data_dir + "/slurm";
    fs::create_directories(config_.shared_dir, ec);
    if (ec) throw std::runtime_error("--shared-dir " + config_.shared_dir + ": " + ec.message());
    config_.shared_dir = fs::canonical(config_.shared_dir).string();
    if (config_.slurm_binary.empty())
      config_.slurm_binary = fs::read_symlink("/proc/self/exe").string();
  }
  // Before anything reads or recovers the directory's jobs.
  data_dir_lock_ = std::make_unique<DataDirLock>(config_.data_dir);
  if (!config_.token_file.empty()) tokens_ = TokenTable::load(config_.token_file);

  store_ = std::make_unique<JobStore>(config_.data_dir + "/slipfront.db", config_.integrity_check);
  if (auto malformed = store_->malformed_rows(); !malformed.empty()) {
    log_error("start-up check: " + std::to_string(malformed.size()) +
              " row(s) of the database hold JSON that does not parse; listings leave them out "
              "(`slipfront check " +
              config_.data_dir + "` lists them), the first: " + describe(malformed.front()));
  }
  queue_ = std::make_unique<JobQueue>(config_.queue_limit);
  const bool slurm = config_.executor == "slurm";
  int recovered = store_->requeue_all_running(slurm);
  if (recovered > 0)
    log_info("recovery: " + std::to_string(recovered) +
             " job(s) left running by the last process are queued again");
  auto queued = store_->queued_jobs();
  for (const auto& job : queued)
    queue_->push_unbounded(job.id, job.priority);
  // Temporary results of runs a crash interrupted are garbage.
  for (const auto& entry : fs::directory_iterator(fs::path(config_.data_dir) / "results", ec))
    if (entry.path().filename().string().find(".tmp") != std::string::npos)
      fs::remove(entry.path(), ec);

  ServiceOptions so;
  so.max_memory_bytes = config_.max_memory_bytes;
  so.max_result_bytes = config_.max_result_bytes;
  so.cost_model = load_cost_model(config_.cost_model_file, config_.data_dir);
  so.max_run_seconds = config_.max_run_seconds > 0 ? config_.max_run_seconds
                                                   : std::numeric_limits<double>::infinity();
  so.code_version = code_version_;
  so.auth_enabled = tokens_.has_value();
  so.data_dir = config_.data_dir;
  so.min_free_bytes = config_.min_free_bytes;
  service_ = std::make_unique<JobService>(so, *store_, *queue_, running_);
  // Imports and deletes a crash interrupted, and any result file no row refers to.
  const StrayResults stray = service_->recover_result_files();
  if (stray.intents > 0)
    log_info("recovery: " + std::to_string(stray.intents) +
             " import(s) or delete(s) were interrupted; " + std::to_string(stray.undone) +
             " of their result files removed");
  constexpr std::size_t named = 20; // then a count
  for (std::size_t i = 0; i < stray.removed.size() && i < named; ++i)
    log_info("recovery: " + stray.removed[i].path + " removed: no job refers to it");
  if (stray.removed.size() > named)
    log_info("recovery: " + std::to_string(stray.removed.size() - named) +
             " more result files no job refers to removed");

  WorkerOptions wo;
  wo.workers = config_.workers;
  wo.data_dir = config_.data_dir;
  wo.code_version = code_version_;
  wo.host = host_name();
  wo.db_progress_interval_s = config_.db_progress_interval_s;
  study_store_ = std::make_unique<StudyStore>(*store_);
  supervisor_ = std::make_unique<StudySupervisor>(*study_store_, *service_);
  studies_ = std::make_unique<StudyService>(*study_store_, *service_, *supervisor_);
  wo.on_finished = [this](const std::string& id) { supervisor_->job_finished(id); };
  service_->set_on_cancelled([this](const std::string& id) { supervisor_->job_finished(id); });
  if (slurm)
    executor_ = std::make_unique<SlurmExecutor>(slurm_options(wo.on_finished), *store_, *queue_,
                                                running_, stats_);
  else
    executor_ = std::make_unique<WorkerPool>(wo, *store_, *queue_, *runner_, running_, stats_);

  context_.reset(new ServerContext{*service_, stats_, tokens_, config_.data_dir, executor_->slots(),
                                   config_.retry_after_s, draining_, *studies_,
                                   config_.min_free_bytes, executor_->name()});
  context_->export_bytes = std::make_shared<ByteBudget>(config_.max_export_bytes);
  router_.on_storage_unavailable(config_.retry_after_s, [this](const std::string& what) {
    stats_.record_storage_error(what);
  });
  add_job_routes(router_, *context_);
  add_job_keep_routes(router_, *context_);
  add_archive_routes(router_, *context_);
  add_result_routes(router_, *context_);
  add_station_routes(router_, *context_);
  add_ops_routes(router_, *context_);
  add_study_routes(router_, *context_);
  add_study_keep_routes(router_, *context_);
  add_preset_routes(router_);
  add_length_fit_routes(router_);
  {
    const std::string web_dir =
        config_.web_dir.empty() ? StaticFiles::default_dir() : config_.web_dir;
    auto files = StaticFiles::load(web_dir);
    if (files->size() == 0)
      log_info("web view: no files found (" +
               (web_dir.empty() ? std::string("no web/ beside the executable") : web_dir) +
               "); / answers 404");
    else
      log_info("web view: " + std::to_string(files->size()) + " files from " + web_dir);
    add_static_routes(router_, files);
  }

  supervisor_->start(); // resumes every study left running
  executor_->start();
  listener_->run();
  work_.emplace(ioc_.get_executor());
  for (int i = 0; i < config_.io_threads; ++i)
    io_threads_.emplace_back([this] {
      for (;;) {
        try {
          ioc_.run();
          return;
        } catch (const std::exception& e) { // a handler threw past the router: log, go on
          log_error(std::string("io thread: ") + e.what());
        }
      }
    });
  log_info("slipfront " + code_version_ + ": " +
           (slurm ? "slurm executor (up to " + std::to_string(executor_->slots()) +
                        " jobs in SLURM, shared dir " + config_.shared_dir + ")"
                  : std::to_string(config_.workers) + " worker(s)") +
           ", data dir " + config_.data_dir + ", " + std::to_string(queued.size()) +
           " job(s) queued, memory limit per job " +
           std::to_string(static_cast<long long>(config_.max_memory_bytes)) + " bytes" +
           (tokens_ ? ", " + std::to_string(tokens_->size()) + " token(s)" : ", no auth"));
  started_ = true;
}

SlurmExecutorOptions
ServerApp::slurm_options(std::function<void(const std::string&)> on_finished) const {
  SlurmExecutorOptions so;
  so.slurm.partition = config_.slurm_partition;
  so.slurm.account = config_.slurm_account;
  so.slurm.time_limit = config_.slurm_time_limit;
  std::istringstream args(config_.slurm_sbatch_args);
  for (std::string arg; args >> arg;)
    so.slurm.extra_sbatch_args.push_back(arg);
  so.shared_dir = config_.shared_dir;
  so.data_dir = config_.data_dir;
  so.binary = config_.slurm_binary;
  so.code_version = code_version_;
  so.max_jobs = config_.slurm_max_jobs;
  so.poll_interval_s = config_.slurm_poll_interval_s;
  so.db_progress_interval_s = config_.db_progress_interval_s;
  so.on_finished = std::move(on_finished);
  return so;
}

void ServerApp::reload_tokens() {
  if (!tokens_) {
    log_info("SIGHUP: no --token-file, no tokens to reload");
    return;
  }
  try {
    tokens_->reload(config_.token_file);
    log_info("SIGHUP: " + std::to_string(tokens_->size()) + " token(s) reloaded from " +
             config_.token_file);
  } catch (const std::exception& e) {
    log_error(std::string("SIGHUP: tokens not reloaded, the previous ones stay: ") + e.what());
  }
}

void ServerApp::request_stop() {
  {
    std::lock_guard lock(stop_mutex_);
    stop_requested_ = true;
  }
  stop_cv_.notify_all();
}

void ServerApp::run_until_stopped() {
  {
    std::unique_lock lock(stop_mutex_);
    stop_cv_.wait(lock, [&] { return stop_requested_; });
  }
  shutdown();
}

void ServerApp::shutdown() {
  if (shut_down_) return;
  shut_down_ = true;
  draining_ = true;
  // A start that failed says why (serve.cpp) and nothing else: what it opened is released
  // quietly.
  if (started_)
    log_info("shutting down: no new connections; running jobs stop and are queued again");
  if (listener_) listener_->stop();
  // Local: each running job stops at its next step. SLURM: the jobs stay in SLURM.
  if (executor_) executor_->drain();
  if (supervisor_) supervisor_->stop();
  work_.reset();
  ioc_.stop();
  for (auto& t : io_threads_)
    if (t.joinable()) t.join();
  io_threads_.clear();
  // Handlers in flight finish; their answers are dropped.
  if (read_pool_) read_pool_->join();
  if (write_pool_) write_pool_->join();
  if (export_pool_) export_pool_->join();
  if (fit_pool_) fit_pool_->join();
  executor_.reset();
  studies_.reset();
  supervisor_.reset();
  study_store_.reset();
  store_.reset(); // checkpoints the WAL and closes the database
  if (started_) log_info("stopped");
}

} // namespace slipfront::server
