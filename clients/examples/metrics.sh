#!/bin/sh
# GET /api/v1/jobs/{id}/metrics: the metrics of the run (docs/metrics.md). Usage: metrics.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/jobs/$1/metrics"
