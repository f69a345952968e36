#!/bin/sh
# POST /api/v1/studies/{id}/cancel (200 cancelled, 202 running runs stopping, 409 not running). Usage: study-cancel.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -X POST "$SERVER/api/v1/studies/$1/cancel" ${SLIPFRONT_TOKEN:+-H "Authorization: Bearer $SLIPFRONT_TOKEN"}
