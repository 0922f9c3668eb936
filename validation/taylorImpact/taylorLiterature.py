"""Reference ranges and thresholds of the Taylor impact study (taylor.py).

doc/benchmarks.md section 3 and issue 10, acceptance 1.
"""

# doc/benchmarks.md 3: Camacho & Ortiz 1997 compilation (Kamoulakos 1990,
# Zhu & Cescotto 1995), at 80 us
LITERATURE = {
    "length_mm": (21.26, 21.49),
    "footRadius_mm": (6.89, 7.24),
    "peakPlasticStrain": (2.5, 3.25),
}
QUANTITIES = {
    "length_mm": "final length [mm]",
    "footRadius_mm": "foot radius [mm]",
    "peakPlasticStrain": "peak equivalent plastic strain",
}
CHECKER_FIELDS = ("pressure", "epsilonP")
CHECKER_FREE = 0.2      # C above this (all cells): not free of checker-board
ORDER_RANGE = (0.5, 4.0)    # observed orders believed for extrapolation
ONSET = 1e-6            # a step raising the total energy by this x E_0
