"""Sample, measure and draw: white noise beside a Poisson disk set.

    /usr/bin/python3 examples/python/blue_noise.py [OUTPUT.png]

Draws each set's points, its averaged periodogram and its radial power, the
spatial view beside the Fourier view (docs/python.md shows the picture).
"""

import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pds  # noqa: E402

output = sys.argv[1] if len(sys.argv) > 1 else "blue_noise.png"
rows = {
    "random": dict(count=1000),
    "dunbar-humphreys": dict(radius=0.025),
}
fig, axes = plt.subplots(len(rows), 3, figsize=(11, 3.8 * len(rows)))
for (method, sizing), (ax_points, ax_spectrum, ax_radial) in zip(rows.items(), axes):
    sets = [pds.generate(method, torus=True, seed=s, **sizing) for s in range(4)]
    power = pds.periodogram(sets, torus=True, max_frequency=48)
    freq, radial, _ = pds.radial_power(sets, torus=True, max_frequency=48)
    ax_points.scatter(sets[0][:, 0], sets[0][:, 1], s=2, c="k")
    ax_points.set(aspect="equal", xlim=(0, 1), ylim=(0, 1), title=f"{method}: {len(sets[0])} points")
    ax_spectrum.imshow(np.log10(np.clip(power, 1e-2, 10)), cmap="gray", extent=(-48, 48, -48, 48), origin="lower")
    ax_spectrum.set(title="periodogram (4 sets, log)", xlabel="kx", ylabel="ky")
    ax_radial.plot(freq, radial, "k-")
    ax_radial.axhline(1, color="grey", lw=0.5)
    ax_radial.set(title="radial power", xlabel="frequency (1 / mean spacing)", ylim=(0, 2.5))
fig.tight_layout()
fig.savefig(output, dpi=80)
print(f"wrote {output}")
