"""The reproduction's new pieces that need no server: the filter rule of Fig. 6 and its
inverse, the power spectrum of Fig. 5, which runs Fig. 4-6 draw, and the L search's body.

    /usr/bin/python3 -m unittest discover -s tests/clients -p 'test_unit*.py'
"""

import types
import unittest

import numpy as np

import harness
from slipfront_client import reproduction
from slipfront_client.plots import critical_frequency, filter_response, strength_spectrum
from slipfront_client.reproduction_figures import converged_by_L

assert harness.CLIENTS  # importing harness put clients/ on sys.path


def run(job, L, n_d, status="converged", outcome="arrested", regime=None):
    r = {"job_id": job, "L": L, "n_d": n_d, "job_status": "succeeded", "outcome": outcome,
         "convergence": {"status": status}}
    if regime:
        r["regime"] = regime
    return r


class FilterRule(unittest.TestCase):
    def test_critical_length_attenuates_by_two_percent(self):
        # eq. 6 at the rule's L gives A/A0 = 0.98 at that frequency, whatever f and |V|
        for f, v in ((0.8, 2.4e-3), (20.0, 3e-3), (100.0, 1e-3)):
            L = float(critical_frequency.critical_length(f, 1e-4, v))
            self.assertAlmostEqual(filter_response.amplitude_ratio(f, L, 1e-4, v), 0.98, places=12)
            self.assertAlmostEqual(critical_frequency.frequency_of(L, 1e-4, v), f, places=9)

    def test_the_papers_critical_length_needs_about_eight_hertz(self):
        # by hand: sqrt(1/0.98^2 - 1) = 0.203059; (1e-4 + 2.36e-3) * 0.203059 = 4.99525e-4;
        # / (2 pi 1e-5) = 7.950 Hz (docs/reproduction.md, "The paper's L_c beside ours")
        self.assertAlmostEqual(critical_frequency.frequency_of(1e-5, 1e-4, 2.36e-3), 7.950,
                               delta=0.001)


class Spectrum(unittest.TestCase):
    def test_power_spectrum_peaks_at_the_signal_frequency(self):
        t = np.arange(0, 10, 0.01)
        signal = 11.0 + 0.5 * np.sin(2 * np.pi * 5.0 * t) + 0.1 * t  # a drift is removed
        f, p = strength_spectrum.power_spectrum(t, signal)
        self.assertAlmostEqual(f[int(np.argmax(p[1:])) + 1], 5.0, places=6)


class MeasuredFilter(unittest.TestCase):
    @staticmethod
    def record(strength, t):
        """A Result holding `strength` at a single node x1 = 6 m."""
        from slipfront_client.results import Result
        s = np.asarray(strength, float)[:, None]
        x = np.array([6.0])
        return Result("made-up.h5", x, t, np.zeros_like(s), s, x, x, x)

    def test_half_amplitude_frequency_of_a_known_low_pass_filter(self):
        # The reference: a pulse with content up to 20 Hz; the run: the same pulse through a
        # first-order low-pass filter of corner f_c = 3 Hz, applied exactly in frequency
        # (|H| = 1/sqrt(1 + (f/f_c)^2) = 1/2 at f = sqrt(3) f_c = 5.196 Hz).
        dt, n = 0.025, 1024
        t = np.arange(n) * dt
        pulse = np.exp(-0.5 * ((t - 12.8) / 0.02) ** 2)
        f = np.fft.rfftfreq(n, dt)
        filtered = np.fft.irfft(np.fft.rfft(pulse) / (1 + 1j * f / 3.0), n)
        # offset and the record of the reference a little longer and finer: resampled on the
        # coarser step over the time both cover
        t_fine = np.arange(2 * n + 40) * dt / 2
        reference = self.record(11.0 + np.interp(t_fine, t, pulse), t_fine)
        run = self.record(11.0 + filtered, t)
        fr, ratio = strength_spectrum.amplitude_against(run, reference, 6.0, smooth_bins=1)
        self.assertAlmostEqual(fr[-1], 0.5 / dt, delta=fr[1])  # on the coarser step: 20 Hz
        half = strength_spectrum.half_amplitude_frequency(fr, ratio)
        self.assertAlmostEqual(half, np.sqrt(3) * 3.0, delta=2 * (fr[1] - fr[0]))

    def test_half_amplitude_frequency_is_none_when_the_ratio_stays_above_half(self):
        f = np.linspace(0, 20, 11)
        self.assertIsNone(strength_spectrum.half_amplitude_frequency(f, np.full(11, 0.9)))
        ratio = np.array([1, 1, 0.4, 0.6, 0.3, 0.2, 0.1, 0.1, 0.1, 0.1, 0.1])
        self.assertEqual(strength_spectrum.half_amplitude_frequency(f, ratio), 8.0)


class DrawnRuns(unittest.TestCase):
    def test_coarsest_converged_run_of_each_L_without_coulomb_or_no_rupture(self):
        bi = {"runs": [run("a", 1e-3, 10, outcome="no_rupture"), run("b", 1e-5, 10, "not_converged"),
                       run("c", 1e-5, 20), run("d", 1e-5, 40, "unknown"), run("e", 5e-6, 40),
                       run("f", 5e-6, 20)]}
        search = {"runs": [run("g", 5e-6, 10), run("h", 8e-7, 40),
                           run("i", 3.2e-6, 80, regime="coulomb"),
                           run("j", 3.2e-6, 40, "not_converged", regime="coulomb")]}
        refs, coulomb = converged_by_L(bi, search)
        self.assertEqual({L: r["job_id"] for L, r in refs.items()},
                         {1e-5: "c", 5e-6: "f", 8e-7: "h"})  # the BI study's 5e-6 wins
        self.assertEqual(coulomb["job_id"], "i")


class SearchBody(unittest.TestCase):
    def test_search_body_is_a_bi_search_without_an_L_list(self):
        args = types.SimpleNamespace(quick=False, base={"geometry": {"height": 8, "width": 20}},
                                     search=reproduction.SEARCH, bi_ladder=[10, 20],
                                     bi_n_d_max=320, fresh=False)
        body = reproduction.search_body(args)
        self.assertEqual(body["convergence"], {"search": {"from": 3.2e-6, "factor": 2},
                                               "n_d": [10, 20], "n_d_max": 320})
        self.assertEqual(body["base"], {"geometry": {"width": 20}, "method": "spectral_bi"})


class DampedBody(unittest.TestCase):
    def test_damped_study_is_fe_with_the_mesh_damping_on_the_same_scene(self):
        args = types.SimpleNamespace(quick=False, base={"geometry": {"height": 8}},
                                     damped=reproduction.DAMPED, fresh=True)
        body = reproduction.damped_body(args)
        self.assertEqual(body["base"], {"geometry": {"height": 8}, "fe": {"mesh_damping": 0.1}})
        self.assertEqual(body["convergence"], {"L": [5e-6], "n_d": [20, 40, 80], "n_d_max": 80})
        self.assertTrue(body["fresh"])
        self.assertEqual(args.base, {"geometry": {"height": 8}})  # not changed in place


if __name__ == "__main__":
    unittest.main()
