#!/bin/sh
# GET /api/v1/jobs?where=...&sort=...&format=csv|ndjson: search the runs on spec fields, metrics
# and job columns, and export the run table. Usage: export.sh WHERE [csv|ndjson] [SORT], e.g.
# export.sh 'friction.L<1e-4; metrics.arrest_position>12' csv -friction.L > runs.csv
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -f --get "$SERVER/api/v1/jobs" --data-urlencode "where=$1" \
     --data-urlencode "format=${2:-csv}" --data-urlencode "sort=${3:-friction.L}"
