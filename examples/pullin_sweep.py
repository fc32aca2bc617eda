# %% [markdown]
# # A cantilever's pull-in voltage over its length
# Paste the cells into Jupyter, or run the whole script:
#   bash cmake/bootstrap.sh python examples/pullin_sweep.py [PNG]
# The cantilever-pullin scene (200 x 20 x 2 um silicon over a 2 um gap) is swept over 21
# lengths on every core; the plot shows the pull-in voltage and the L^-2 law it follows.

# %%
import sys

import matplotlib

if "ipykernel" not in sys.modules:
    matplotlib.use("Agg")  # no display needed outside a notebook
import matplotlib.pyplot as plt
import numpy as np

import cosmems

scene = cosmems.Scene("cantilever-pullin")
summary = cosmems.sweep(scene, vary={"structure.length": "100e-6:300e-6:21"},
                        spec="pullin_voltage_v>=10")
rows = [row for row in summary["rows"] if row["status"] == "ok"]
length = np.array([row["parameters"]["structure.length"] for row in rows])
voltage = np.array([row["result"]["pullin_voltage_v"] for row in rows])
print(f"{len(rows)} pull-in analyses in {summary['wall_time_s']:.3f} s; "
      f"yield of V >= 10 V: {summary['yield']:.2f}")

# %% [markdown]
# Beam stiffness goes as L^-3 and electrode area as L, so V_PI = c L^-2: the fitted exponent
# tells how closely the computed voltages follow it.

# %%
exponent, log_c = np.polyfit(np.log(length), np.log(voltage), 1)
print(f"fitted V_PI ~ L^{exponent:.4f}")

figure, axes = plt.subplots(figsize=(6, 4))
axes.plot(length * 1e6, voltage, "o", label="cosmems")
axes.plot(length * 1e6, np.exp(log_c) * length**exponent, "-",
          label=f"fit: L^{exponent:.3f}")
axes.axhline(10.0, color="red", linestyle=":", label="spec: 10 V")
axes.set_xlabel("length (um)")
axes.set_ylabel("pull-in voltage (V)")
axes.set_yscale("log")
axes.legend()
axes.set_title("Cantilever pull-in voltage")
figure.tight_layout()
output = sys.argv[1] if len(sys.argv) > 1 and not sys.argv[1].startswith("-") else "pullin_sweep.png"
figure.savefig(output, dpi=100)
print(f"plot written to {output}")
