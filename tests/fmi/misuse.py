"""Bad use of a dirac FMU through FMI's C functions, for tests/integration/fmi.rs.

usage: misuse.py DRIVEN_PENDULUM.fmu [DRIVEN_PENDULUM_FMI2.fmu]

Each check calls the FMU the wrong way through FMPy's bindings and expects the status FMI
prescribes (fmi3Error, or fmi3Discard for a step that cannot be taken), a message in the log
naming the cause, and the instance still usable where FMI allows it. The process surviving to
the end is itself part of the test. Prints one line per check; exits with 1 on the first
failure.
"""

import shutil
import sys
from ctypes import byref

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi3 import (
    FMU3Slave,
    fmi3Boolean,
    fmi3Float64,
    fmi3LogMessageCallback,
)

OK, DISCARD, ERROR = 0, 2, 3

fmu_path = sys.argv[1]
description = read_model_description(fmu_path)
vr = {v.name: v.valueReference for v in description.modelVariables}
unzipped = extract(fmu_path)
messages = []


def log(env, status, category, message):
    messages.append((status, category.decode(), message.decode()))


def check(what, condition, detail=""):
    if not condition:
        print(f"FAILED: {what} {detail}")
        sys.exit(1)
    print(f"ok: {what}")


def status_of(call):
    """The status of an FMI call: 0 if FMPy did not raise, the raised status otherwise."""
    messages.clear()
    try:
        call()
        return OK
    except FMICallException as e:
        return e.status


def expect(what, call, status, words):
    """`call` returns `status` and logs a message containing `words`."""
    got = status_of(call)
    logged = " | ".join(m for _, _, m in messages)
    check(what, got == status and words in logged, f"status {got}, log: {logged!r}")


def new_instance(**kwargs):
    fmu = FMU3Slave(
        guid=kwargs.pop("guid", description.guid),
        unzipDirectory=unzipped,
        modelIdentifier=description.coSimulation.modelIdentifier,
        instanceName="misuse",
    )
    fmu.instantiate(logMessage=log)
    return fmu


def do_step(fmu, t, h):
    """fmi3DoStep's status and lastSuccessfulTime."""
    event, terminate, early, last = fmi3Boolean(), fmi3Boolean(), fmi3Boolean(), fmi3Float64(-1.0)
    messages.clear()
    try:
        fmu.fmi3DoStep(fmu.component, t, h, fmi3Boolean(True), byref(event), byref(terminate), byref(early), byref(last))
        status = OK
    except FMICallException as e:
        status = e.status
    return status, last.value


# A library and a description of different models refuse each other.
messages.clear()
try:
    new_instance(guid="{not-this-model}")
    refused = False
except Exception:
    refused = True
check("a wrong instantiation token is refused", refused and any("instantiation token" in m for _, _, m in messages))

# Model exchange is not offered.
fmu = FMU3Slave(
    guid=description.guid,
    unzipDirectory=unzipped,
    modelIdentifier=description.coSimulation.modelIdentifier,
    instanceName="me",
)
callback = fmi3LogMessageCallback(log)
messages.clear()
handle = fmu.fmi3InstantiateModelExchange(b"me", description.guid.encode(), b"", False, False, None, callback)
check("model exchange is refused with a message", not handle and any("co-simulation only" in m for _, _, m in messages))

fmu = new_instance()

# Calls in the wrong state.
expect("fmi3DoStep before initialisation", lambda: fmu.doStep(0.0, 0.1), ERROR, "not allowed")
expect("fmi3GetFloat64 before initialisation", lambda: fmu.getFloat64([vr["x"]]), ERROR, "not allowed")
expect("fmi3ExitInitializationMode before entering it", fmu.exitInitializationMode, ERROR, "not allowed")

# Parameters are settable before initialisation: a longer rod.
check("a parameter is set before initialisation", status_of(lambda: fmu.setFloat64([vr["l"]], [2.0])) == OK)
expect("a negative tolerance", lambda: fmu.enterInitializationMode(tolerance=-1.0), ERROR, "tolerance")
fmu.enterInitializationMode(tolerance=1e-8, startTime=0.0)
x0 = fmu.getFloat64([vr["x"]])[0]
check("the start state is made consistent with the new length", abs(x0 * x0 + fmu.getFloat64([vr["y"]])[0] ** 2 - 4.0) < 1e-9, f"x = {x0}")
fmu.exitInitializationMode()
check("the parameter reads back", fmu.getFloat64([vr["l"]]) == [2.0])

# Invalid value references and values.
expect("an invalid value reference", lambda: fmu.getFloat64([9999]), ERROR, "value reference 9999")
expect("a value reference of a type the model has none of", lambda: fmu.getInt32([vr["x"]]), ERROR, "no Int32 variable")
expect("a fixed parameter after initialisation", lambda: fmu.setFloat64([vr["m"]], [3.0]), ERROR, "cannot be set")
expect("an output", lambda: fmu.setFloat64([vr["energy"]], [1.0]), ERROR, "cannot be set")
expect("a NaN input", lambda: fmu.setFloat64([vr["f"]], [float("nan")]), ERROR, "cannot be set to NaN")
expect("an unsupported function", fmu.enterEventMode, ERROR, "not supported")
check("the input is unchanged by the refused calls", fmu.getFloat64([vr["f"]]) == [0.0])

# Steps: wrong arguments, then a step that cannot be taken.
status, _ = do_step(fmu, 0.5, 0.1)
check("a step from the wrong time", status == ERROR and "instance is at t = 0" in messages[-1][2], messages)
status, _ = do_step(fmu, 0.0, -0.1)
check("a negative step size", status == ERROR and "not positive" in messages[-1][2], messages)
status, last = do_step(fmu, 0.0, 0.1)
check("a good step", status == OK and last == 0.1, (status, last))
before = fmu.getFloat64([vr["x"], vr["y"], vr["vx"], vr["vy"]])
fmu.setFloat64([vr["f"]], [1e300])
status, last = do_step(fmu, 0.1, 0.1)
check(
    "a step that cannot be taken is discarded, at the last good time",
    status == DISCARD and last == 0.1 and messages and messages[-1][1] == "logStatusDiscard",
    (status, last, messages),
)
print("   logged:", messages[-1][2])
check("the state is where the discarded step began", fmu.getFloat64([vr["x"], vr["y"], vr["vx"], vr["vy"]]) == before)
fmu.setFloat64([vr["f"]], [0.5])
status, last = do_step(fmu, 0.1, 0.1)
check("the simulation goes on after a discarded step", status == OK and abs(last - 0.2) < 1e-15, (status, last))

# FMU state: save, go on, come back; and through its serialised form.
state = fmu.getFMUState()
saved = fmu.getFloat64([vr["time"], vr["x"], vr["y"], vr["lambda(rod)"]])
serialized = fmu.serializeFMUState(state)
do_step(fmu, 0.2, 0.3)
fmu.setFMUState(state)
check("fmi3SetFMUState goes back", fmu.getFloat64([vr["time"], vr["x"], vr["y"], vr["lambda(rod)"]]) == saved)
status, _ = do_step(fmu, 0.2, 0.3)
after_restore = fmu.getFloat64([vr["x"]])
copy = fmu.deserializeFMUState(serialized)
fmu.setFMUState(copy)
check("a deserialised state goes back too", fmu.getFloat64([vr["time"], vr["x"], vr["y"], vr["lambda(rod)"]]) == saved)
do_step(fmu, 0.2, 0.3)
check("and steps as the original did", fmu.getFloat64([vr["x"]]) == after_restore)
expect(
    "bytes that are no FMU state",
    lambda: fmu.deserializeFMUState(b"\x01\x02\x03"),
    ERROR,
    "not a serialised FMU state",
)
garbage = bytes(8 * 5)
expect("a state of the wrong shape", lambda: fmu.setFMUState(fmu.deserializeFMUState(garbage)), ERROR, "does not belong")
fmu.freeFMUState(state)
fmu.freeFMUState(copy)

# After terminating, steps are refused; reset goes back to the start.
fmu.terminate()
expect("a step after fmi3Terminate", lambda: fmu.doStep(0.5, 0.1), ERROR, "not allowed")
fmu.reset()
fmu.enterInitializationMode()
check("reset restores the start values", fmu.getFloat64([vr["l"], vr["time"]]) == [1.0, 0.0])
fmu.exitInitializationMode()

# A null instance is refused, not dereferenced.
check("a null instance", status_of(lambda: fmu.fmi3Terminate(None)) == ERROR)
check("a null instance to free", fmu.fmi3FreeInstance(None) is None)
fmu.freeInstance()

shutil.rmtree(unzipped, ignore_errors=True)

# FMI 2.0, through the same library: a call in the wrong state is refused and logged through
# FMI 2.0's logger.
if len(sys.argv) > 2:
    from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE

    def log2(env, name, status, category, message):
        messages.append((status, category.decode(), message.decode()))

    description2 = read_model_description(sys.argv[2])
    unzipped2 = extract(sys.argv[2])
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(log2)
    fmu2 = FMU2Slave(
        guid=description2.guid,
        unzipDirectory=unzipped2,
        modelIdentifier=description2.coSimulation.modelIdentifier,
        instanceName="misuse2",
    )
    fmu2.instantiate(callbacks=callbacks)
    expect("FMI 2.0: fmi2DoStep before initialisation", lambda: fmu2.doStep(0.0, 0.1), ERROR, "not allowed")
    fmu2.setupExperiment(tolerance=1e-8)
    fmu2.enterInitializationMode()
    fmu2.exitInitializationMode()
    expect("FMI 2.0: an invalid value reference", lambda: fmu2.getReal([9999]), ERROR, "value reference 9999")
    fmu2.setReal([vr["f"]], [1e300])
    check("FMI 2.0: a step that cannot be taken is discarded", status_of(lambda: fmu2.doStep(0.0, 0.1)) == DISCARD)
    check("FMI 2.0: the last successful time", fmu2.getRealStatus(2) == 0.0)
    fmu2.setReal([vr["f"]], [0.0])
    check("FMI 2.0: and the run goes on", status_of(lambda: fmu2.doStep(0.0, 0.1)) == OK)
    fmu2.terminate()
    fmu2.freeInstance()
    shutil.rmtree(unzipped2, ignore_errors=True)
    print("FMI 2.0 checks passed")
print("all checks passed")
