#!/bin/sh
# GET /api/v1/studies/{id}/speed-accuracy: per run, wall time and memory against its errors. Usage: speed-accuracy.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/studies/$1/speed-accuracy"
