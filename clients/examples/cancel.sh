#!/bin/sh
# POST /api/v1/jobs/{id}/cancel (200 queued job cancelled, 202 running job stopping, 409 already finished). Usage: cancel.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -X POST "$SERVER/api/v1/jobs/$1/cancel" ${SLIPFRONT_TOKEN:+-H "Authorization: Bearer $SLIPFRONT_TOKEN"}
