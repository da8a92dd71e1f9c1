"""Validates an FMU with FMPy and simulates it there, for tests/integration/fmi.rs.

usage: simulate.py FMU OUT.csv STOP STEP TOLERANCE [input=NAME,AMPLITUDE,FREQUENCY] [NAME=VALUE ...]

Prints FMPy's validation problems (none expected) and exits with 1 if there are any. Writes
every Float64 variable that is not a parameter or an input, at each communication point, to
OUT.csv. With `input=...`, the input NAME follows AMPLITUDE * sin(FREQUENCY * t), given to FMPy
as a table at the communication points (FMPy interpolates it linearly, so at those points it
takes the table's values). Each NAME=VALUE is a start value FMPy sets before initialisation.
"""

import sys

import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

fmu, out, stop, step, tolerance = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:6])

problems = validate_fmu(fmu)
for problem in problems:
    print("validation:", problem)
if problems:
    sys.exit(1)

description = read_model_description(fmu)
names = [
    v.name
    for v in description.modelVariables
    if v.type in ("Float64", "Real") and v.causality not in ("parameter", "independent", "input")
]

signals = None
start_values = {}
for argument in sys.argv[6:]:
    key, value = argument.split("=", 1)
    if key != "input":
        start_values[key] = float(value)
        continue
    name, amplitude, frequency = value.split(",")
    amplitude, frequency = float(amplitude), float(frequency)
    times = np.arange(round(stop / step) + 1) * step
    signals = np.array(
        list(zip(times, amplitude * np.sin(frequency * times))),
        dtype=[("time", np.float64), (name, np.float64)],
    )

result = simulate_fmu(
    fmu,
    stop_time=stop,
    output_interval=step,
    relative_tolerance=tolerance,
    input=signals,
    start_values=start_values,
    output=names,
    validate=True,
)
with open(out, "w") as f:
    f.write(",".join(result.dtype.names) + "\n")
    for row in result:
        f.write(",".join(repr(float(x)) for x in row) + "\n")
print(f"{len(result)} samples of {len(names)} variables")
