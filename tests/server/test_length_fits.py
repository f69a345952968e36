"""The length fit of paper Sec. 6 end to end, on records from our own runs with known L
(docs/length-fit.md): `slipfront run` of the paper's scene at n_d = 10 by FE and by BI with a
station at x1 = 6 m, `slipfront stations --csv`, then `slipfront fit-length` and
POST /api/v1/length-fits on a `slipfront serve` on an ephemeral loopback port.

- Above the event's critical length (L = 3e-4 m; the event's L_c by the rule is 3e-5 to 8e-5 m)
  the verdict is "rich enough" and the 95 % interval holds the run's L, noise-free and with
  Gaussian noise on the stress (1 % and 5 % of its range while slipping, 10 seeds each);
- below it (L = 1e-6 m) the verdict is "upper bound", and the bound holds the run's L;
- the CLI and the server answer the same JSON for the same record;
- bad records: 422 with the JSON pointer (JSON) or the line and column (CSV), exit code 2 from
  the CLI with the same words; 400 for a body that is not JSON, 413 above the body limit.

    /usr/bin/python3 tests/server/test_length_fits.py --binary build/slipfront
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from server_harness import Server  # noqa: E402

BINARY = None
FITS = "/api/v1/length-fits"
RICH, BOUNDED = 3e-4, 1e-6


def run_record(binary, directory, method, L, stations=(6,)):
    """The stations CSV of the paper's scene at n_d = 10 with friction L (a run of < 1 s)."""
    job = {"geometry": {"nodes_per_meter": 10}, "friction": {"L": L},
           "stations": {"x1": list(stations)}}
    if method == "spectral_bi":
        job["method"] = "spectral_bi"
    name = os.path.join(directory, f"{method}_{L:g}_" + "_".join(f"{x:g}" for x in stations))
    with open(name + ".json", "w") as f:
        json.dump(job, f)
    subprocess.run([binary, "run", name + ".json", "--output", name + ".h5", "--quiet"],
                   check=True, stdout=subprocess.DEVNULL)
    subprocess.run([binary, "stations", name + ".h5", "--csv", name + ".csv"], check=True)
    with open(name + ".csv") as f:
        return name + ".csv", f.read()


def columns(csv_text):
    """The four columns of a one-station stations CSV as a JSON record."""
    lines = [line for line in csv_text.splitlines() if not line.startswith("#")]
    names = lines[0].split(",")
    values = np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    at = {n: values[:, i] for i, n in enumerate(names)}
    return {"time": at["time"], "slip_rate": at["slip_rate"],
            "contact_pressure": -at["normal_traction"], "frictional_stress": at["shear_traction"]}


def as_json(record):
    return {k: [float(x) for x in v] for k, v in record.items()}


class LengthFits(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.records = {}
        for method in ("fe", "spectral_bi"):
            for L in (RICH, BOUNDED):
                cls.records[method, L] = run_record(BINARY, cls.dir.name, method, L)
        cls.server = Server(BINARY).start()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.terminate()
        cls.server.cleanup()
        cls.dir.cleanup()
        assert code == 0, f"server exit code {code}"

    def cli(self, *args, stdin=None):
        return subprocess.run([BINARY, "fit-length", *args], input=stdin, capture_output=True,
                              text=True, timeout=60)

    def post(self, body):
        return self.server.post(FITS, data=json.dumps(body),
                                headers={"Content-Type": "application/json"}, timeout=60)

    def fit(self, body):
        r = self.post(body)
        self.assertEqual(r.status_code, 200, r.text)
        return r.json()

    def test_cli_and_server_answer_the_same(self):
        path, text = self.records["spectral_bi", RICH]
        cli = self.cli(path, "--json")
        self.assertEqual(cli.returncode, 0, cli.stderr)
        self.assertEqual(json.loads(cli.stdout), self.fit({"record": text}))

    def test_above_the_critical_length_the_fit_recovers_L(self):
        for method in ("fe", "spectral_bi"):
            path, text = self.records[method, RICH]
            answer = self.fit({"record": text})
            fit, verdict = answer["fit"], answer["verdict"]
            low, high = fit["L_interval_95"]
            print(f"[measured] {method}, L = {RICH:g} m: L_m = {fit['L']:.5g} m "
                  f"[{low:.4g}, {high:.4g}], event L_c = {verdict['event_critical_length']:.3g} m,"
                  f" {100 * verdict['power_above_f_m']:.1f} % of the power above f_m = "
                  f"{answer['critical_frequency']['f_m']:.3g} Hz", flush=True)
            self.assertTrue(low <= RICH <= high, fit)
            self.assertLess(abs(fit["L"] / RICH - 1), 0.02)
            self.assertLess(high / low, 1.2)  # the claim is sharp: +-10 % at most
            self.assertTrue(verdict["rich_enough"], verdict)
            self.assertEqual(verdict["L_m_is"], "physical_length")
            self.assertIn("the event is rich enough", verdict["text"])
            self.assertLess(verdict["event_critical_length"], RICH)
            self.assertEqual(answer["record"]["source"], "stations_csv")
            self.assertEqual(answer["record"]["station_x1"], 6)
            # The human report says the same.
            cli = self.cli(path)
            self.assertEqual(cli.returncode, 0, cli.stderr)
            self.assertIn("verdict: the event is rich enough: the interface's physical length "
                          "is L_m = ", cli.stdout)

    def test_noise_on_the_stress_stays_inside_the_interval(self):
        for method in ("fe", "spectral_bi"):
            record = columns(self.records[method, RICH][1])
            stress = record["frictional_stress"]
            slipping = np.abs(record["slip_rate"]) >= 0.01 * np.abs(record["slip_rate"]).max()
            spread = np.ptp(stress[slipping])
            for level, at_least in ((0.01, 9), (0.05, 8)):
                covered, errors = 0, []
                for seed in range(10):
                    noisy = dict(record)
                    rng = np.random.default_rng(seed)
                    noisy["frictional_stress"] = stress + level * spread * rng.standard_normal(
                        stress.size)
                    answer = self.fit({"record": as_json(noisy)})
                    low, high = answer["fit"]["L_interval_95"]
                    covered += low <= RICH <= high
                    errors.append(abs(answer["fit"]["L"] / RICH - 1))
                    self.assertTrue(answer["verdict"]["rich_enough"])
                print(f"[measured] {method}, {100 * level:g} % noise: the interval holds L in "
                      f"{covered} of 10 records, largest error {max(errors):.3f}", flush=True)
                self.assertGreaterEqual(covered, at_least)
                self.assertLess(max(errors), 4 * level)

    def test_below_the_critical_length_the_verdict_is_an_upper_bound(self):
        for method in ("fe", "spectral_bi"):
            path, text = self.records[method, BOUNDED]
            answer = self.fit({"record": text})
            verdict = answer["verdict"]
            print(f"[measured] {method}, L = {BOUNDED:g} m: L_m = {answer['fit']['L']:.3g} m, "
                  f"f_m = {answer['critical_frequency']['f_m']:.3g} Hz, "
                  f"{100 * verdict['power_above_f_m']:.2g} % above, upper bound "
                  f"{verdict['upper_bound']:.3g} m", flush=True)
            self.assertFalse(verdict["rich_enough"], verdict)
            self.assertEqual(verdict["L_m_is"], "upper_bound")
            self.assertIn("the event is not rich enough to measure the length: the physical "
                          f"length is at most {verdict['upper_bound']:.3g} m", verdict["text"])
            self.assertGreaterEqual(verdict["upper_bound"], BOUNDED)
            cli = self.cli(path)
            self.assertEqual(cli.returncode, 0, cli.stderr)
            self.assertIn("is not a measurement of it", cli.stdout)

    def test_a_stations_csv_of_several_stations_needs_one_chosen(self):
        path, text = run_record(BINARY, self.dir.name, "spectral_bi", RICH, stations=(4, 6))
        cli = self.cli(path)
        self.assertEqual(cli.returncode, 2)
        self.assertIn("--station: the record holds 2 stations (x1 = 4, 6 m): choose one",
                      cli.stderr)
        r = self.post({"record": text})
        self.assertEqual(r.status_code, 422)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/station_x1")
        chosen = self.fit({"record": text, "station_x1": 6})
        self.assertEqual(chosen["record"]["station_x1"], 6)
        self.assertEqual(chosen["record"]["stations_in_file"], 2)
        self.assertEqual(self.cli(path, "--station", "6").returncode, 0)

    def test_bad_records_name_the_column_and_the_line(self):
        path, text = self.records["spectral_bi", RICH]
        lines = text.split("\n")
        header = next(i for i, line in enumerate(lines) if not line.startswith("#"))
        cases = []
        bad = list(lines)
        cells = bad[header + 20].split(",")
        cells[3] = "fast"  # slip_rate
        bad[header + 20] = ",".join(cells)
        cases.append(("\n".join(bad), header + 21, 'column "slip_rate": not a number: "fast"'))
        bad = list(lines)
        cells = bad[header + 30].split(",")
        cells[1] = "0"  # time goes back
        bad[header + 30] = ",".join(cells)
        cases.append(("\n".join(bad), header + 31, 'column "time": time must increase'))
        bad = list(lines)
        cells = bad[header + 40].split(",")
        cells[5] = "nan"  # normal_traction
        bad[header + 40] = ",".join(cells)
        cases.append(("\n".join(bad), header + 41,
                      'column "normal_traction": not a finite number: "nan"'))
        for i, (csv, line, words) in enumerate(cases):
            r = self.post({"record": csv})
            self.assertEqual(r.status_code, 422, r.text)
            error = r.json()["errors"][0]
            self.assertEqual(error["pointer"], "/record")
            self.assertIn(f"line {line}, {words}", error["reason"])
            bad_path = os.path.join(self.dir.name, f"bad{i}.csv")
            with open(bad_path, "w") as f:
                f.write(csv)
            cli = self.cli(bad_path)
            self.assertEqual(cli.returncode, 2, cli.stderr)
            self.assertIn(f"{bad_path}: line {line}, {words}", cli.stderr)

        record = as_json(columns(text))
        record["slip_rate"][3] = None
        r = self.post({"record": record})
        self.assertEqual(r.status_code, 422)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/record/slip_rate/3")
        record = as_json(columns(text))
        del record["contact_pressure"]
        self.assertEqual(self.post({"record": record}).json()["errors"][0]["pointer"],
                         "/record/contact_pressure")
        still = as_json(columns(text))
        still["slip_rate"] = [0.0] * len(still["slip_rate"])
        r = self.post({"record": still})
        self.assertEqual(r.status_code, 422)
        self.assertEqual(r.json()["errors"][0]["pointer"], "/record/slip_rate")
        self.assertIn("no slip", r.json()["errors"][0]["reason"])
        short = {k: v[:20] for k, v in as_json(columns(text)).items()}
        r = self.post({"record": short})
        self.assertIn("too short: 20 samples", r.json()["errors"][0]["reason"])
        r = self.post({"record": text, "v_star": 0})
        self.assertEqual(r.json()["errors"][0]["pointer"], "/v_star")
        cli = self.cli(path, "--v-star", "0")
        self.assertEqual(cli.returncode, 2)
        self.assertIn("--v-star: needs a finite number in (0, 1e+06], got \"0\"", cli.stderr)
        r = self.server.post(FITS, data="{not json", headers={"Content-Type": "application/json"})
        self.assertEqual(r.status_code, 400)
        r = self.post({"record": text + "#" * (1 << 20)})
        self.assertEqual(r.status_code, 413)
        cli = self.cli(os.path.join(self.dir.name, "no_such.csv"))
        self.assertEqual(cli.returncode, 1)
        self.assertIn("cannot open", cli.stderr)

    def test_openapi_lists_the_route(self):
        doc = self.server.get("/api/v1/openapi.json").json()
        self.assertIn("post", doc["paths"][FITS])
        self.assertIn("LengthFitRequest", doc["components"]["schemas"])


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--binary", required=True)
    args, rest = parser.parse_known_args()
    BINARY = os.path.abspath(args.binary)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
