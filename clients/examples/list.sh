#!/bin/sh
# GET /api/v1/jobs: list jobs newest first. Usage: list.sh [QUERY], e.g. 'status=succeeded&tag=example&L_min=1e-6&n_d_max=40&limit=10&fields=status,metrics' (then '&cursor=NEXT_CURSOR')
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/jobs?${1:-limit=20}"
