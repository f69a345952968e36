#include "app/commands.hpp"

#include <ostream>

namespace slipfront::app {

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
  slipfront serve [--host 127.0.0.1] [--port 8080] [--data-dir DIR] [...]
      Run the HTTP job server (docs/server.md).
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
