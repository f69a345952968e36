#!/bin/sh
# GET /api/v1/openapi.json: the OpenAPI 3 description of every endpoint.
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS "$SERVER/api/v1/openapi.json"
