#!/bin/sh
# GET /api/v1/jobs/{id}: status, progress, spec, metrics. Usage: status.sh ID [FIELDS, e.g. status,progress]
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/jobs/$1${2:+?fields=$2}"
