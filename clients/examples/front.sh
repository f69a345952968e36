#!/bin/sh
# GET /api/v1/jobs/{id}/front: x1, arrival_time, rupture_speed (null where undefined). Usage: front.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/jobs/$1/front"
