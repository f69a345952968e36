#!/usr/bin/python3
"""Reflection coefficient of the FE block's top against the incidence angle and the wavelength:
the perfectly matched layer (20 elements) and the Lysmer-Kuhlemeyer dashpots, plane P and S
wave packets, against the continuum layer's theory (docs/physics.md "Perfectly matched layer").

Runs the sweep test (tests/solver/fe/absorbing_layer_sweep_test.cpp, a few minutes) or reads
its saved output, prints a markdown table and draws docs/figures/layer_reflection.png.

usage: /usr/bin/python3 bench/layer_reflection.py [--tests build/tests/solver/solver_slow_tests]
           [--from-log saved.txt] [--out docs/figures/layer_reflection.png]
"""
import argparse
import re
import subprocess

LINE = re.compile(r"sweep top=(\w+) wave=(\w) angle=([\d.]+) wavelength=([\d.]+) omega_dx=([\d.]+) "
                  r"R=([\deE.+-]+) theory=([\deE.+-]+) energy=([\deE.+-]+)")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tests", default="build/tests/solver/solver_slow_tests")
    ap.add_argument("--from-log")
    ap.add_argument("--out", default="docs/figures/layer_reflection.png")
    args = ap.parse_args()
    if args.from_log:
        text = open(args.from_log).read()
    else:
        text = subprocess.run([args.tests, "--gtest_filter=AbsorbingLayerSweep.*"], check=True,
                              capture_output=True, text=True).stdout
    rows = [(m[0], m[1], float(m[2]), float(m[3]), float(m[4]), float(m[5]), float(m[6]), float(m[7]))
            for m in LINE.findall(text)]
    print("| top | wave | wavelength [dx] | omega dx/c_s | angle [deg] | R measured | R theory (layer) | energy balance |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for top, wave, angle, lam, om, r, th, e in rows:
        print(f"| {top} | {wave} | {lam:g} | {om:.3f} | {angle:.1f} | {r:.2e} | {th:.2e} | {e:.0e} |")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    colors = {10.0: "tab:blue", 20.0: "tab:orange", 40.0: "tab:green"}
    for ax, wave in zip(axes, ("P", "S")):
        for lam in (10.0, 20.0, 40.0):
            pts = [(a, r, th) for top, w, a, l, om, r, th, e in rows if top == "pml" and w == wave and l == lam]
            if not pts:
                continue
            ax.semilogy([p[0] for p in pts], [p[1] for p in pts], "o-", color=colors[lam],
                        label=f"PML, {lam:g} dx a wavelength")
            if lam == 20.0:
                ax.semilogy([p[0] for p in pts], [p[2] for p in pts], "k--", label="PML theory (continuum round trip)")
        pts = [(a, r) for top, w, a, l, om, r, th, e in rows if top == "dashpots" and w == wave]
        if pts:
            ax.semilogy([p[0] for p in pts], [p[1] for p in pts], "s:", color="tab:red", label="dashpots, 20 dx")
        ax.set_xlabel("incidence angle [deg]")
        ax.set_title(f"{wave} wave")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("reflection coefficient sqrt(E_back / E_in)")
    axes[1].legend(fontsize=8)
    fig.suptitle("Top of the FE block: perfectly matched layer of 20 elements vs Lysmer-Kuhlemeyer dashpots")
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print(f"\nchart: {args.out}")


if __name__ == "__main__":
    main()
