#include "app/commands.hpp"

#include <string>
#include <vector>

#include <algorithm>
#include <ostream>

namespace slipfront::app {

bool wants_help(const std::vector<std::string>& args) {
  return std::any_of(args.begin(), args.end(),
                     [](const std::string& a) { return a == "--help" || a == "-h"; });
}

void print_run_usage(std::ostream& out) {
  out << R"(usage: slipfront run JOB.json [--output RESULT.h5] [--threads N] [--max-memory SIZE]
                     [--quiet]

Run one job in the foreground. JOB.json may be "-" to read the job from standard input.
Progress goes to stderr (a bar on a terminal, a line every few seconds otherwise, and a
final line with the outcome, arrest position and wall time); the metrics go to stdout as
one JSON object.

options:
  --output RESULT.h5  write the HDF5 result file (docs/hdf5-layout.md) and its XDMF
                      sidecar RESULT.xdmf (ParaView, VisIt)
  --threads N         worker threads (overrides the job's "threads"; 0 = all cores)
  --max-memory SIZE   refuse a job whose memory estimate is above SIZE (bytes, or with a
                      suffix K, M, G, T; default 8G)
  --quiet             no progress on stderr
  -h, --help          this help

exit codes: 0 success, 1 the run failed, 2 invalid job or command line, 3 diverged,
130 interrupted (SIGINT). The job JSON: docs/api-job-spec.md.
)";
}

void print_validate_usage(std::ostream& out) {
  out << R"(usage: slipfront validate JOB.json [--max-memory SIZE]

Check a job without running it: prints "ok", its spec hash, memory estimate and mesh, or
every error as "pointer: reason" on stderr. JOB.json may be "-" for standard input.

options:
  --max-memory SIZE   refuse a job whose memory estimate is above SIZE (bytes, or with a
                      suffix K, M, G, T; default 8G)
  -h, --help          this help

exit codes: 0 valid, 2 invalid job or command line. The job JSON: docs/api-job-spec.md.
)";
}

void print_stations_usage(std::ostream& out) {
  out << R"(usage: slipfront stations RESULT.h5 [--csv FILE]

The on-fault stations of a result file (the job's "stations"; docs/hdf5-layout.md): each
station's x1, the nodes it is read from and its rupture time; or, with --csv, every recorded
step as CSV in the long format (station_x1,time,slip,slip_rate,shear_traction,
normal_traction; units in the header comments). FILE may be "-" for standard output.

options:
  --csv FILE   write the CSV to FILE ("-": standard output)
  -h, --help   this help

exit codes: 0 success, 1 the file cannot be read or has no stations, 2 invalid command line.
)";
}

void print_usage(std::ostream& out) {
  out << R"(slipfront: frictional interface rupture simulations (Kammer et al. 2014)

usage:
  slipfront run JOB.json [--output RESULT.h5] [--threads N] [--max-memory SIZE] [--quiet]
                [--progress-file F] [--report-file F]
      Run one job in the foreground; progress on stderr, the metrics as one JSON object
      on stdout. JOB.json may be "-" to read the job from standard input.
      --progress-file rewrites F (JSON: fraction, time, duration, steps, eta_s) about
      twice a second; --report-file writes F at the end (metrics, front, result file):
      what the server's SLURM executor follows (docs/cluster.md).
  slipfront validate JOB.json [--max-memory SIZE]
      Check a job: prints "ok", its spec hash and memory estimate, or every error.
  --max-memory SIZE refuses a job whose memory estimate is above SIZE (bytes, or with a
      suffix K, M, G, T; default 8G).
  slipfront schema [--markdown]
      The job schema: JSON Schema (also served at /api/v1/schema/job.json), or the field
      tables of docs/api-job-spec.md.
  slipfront presets [NAME] [--json]
      The presets a job may start from (the field's standard scenes and the examples);
      with NAME its job as JSON. A job may name one: {"preset": NAME, ...} (docs/presets.md).
  slipfront stations RESULT.h5 [--csv FILE]
      The on-fault stations of a result file: rupture times, or every step as CSV.
  slipfront fit-length RECORD [--json] [--fit-v-star] [--v-star V] [--mu MU] [--station X1]
      The paper's Sec. 6 on one interface point's record (CSV, a stations CSV, or JSON): the
      fitted length L_m, f_m, and whether L_m is the physical length (docs/length-fit.md).
  slipfront serve [--host 127.0.0.1] [--port 8080] [--data-dir DIR] [--max-memory SIZE] [...]
      Run the HTTP job server (docs/server.md).
  slipfront check DATA_DIR
      List what a server could not read in DATA_DIR/slipfront.db (rows whose stored JSON
      does not parse, PRAGMA quick_check); exit 0 and "ok" if nothing.
  slipfront run|validate|presets|stations|fit-length|serve|check --help   the options of one command
  slipfront --version
  slipfront help | --help

exit codes:
  0    success
  1    the run failed (I/O or internal error)
  2    invalid job or command line (each error as "pointer: reason" on stderr)
  3    the run diverged (metrics still printed, no result file written)
  130  interrupted by SIGINT (no result file written)

The job JSON and the result file: docs/api-job-spec.md, docs/hdf5-layout.md.
)";
}

} // namespace slipfront::app
