"""The rock wedge of rock_wedge.tess for a range of joint friction angles: how far it moves.

Run with `tessera --batch examples/wedge_friction_study.py` (or with the module on PYTHONPATH,
`python3 examples/wedge_friction_study.py`). The wedge is settled once at 45 degrees and saved;
each friction angle then starts from that state, runs 3,000 undamped cycles and records the
wedge's displacement every 100 cycles from a callback. Hoek & Bray's limit friction angle for
the two planes is 37.2 degrees: below it the wedge slides out, above it it stands.

Writes wedge_friction.csv (always) and wedge_friction.png (when matplotlib is installed) into the
results folder, with each run's own results in a folder named for its friction angle.
"""
import csv
import os

import numpy as np

import tessera

FRICTIONS = [30, 33, 36, 38, 40, 45]
CYCLES = 3000

# The slope, the two joint planes and the wedge between them (as in rock_wedge.tess).
GEOMETRY = """
dimension 3
tolerance 0.01
material define rock density=2600
joint define rough kn=1e10 ks=1e10 friction=45
joint assign rough
region -15,-10,-20 15,15,0 group=rock material=rock
crack dip=70 ddir=180 origin=0,0,0 name=face
delete at=0,-5,-1
crack dip=50 ddir=140 origin=0,0,-8 name=A
crack dip=55 ddir=230 origin=0,0,-8 name=B
group wedge at=0,1.5,-1
fix all
free group=wedge
gravity 0 0 -9.81
"""

out = tessera.out_dir()
os.makedirs(out, exist_ok=True)
settled = os.path.abspath(os.path.join(out, "settled.state"))

# Settle the wedge on both planes at 45 degrees, once.
m = tessera.Model(out=os.path.join(out, "settle"))
m.command(GEOMETRY)
m.command("damping local 0.8")
m.solve(ratio=1e-5, cycles=50000)
wedge = list(m.groups).index("wedge")
row = int(np.flatnonzero(m.blocks.group == wedge)[0])
m.command(f"save {settled}")

results = {}
for phi in FRICTIONS:
    with tessera.Model(out=os.path.join(out, f"friction_{phi}")) as run:
        run.command(f"restore {settled}")
        start = run.blocks.disp[row].copy()
        run.set_joint("rough", friction=phi)
        run.command("damping none")
        moved = []
        run.on_cycle(lambda model: moved.append(
            (model.cycles, float(np.linalg.norm(model.blocks.disp[row] - start)))), every=100)
        run.cycle(CYCLES)
        results[phi] = moved
        print(f"friction {phi}: the wedge moved {moved[-1][1]:.4f} m in {CYCLES} cycles")

with open(os.path.join(out, "wedge_friction.csv"), "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["friction_deg", "cycle", "displacement_m"])
    for phi, moved in results.items():
        for cycle, d in moved:
            w.writerow([phi, cycle, f"{d:.6e}"])

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed: wedge_friction.csv holds the results")
else:
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for phi, moved in results.items():
        c, d = zip(*moved)
        ax.plot(c, d, label=f"{phi} deg")
    ax.set_xlabel("cycles after the friction change")
    ax.set_ylabel("wedge displacement (m)")
    ax.set_title("Rock wedge: displacement by joint friction (limit 37.2 deg)")
    ax.legend()
    fig.savefig(os.path.join(out, "wedge_friction.png"), dpi=120)
    print("figure", os.path.join(out, "wedge_friction.png"))
