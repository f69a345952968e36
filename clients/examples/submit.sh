#!/bin/sh
# POST /api/v1/jobs: submit a job file, or stdin ('echo {} | submit.sh' = the paper's scene). Usage: submit.sh [JOB.json] [QUERY, e.g. 'fresh=true&priority=5']
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -X POST "$SERVER/api/v1/jobs?${2:-}" -H "Content-Type: application/json" -H "Idempotency-Key: $(date +%s%N)" ${SLIPFRONT_TOKEN:+-H "Authorization: Bearer $SLIPFRONT_TOKEN"} --data-binary @"${1:-/dev/stdin}"
