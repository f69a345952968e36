#!/bin/sh
# GET /api/v1/jobs/{id}/result.h5 with If-None-Match: 304 when the local copy (by sha256) is current. Usage: download-if-changed.sh ID FILE
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -o "$2.new" -w "%{http_code}\n" -H "If-None-Match: \"$(sha256sum "$2" | cut -d" " -f1)\"" "$SERVER/api/v1/jobs/$1/result.h5"
