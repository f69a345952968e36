#!/bin/sh
# GET /api/v1/jobs/{id}/result.h5: download the HDF5 result and check it against the sha256 the
# job announces (= the strong ETag). A partial FILE is resumed (-C - sends Range); a FILE that
# already matches is kept. Usage: download.sh ID [FILE]
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
out=${2:-$1.h5}
sha=$(curl -sS -f "$SERVER/api/v1/jobs/$1?fields=result" | sed -n 's/.*"sha256":"\([0-9a-f]*\)".*/\1/p')
echo "$sha  $out" | sha256sum -c --status - 2>/dev/null || curl -sS -f -C - -o "$out" "$SERVER/api/v1/jobs/$1/result.h5"
echo "$sha  $out" | sha256sum -c -
