#!/bin/sh
# GET /healthz: liveness and readiness (workers, queue depth, database).
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/healthz"
