#!/bin/sh
# GET /api/v1/jobs/{id}/result.h5 with Range: the first 8 bytes (206 Partial Content; the HDF5 signature). Usage: range.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -H "Range: bytes=0-7" "$SERVER/api/v1/jobs/$1/result.h5" | od -c | head -1
