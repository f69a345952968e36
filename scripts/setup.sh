#!/usr/bin/env bash
# Installs the Debian packages slipfront needs (only the missing ones), then configures and
# builds the Release tree in build/ (build/slipfront). Safe to run again. The web view's
# third-party files (Swagger UI and Plotly, pinned in web/package-lock.json) come from the npm
# registry with `npm ci`; Chromium, its driver and Selenium are for the browser test (docs/web.md).
# Last, the Python client goes into a venv that sees the Debian packages (~/venv/slipfront, an
# editable install that follows the checkout) with a Jupyter kernel "slipfront" running in it
# (docs/python-api.md "Install").
#   bash scripts/setup.sh            # packages + Release build + client venv and kernel
#   BUILD_DIR=build-x bash scripts/setup.sh
#   SLIPFRONT_VENV=/other/venv bash scripts/setup.sh    # SLIPFRONT_VENV=none: no venv, no kernel
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake git pkg-config
  libeigen3-dev libboost1.81-all-dev nlohmann-json3-dev libsqlite3-dev sqlite3
  libcli11-dev   # the command line of slipfront (CLI11, header-only)
  libhdf5-dev hdf5-tools libfftw3-dev libssl-dev libgtest-dev libgmock-dev libbenchmark-dev
  python3-numpy python3-h5py python3-matplotlib python3-requests python3-pandas
  python3-venv python3-pip python3-setuptools python3-xarray python3-h5netcdf
  python3-nbconvert python3-ipykernel   # clients/examples/tour.ipynb, executed in ctest
  curl wrk clang-format pyflakes3
  slurm-wlm munge
  chromium chromium-driver python3-selenium
  clang libclang-rt-14-dev   # the libFuzzer targets (scripts/fuzz.sh)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

# npm (for the pinned Swagger UI and Plotly): Debian's npm unless a node with npm is already there.
if ! command -v npm >/dev/null 2>&1; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends npm >&2
fi
# npm ci when a web package pinned in web/package.json is missing or at another version.
if ! node -e '
  const deps = require("./web/package.json").dependencies;
  for (const [name, pinned] of Object.entries(deps))
    if (require(`./web/node_modules/${name}/package.json`).version !== pinned) process.exit(1);
' 2>/dev/null; then
  echo "setup: npm ci in web/ (swagger-ui-dist, plotly.js-cartesian-dist-min, pinned)" >&2
  (cd web && npm ci --ignore-scripts --no-audit --no-fund >&2) ||
    echo "setup: npm ci failed: the API docs page falls back to its small renderer and the" \
         "figures of the web view are missing" >&2
fi

build_dir="${BUILD_DIR:-build}"
# SLIPFRONT_CMAKE_ARGS: extra configure options (CI: -DSLIPFRONT_WERROR=ON).
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release ${SLIPFRONT_CMAKE_ARGS:-} >&2
cmake --build "$build_dir" -j"$(nproc)" >&2
echo "setup: built $build_dir/slipfront" >&2

# The client venv and the notebook's kernel: made once, the install and the kernel spec
# refreshed on every run (offline: the in-tree build backend of clients/pyproject.toml).
venv="${SLIPFRONT_VENV:-$HOME/venv/slipfront}"
if [ "$venv" != none ]; then
  if { [ -x "$venv/bin/python" ] || /usr/bin/python3 -m venv --system-site-packages "$venv"; } &&
     "$venv/bin/pip" install -q --no-index --disable-pip-version-check -e ./clients >&2 &&
     PYDEVD_DISABLE_FILE_VALIDATION=1 "$venv/bin/python" -m ipykernel install --user --name slipfront \
       --display-name "Python (slipfront)" >/dev/null; then
    echo "setup: client in $venv ($venv/bin/slipfront-client), Jupyter kernel 'slipfront'" >&2
    "$venv/bin/python" -c "import numpy, h5py, matplotlib, requests" 2>/dev/null ||
      echo "setup: $venv does not see Debian's numpy/h5py/matplotlib/requests (made without" \
           "--system-site-packages?): remove it and run the set-up again" >&2
  else
    echo "setup: the client venv $venv or its Jupyter kernel could not be set up" \
         "(docs/python-api.md \"Install\" does it by hand)" >&2
  fi
fi
