#!/bin/sh
# GET /api/v1/jobs/{id}/result.xdmf: the XDMF sidecar of the result file (ParaView, VisIt). It
# names the HDF5 file ID.h5: save it beside download.sh's ID.h5. Usage: xdmf.sh ID
set -eu
SERVER=${SLIPFRONT_SERVER:-http://127.0.0.1:8080}
curl -sS -f -o "$1.xdmf" "$SERVER/api/v1/jobs/$1/result.xdmf"
echo "$1.xdmf"
