#!/bin/sh
# GET /api/v1/studies/{id} (SPEC §4; not served yet: 404). Usage: study-get.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/studies/$1"
