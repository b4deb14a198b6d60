"""Helpers of the pvpython tests: checks that are counted and reported, and an abort on cue."""
import sys

_checks, _failures = [], []


def check(condition, message):
    _checks.append(message)
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        _failures.append(message)


def finish():
    """The closing 'N passed, N failed' line (read by CI), and the exit code."""
    print("%d passed, %d failed" % (len(_checks) - len(_failures), len(_failures)))
    sys.exit(1 if _failures else 0)


def abort_at(algorithm, event, after=0.0):
    """Aborts the algorithm at its event-th progress event, counting those at a progress of `after` or
    more (Shrink Wrap's steps come after its setup, from 0.3), once; returns the observer's tag."""
    seen = [0]

    def on_progress(caller, _):
        if caller.GetProgress() >= after:
            seen[0] += 1
        if seen[0] == event:
            seen[0] += 1
            caller.AbortExecuteOn()

    return algorithm.AddObserver("ProgressEvent", on_progress)


def messages_of(proxy, run):
    """What the proxy's filter said while `run()` ran: its error and warning messages, joined."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.vtkCommonCore import VTK_STRING

    said = []

    @calldata_type(VTK_STRING)
    def on_message(caller, event, message):
        said.append(message)

    algorithm = proxy.GetClientSideObject()
    tags = [algorithm.AddObserver(event, on_message) for event in ("ErrorEvent", "WarningEvent")]
    try:
        run()
    finally:
        for tag in tags:
            algorithm.RemoveObserver(tag)
    return " ".join(said)
