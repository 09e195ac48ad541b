#!/usr/bin/python3
"""Total and kinetic energy of the colliding disks against time
(scripts/colliding_disks_study.sh): one velocity field and each contact
law, MUSL, h = 0.05, CFL 0.4."""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

work, out = sys.argv[1], sys.argv[2]
fig, ax = plt.subplots(figsize=(6.5, 4.2))
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for k, law in enumerate(["none", "no separation", "frictionless", "Coulomb"]):
    s = pd.read_csv(os.path.join(work, f"stats_{law.replace(' ', '_')}_MUSL_20_0.4.txt"),
                    sep=r"\s+")
    e0 = s.total_energy.iloc[0]
    ax.plot(s.time, s.total_energy / e0, "-", color=colours[k],
            label=f"{law}: total")
    ax.plot(s.time, s.kinetic_energy / e0, "--", color=colours[k],
            label=f"{law}: kinetic")
ax.set_xlabel("t [s]")
ax.set_ylabel("energy / initial energy")
ax.set_title("Colliding disks, MUSL, h = 0.05, CFL 0.4", fontsize=9)
ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(out, dpi=120)
