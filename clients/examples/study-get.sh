#!/bin/sh
# GET /api/v1/studies/{id}: status, progress, runs with their convergence status, L_c, map. Usage: study-get.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/studies/$1"
