#!/usr/bin/python3
"""The contact of the wave curve from Python: contact fraction against pa/p* for several shapes
m (one continuation per shape, up to full contact), and the pressure at one load.

    PYTHONPATH=build/python /usr/bin/python3 examples/sweep.py --out sweep.png
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import wavecontact as wc  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="sweep.png", help="the PNG to write")
    args = parser.parse_args()

    H1, b1, E = 1.0, 10.0, 1.0
    ratios = np.linspace(0.01, 1.5, 150)  # pa/p* = P/(pi E* H1)
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    for m in (0.0, 0.2, 2.0, 10.0):
        surface = wc.Surface(wc.WavinessParams(H1=H1, b1=b1, m=m, E=E))
        contacts = wc.solve_contact(surface, ratios * np.pi * E * H1, tolerance=1e-8)
        left.plot(ratios, [c.contact_fraction for c in contacts], label=f"m = {m:g}")
    left.set(xlabel="pa / p*", ylabel="contact fraction", title="the contact up to full contact")
    left.grid(alpha=0.3)
    left.legend()

    # The seed's two-scale profile at pa/p* = 0.3: several zones per period.
    rough = wc.Surface(wc.WavinessParams(H1=H1, b1=b1, m=0.0, E=E), [wc.Harmonic(H=0.15, n=8)])
    contact = wc.solve_contact(rough, 0.3 * np.pi * E * H1)
    x = np.linspace(-b1, b1, 4001)
    right.plot(x, contact.pressure(x) / E)
    right.set(xlabel="x [mm]", ylabel="p / E*",
              title=f"H2 = 0.15, n = 8, pa/p* = 0.3: {contact.zones_per_period} zones per period")
    right.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
