#!/bin/sh
# GET /api/v1/convergence-map: the map and L_c of every run of a scene, whoever submitted it. Usage: convergence-map.sh 'study=ID' (or 'scene=HASH')
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/convergence-map?${1:?usage: convergence-map.sh study=ID (or scene=HASH)}"
