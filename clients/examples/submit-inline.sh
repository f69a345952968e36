#!/bin/sh
# POST /api/v1/jobs with an inline job: L = 1e-5 m, n_d = 20 (prints the Location header and the job).
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -i -X POST "$SERVER/api/v1/jobs" -H "Content-Type: application/json" ${SLIPFRONT_TOKEN:+-H "Authorization: Bearer $SLIPFRONT_TOKEN"} -d '{"name": "L=1e-5 n_d=20", "tags": ["example"], "friction": {"L": 1e-5}, "geometry": {"nodes_per_meter": 20}}'
