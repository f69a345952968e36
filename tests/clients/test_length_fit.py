"""`slipfront-client fit-length` against a real `slipfront serve` (ephemeral loopback port):
the record of a BI run of the paper's scene (L = 3e-4 m, stations at x1 = 4 and 6 m, made by
`slipfront run` and `slipfront stations --csv`), the report and --json (the server's answer),
--station sending one station's rows only (same answer, line numbers kept), --plot, JSON
records, and a bad record's exit code 2 with its line and column.

    /usr/bin/python3 tests/clients/test_length_fit.py --binary build/slipfront
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

from harness import Server, binary_from_argv, run_client
from slipfront_client.length_fit import stations_rows_only

BINARY = None


class ClientLengthFit(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="slipfront-client-length-fit-")
        job = os.path.join(cls.tmp, "job.json")
        with open(job, "w") as f:
            json.dump({"method": "spectral_bi", "geometry": {"nodes_per_meter": 10},
                       "friction": {"L": 3e-4}, "stations": {"x1": [4, 6]}}, f)
        h5, cls.csv = os.path.join(cls.tmp, "run.h5"), os.path.join(cls.tmp, "stations.csv")
        subprocess.run([BINARY, "run", job, "--output", h5, "--quiet"], check=True,
                       stdout=subprocess.DEVNULL)
        subprocess.run([BINARY, "stations", h5, "--csv", cls.csv], check=True)
        cls.server = Server(BINARY).start()

    @classmethod
    def tearDownClass(cls):
        cls.server.stop()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def client(self, *args):
        return run_client("fit-length", *args, server=self.server.base)

    def test_report_and_json_of_one_station(self):
        r = self.client(self.csv, "--station", "6")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("verdict: the event is rich enough: the interface's physical length is L_m = ",
                      r.stdout)
        self.assertIn("(station x1 = 6 m)", r.stdout)
        j = self.client(self.csv, "--station", "6", "--json")
        answer = json.loads(j.stdout)
        low, high = answer["fit"]["L_interval_95"]
        self.assertTrue(low <= 3e-4 <= high, answer["fit"])
        # The CLI of the server's binary reads the whole file and gives the same answer (but
        # for the stations it saw: the client sent one).
        cli = subprocess.run([BINARY, "fit-length", self.csv, "--station", "6", "--json"],
                             capture_output=True, text=True, check=True)
        whole = json.loads(cli.stdout)
        self.assertEqual((whole["record"].pop("stations_in_file"),
                          answer["record"].pop("stations_in_file")), (2, 1))
        self.assertEqual(whole, answer)

    def test_only_the_chosen_stations_rows_are_sent(self):
        with open(self.csv) as f:
            text = f.read()
        sent = stations_rows_only(text, 6.0)
        self.assertEqual(sent.count("\n"), text.count("\n"))  # line numbers kept
        rows = [line for line in sent.split("\n") if line and not line.startswith("#")]
        self.assertTrue(all(line.startswith("6,") for line in rows[1:]), rows[:3])
        self.assertLess(len(sent), 0.6 * len(text))
        self.assertEqual(stations_rows_only("time,slip_rate\n1,2\n", 6.0), "time,slip_rate\n1,2\n")

    def test_a_json_record_and_the_plot(self):
        with open(self.csv) as f:
            lines = [line for line in f if not line.startswith("#")]
        names = lines[0].strip().split(",")
        rows = [dict(zip(names, map(float, line.split(",")))) for line in lines[1:]]
        rows = [r for r in rows if r["station_x1"] == 6]
        record = {"time": [r["time"] for r in rows], "slip_rate": [r["slip_rate"] for r in rows],
                  "contact_pressure": [-r["normal_traction"] for r in rows],
                  "frictional_stress": [r["shear_traction"] for r in rows]}
        path = os.path.join(self.tmp, "record.json")
        with open(path, "w") as f:
            json.dump(record, f)
        png = os.path.join(self.tmp, "fit.png")
        r = self.client(path, "--plot", png, "--json")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(json.loads(r.stdout)["record"]["source"], "json")
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")

    def test_a_bad_record_exits_2_naming_line_and_column(self):
        with open(self.csv) as f:
            lines = f.read().split("\n")
        at = next(i for i, line in enumerate(lines) if line.startswith("6,")) + 5
        cells = lines[at].split(",")
        cells[4] = "strong"  # shear_traction
        lines[at] = ",".join(cells)
        bad = os.path.join(self.tmp, "bad.csv")
        with open(bad, "w") as f:
            f.write("\n".join(lines))
        r = self.client(bad, "--station", "6")
        self.assertEqual(r.returncode, 2, r.stdout)
        self.assertIn(f'line {at + 1}, column "shear_traction": not a number: "strong"', r.stderr)
        r = self.client(self.csv)
        self.assertEqual(r.returncode, 2)
        self.assertIn("choose one", r.stderr)


if __name__ == "__main__":
    BINARY, rest = binary_from_argv(sys.argv[1:])
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
