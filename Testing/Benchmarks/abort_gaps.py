"""How soon Shrink Wrap can stop: the gaps between its progress events, and an abort's latency.

  pvpython abort_gaps.py ShrinkWrap.so mesh.obj N RESOLUTION ABORT_AFTER_S

Wraps the mesh at Target Edge Length diagonal / N on a field of RESOLUTION, observing ProgressEvent;
at the first event past ABORT_AFTER_S seconds it sets AbortExecute. Prints when the update returned
and the longest gaps between events (seconds, when, the progress there): an abort waits at most the
gap it falls in.
"""
import sys
import time

from paraview.simple import *  # noqa: F403 (ShrinkWrap comes with the plugin)

LoadPlugin(sys.argv[1], remote=False, ns=globals())
reader = OpenDataFile(sys.argv[2])
reader.UpdatePipeline()
b = reader.GetDataInformation().GetBounds()
diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
wrap = ShrinkWrap(Input=reader)
wrap.TargetEdgeLength = diagonal / float(sys.argv[3])
wrap.Resolution = int(sys.argv[4])
after = float(sys.argv[5])
algorithm = wrap.GetClientSideObject()
start = time.time()
events = []
aborted = []


def observe(caller, event):
    t = time.time() - start
    events.append((t, algorithm.GetProgress()))
    if not aborted and t > after:
        aborted.append(t)
        algorithm.AbortExecuteOn()


algorithm.AddObserver("ProgressEvent", observe)
wrap.UpdatePipeline(1e9)
end = time.time() - start
gaps = sorted(((events[i][0] - events[i - 1][0], events[i - 1][0], events[i - 1][1])
               for i in range(1, len(events))), reverse=True)
if aborted:
    print("abort set at %.2f s, the update returned at %.2f s (%.2f s later)" % (aborted[0], end, end - aborted[0]))
print("%d progress events; the longest gaps: %s" % (
    len(events), ", ".join("%.2f s at %.1f s (progress %.3f)" % g for g in gaps[:5])))
