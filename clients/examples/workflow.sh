#!/bin/sh
# The same with slipfront-client: a small L x n_d grid of tiny jobs, waited for, then every
# figure. Usage: workflow.sh [OUTPUT_DIR]   (server: $SLIPFRONT_SERVER)
set -eu
here=$(dirname "$0")
client="$here/../slipfront-client"
out=${1:-figures}
tag="workflow-$(date +%s)"
for L in 1e-4 5e-5; do
  for nd in 5 10; do
    "$client" submit "$here/tiny.json" --set friction.L=$L --set geometry.nodes_per_meter=$nd \
      --tag "$tag" --wait >/dev/null
  done
done
"$client" list --tag "$tag"
ids=$("$client" list --tag "$tag" --json | /usr/bin/python3 -c 'import json,sys; print(" ".join(j["id"] for j in json.load(sys.stdin)))')
first=${ids%% *}
"$client" download "$first" -o "$out/first.h5"
"$client" plot map "$out/first.h5" --probes 2,3 -o "$out" --format png,pdf
"$client" plot velocity $ids --x1 2,3 -o "$out" --format png,pdf
"$client" plot speed $ids -o "$out" --format png,pdf
"$client" plot convergence --tag "$tag" -o "$out" --format png,pdf
"$client" plot filter $ids -o "$out" --format png,pdf
"$client" plot cost --tag "$tag" -o "$out" --format png,pdf
