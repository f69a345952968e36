#!/bin/sh
# POST /api/v1/studies (201 + Location; 422 names each bad field). Usage: study-create.sh [STUDY.json] (default: L 1e-4,5e-5,1e-5 x n_d 10,20,40 of the paper's scene)
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -X POST "$SERVER/api/v1/studies" -H "Content-Type: application/json" ${SLIPFRONT_TOKEN:+-H "Authorization: Bearer $SLIPFRONT_TOKEN"} --data-binary @"${1:-$(dirname "$0")/study.json}"
