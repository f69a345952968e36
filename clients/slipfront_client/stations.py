"""The on-fault stations of a run (docs/hdf5-layout.md "/stations"): the time series of slip,
slip rate, shear and normal traction at each station and its rupture time, as numpy arrays,
from the server's CSV (GET /api/v1/jobs/{id}/stations.csv) or from a local result file.

    st = sf.job_stations(api, job_id)     # Stations: x1, time, slip_rate [m, n], ...
    st.rupture_time                       # [n], NaN where the rupture never arrived
    df = st.dataframe()                   # the long format as a pandas DataFrame
"""

import io
import math
import re
from dataclasses import dataclass

import numpy as np

from .errors import UsageError

COLUMNS = ["station_x1", "time", "slip", "slip_rate", "shear_traction", "normal_traction"]
SERIES = ["slip", "slip_rate", "shear_traction", "normal_traction"]
UNITS = {"station_x1": "m", "time": "s", "slip": "m", "slip_rate": "m/s",
         "shear_traction": "Pa", "normal_traction": "Pa", "rupture_time": "s"}
_THRESHOLD = re.compile(r"rupture_threshold = (\S+) m/s")
_RUPTURE = re.compile(r"^# station_x1 = (\S+): rupture_time = (\S+)$")


@dataclass
class Stations:
    x1: np.ndarray               # [n] station positions [m]
    time: np.ndarray             # [m] step times [s]
    slip: np.ndarray             # [m, n] [m]
    slip_rate: np.ndarray        # [m, n] [m/s]
    shear_traction: np.ndarray   # [m, n] [Pa]
    normal_traction: np.ndarray  # [m, n] [Pa], negative in compression
    rupture_time: np.ndarray     # [n] [s], NaN if never
    rupture_threshold: float     # [m/s]

    def at(self, x1):
        """The column index of the station at `x1` (UsageError if there is none)."""
        found = np.nonzero(self.x1 == x1)[0]
        if found.size == 0:
            raise UsageError(f"no station at x1 = {x1:g} m; the stations are "
                             + ", ".join(f"{x:g}" for x in self.x1))
        return int(found[0])

    def long_rows(self):
        """The long format as a dict of equal-length columns (station by station)."""
        m, n = self.time.size, self.x1.size
        columns = {"station_x1": np.repeat(self.x1, m), "time": np.tile(self.time, n)}
        for name in SERIES:
            columns[name] = getattr(self, name).T.reshape(-1)
        return columns

    def dataframe(self):
        """The long format (one row per station and step) as a pandas DataFrame; needs pandas
        (Debian: python3-pandas)."""
        try:
            import pandas
        except ImportError as e:
            raise UsageError("Stations.dataframe() needs pandas (apt-get install "
                             "python3-pandas); the arrays are in .x1, .time, .slip_rate, ...") from e
        return pandas.DataFrame(self.long_rows(), columns=COLUMNS)


def parse_stations_csv(text):
    """`Stations` from the CSV that `slipfront stations --csv` and the server write."""
    threshold, rupture = math.nan, {}
    for line in text.splitlines():
        if not line.startswith("#"):
            continue
        found = _THRESHOLD.search(line)
        if found:
            threshold = float(found.group(1))
        found = _RUPTURE.match(line)
        if found:
            rupture[float(found.group(1))] = float(found.group(2))
    body = "\n".join(line for line in text.splitlines() if not line.startswith("#"))
    table = np.loadtxt(io.StringIO(body), delimiter=",", skiprows=1, ndmin=2)
    header = body.split("\n", 1)[0].split(",")
    if header != COLUMNS:
        raise UsageError(f"not a slipfront stations CSV: header {header}")
    x1 = np.array(list(dict.fromkeys(table[:, 0].tolist())))
    n = x1.size
    m = table.shape[0] // n if n else 0
    if n * m != table.shape[0]:
        raise UsageError(f"stations CSV: {table.shape[0]} rows is not stations x steps")

    def series(column):
        return table[:, column].reshape(n, m).T.copy()  # station by station -> [m, n]

    return Stations(x1=x1, time=table[:m, 1].copy(), slip=series(2), slip_rate=series(3),
                    shear_traction=series(4), normal_traction=series(5),
                    rupture_time=np.array([rupture.get(x, math.nan) for x in x1]),
                    rupture_threshold=threshold)


def job_stations(api, job_id):
    """The stations of a finished job, from the server's CSV (no HDF5 download)."""
    return parse_stations_csv(api.stations_csv(job_id))


def load_stations(path):
    """The stations of a local result file (h5py); UsageError if it has none."""
    import h5py

    with h5py.File(path, "r") as f:
        if "stations" not in f:
            raise UsageError(f"{path} has no stations (its job lists none)")
        s = f["stations"]
        return Stations(x1=s["x1"][()], time=s["time"][()], slip=s["slip"][()],
                        slip_rate=s["slip_rate"][()], shear_traction=s["shear_traction"][()],
                        normal_traction=s["normal_traction"][()],
                        rupture_time=s["rupture_time"][()],
                        rupture_threshold=float(s.attrs["rupture_threshold"]))


def summary_rows(st):
    """Per station, as the metrics' `stations` (docs/metrics.md): x1, rupture_time (None if
    never), the peak |V| and its first time, the slip at the last step."""
    def number(v):
        return None if v != v else float(v)  # NaN: null
    rows = []
    for k, (x, t) in enumerate(zip(st.x1, st.rupture_time)):
        rate = np.abs(st.slip_rate[:, k]) if st.time.size else np.array([])
        peak = int(np.argmax(rate)) if rate.size else None
        rows.append({"x1": float(x), "rupture_time": number(t),
                     "peak_slip_rate": None if peak is None else float(rate[peak]),
                     "peak_time": None if peak is None else float(st.time[peak]),
                     "final_slip": float(st.slip[-1, k]) if st.time.size else None})
    return rows
