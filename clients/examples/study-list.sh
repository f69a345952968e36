#!/bin/sh
# GET /api/v1/studies: newest first, summaries. Usage: study-list.sh ['status=running&limit=10']
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/studies?${1:-limit=20}"
