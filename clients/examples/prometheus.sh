#!/bin/sh
# GET /metrics: Prometheus text (queue depth, running jobs, jobs by status, run durations, HTTP requests).
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/metrics"
