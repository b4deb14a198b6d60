"""pvpython: what crashed ParaView in issue #8, done as a user would from a script.

Usage: pvpython TestBadInput.py <ShrinkWrap plugin .so>
Multiblock inputs (Group Datasets) into both filters, optional ports cleared, a starved step cache
scrubbed back, absurd step counts and times, corrupt starting surfaces and fields, huge coordinates,
aborts. Each must give a correct result or an error and an empty output; the process must live.
"""
import math
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

from checks import abort_at, check, finish, messages_of

plugin = sys.argv[1]



def fetched(proxy, time=None):
    if time is None:
        proxy.UpdatePipeline()
    else:
        proxy.UpdatePipeline(time)
    return servermanager.Fetch(proxy)


def step_of(data):
    array = data.GetFieldData().GetArray("StepIndex")
    return array.GetValue(0) if array else -1


def computed(proxy):
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty("NumberOfComputedSteps").GetData()


def program(script, output_type):
    """A ProgrammableSource with the given script (a corrupt file, as a reader might give one). Its script
    runs in this module's namespace with numpy's names: no global here may be called like one of them."""
    source = ProgrammableSource(OutputDataSetType=output_type)
    source.Script = script
    return source


LoadPlugin(plugin, ns=globals())
sphere = Sphere(ThetaResolution=16, PhiResolution=16)
cone = Cone(Center=[3, 0, 0], Resolution=12)

# Group Datasets -> Mesh Signed Distance crashed ParaView: now one field of both meshes.
group = GroupDatasets(Input=[sphere, cone])
field = MeshSignedDistance(Input=group, Resolution=32)
data = fetched(field)
values = data.GetPointData().GetArray("SignedDistance")
check(data.GetNumberOfPoints() > 0 and values.GetRange()[0] < 0,
      "Group Datasets -> Mesh Signed Distance: one field (%d nodes, min %.3f)"
      % (data.GetNumberOfPoints(), values.GetRange()[0] if values else float("nan")))
wrap = ShrinkWrap(Input=group, NumberOfSteps=10, Resolution=32, StartingShape="Icosphere", Remeshing=0)
data = fetched(wrap)
check(data.IsA("vtkMultiBlockDataSet") and data.GetNumberOfBlocks() == 2 and
      all(data.GetBlock(b).GetNumberOfPoints() == 642 for b in range(2)),
      "Group Datasets -> Shrink Wrap: a wrap per block")

# A block of tetrahedra counts by its outer surface (as Extract Surface gives it): one field of both.
mixed = GroupDatasets(Input=[sphere, Delaunay3D(Input=sphere)])
mixed_field = MeshSignedDistance(Input=mixed, Resolution=32)
check(fetched(mixed_field).GetNumberOfPoints() > 0, "a block of tetrahedra -> Mesh Signed Distance: a field")
data = fetched(ShrinkWrap(Input=mixed, NumberOfSteps=3, Resolution=32, StartingShape="Icosphere", Remeshing=0))
check(data.GetBlock(0).GetNumberOfPoints() == 642, "a block of tetrahedra beside a mesh -> Shrink Wrap: the mesh wrapped")

# Optional ports can be cleared.
lone = ShrinkWrap(Input=sphere, NumberOfSteps=5, Resolution=32, StartingShape="Icosphere", Remeshing=0)
tight = MeshSignedDistance(Input=sphere, Resolution=16, OffsetFactor=0)
lone.DistanceField = tight
check(fetched(lone).GetNumberOfPoints() == 0, "a field too tight for the start: empty output")
lone.DistanceField = None
check(lone.GetClientSideObject().GetNumberOfInputConnections(1) == 0 and fetched(lone).GetNumberOfPoints() == 642,
      "Distance Field set to None: disconnected, the wrap runs")
lone.InitialSurface = Sphere(Radius=0.3)
fetched(lone)
lone.InitialSurface = None
check(lone.GetClientSideObject().GetNumberOfInputConnections(2) == 0 and fetched(lone).GetNumberOfPoints() == 642,
      "Initial Surface set to None: disconnected")

# Cache Memory Limit 1 MiB, Subdivision Level 6, 40 steps: played to the end, then step 7 (SIGFPE before).
starved = ShrinkWrap(Input=sphere, SubdivisionLevel=6, NumberOfSteps=40, CacheMemoryMiB=1, Resolution=32, StartingShape="Icosphere", Remeshing=0)
tau = starved.TimePerStep
for k in range(41):
    starved.UpdatePipeline(k * tau)
data = fetched(starved, 7 * tau)
fresh = fetched(ShrinkWrap(Input=sphere, SubdivisionLevel=6, NumberOfSteps=7, Resolution=32, StartingShape="Icosphere", Remeshing=0))
same = data.GetNumberOfPoints() == fresh.GetNumberOfPoints() and all(
    data.GetPoint(i) == fresh.GetPoint(i) for i in range(0, data.GetNumberOfPoints(), 97))
check(step_of(data) == 7 and same, "a 1 MiB cache scrubbed back to step 7: the same surface as a fresh run")

# Absurd step counts are refused with the label and the range; times far past the end show the
# last step.
lone.NumberOfSteps = 2 ** 31 - 1
said = messages_of(lone, lambda: lone.UpdatePipeline())
lone.UpdatePipelineInformation()
check(len(lone.TimestepValues) == 0 and "Number Of Steps is 2147483647: it must be from 0 to 10000" in said,
      "Number Of Steps 2^31-1: refused (%s), %d time steps advertised" % (said.strip(), len(lone.TimestepValues)))
lone.NumberOfSteps = 5
lone.UpdatePipelineInformation()
for t in (5e7, 1e9, math.inf, math.nan):
    check(step_of(fetched(lone, t)) == 5, "time %g: the last step" % t)
check(step_of(fetched(lone, -math.inf)) == 0, "time -inf: step 0")

# Corrupt starting surfaces and fields (as a broken file would give them): errors, no crash.
bad_ids = program("""
import vtk
points = vtk.vtkPoints()
for p in [(0, 0, 2), (2, 0, -1), (-2, 2, -1), (-2, -2, -1)]:
    points.InsertNextPoint(p)
cells = vtk.vtkCellArray()
for t in [(0, 1, 2), (0, 2, 3), (0, 3, 1), (1, 3, 1000)]:
    cells.InsertNextCell(3, t)
output.SetPoints(points)
output.SetPolys(cells)
""", "vtkPolyData")
lone.InitialSurface = bad_ids
check(fetched(lone).GetNumberOfPoints() == 0, "an InitialSurface naming point 1000: empty output")
lone.InitialSurface = None
short_field = program("""
import vtk
output.SetDimensions(20, 20, 20)
output.SetOrigin(-2, -2, -2)
output.SetSpacing(0.2, 0.2, 0.2)
values = vtk.vtkFloatArray()
values.SetName("SignedDistance")
values.SetNumberOfTuples(100)
values.Fill(1.0)
output.GetPointData().AddArray(values)
""", "vtkImageData")
lone.DistanceField = short_field
check(fetched(lone).GetNumberOfPoints() == 0, "a DistanceField with 100 values for 8000 nodes: empty output")
lone.DistanceField = None

# Coordinates too large for a float field.
far = Transform(Input=sphere)
far.Transform.Scale = [1e160, 1e160, 1e160]
check(fetched(MeshSignedDistance(Input=far, Resolution=16)).GetNumberOfPoints() == 0,
      "a mesh scaled by 1e160: Mesh Signed Distance refuses it")
check(fetched(MeshSignedDistance(Input=sphere, Resolution=16, OffsetFactor=1e300)).GetNumberOfPoints() == 0,
      "Offset Factor 1e300: refused")

# An aborted Mesh Signed Distance computes again after a change.
aborting = MeshSignedDistance(Input=sphere, Resolution=24)
algorithm = aborting.GetClientSideObject()
tag = abort_at(algorithm, 1)
aborting.UpdatePipeline()  # (Fetch would ask again, with a request of its own)
check(algorithm.GetOutputDataObject(0).GetNumberOfPoints() == 0, "Mesh Signed Distance aborted: empty output")
algorithm.RemoveObserver(tag)
aborting.Resolution = 20
check(fetched(aborting).GetNumberOfPoints() == 21 ** 3, "after a change it computes again")

# Every numeric property of both panels, set to NaN, +inf or past its range as a script can set it:
# an error naming the panel's label and its range, an empty output, no time advertised; the
# default again wraps.
def numeric_properties(proxy):
    """(name, label, minimum, maximum) of every settable number the panel shows with a range."""
    found = []
    for name in proxy.ListProperties():
        prop = proxy.GetProperty(name)
        smp = prop.SMProperty
        if smp.GetInformationOnly() or not smp.IsA("vtkSMVectorProperty") or smp.IsA("vtkSMStringVectorProperty"):
            continue
        domain = smp.FindDomain("vtkSMBoundsDomain") or smp.FindDomain("vtkSMDoubleRangeDomain") or \
            smp.FindDomain("vtkSMIntRangeDomain")
        if domain is None or not (domain.IsA("vtkSMDoubleRangeDomain") or domain.IsA("vtkSMIntRangeDomain")):
            continue
        limited = domain.GetMaximumExists(0) and not domain.IsA("vtkSMBoundsDomain")  # bounds: the data's
        found.append((name, smp.GetXMLLabel(), smp.IsA("vtkSMDoubleVectorProperty"),
                      domain.GetMaximum(0) if limited else None))
    return found


sphere_target = Sphere(ThetaResolution=16, PhiResolution=16)
panels = {"Shrink Wrap": ShrinkWrap(Input=sphere_target, NumberOfSteps=3, Resolution=48),
          "Mesh Signed Distance": MeshSignedDistance(Input=sphere_target, Resolution=24)}
for panel, proxy in panels.items():
    described = numeric_properties(proxy)
    check(len(described) >= (20 if panel == "Shrink Wrap" else 4),
          "%s: %d numeric properties with a range" % (panel, len(described)))
    for name, label, is_double, maximum in described:
        kept = list(proxy.GetProperty(name))
        explicit = name in ("OutputBounds", "OutputDimensions")  # read with Use Explicit Grid only
        if explicit:
            proxy.UseExplicitGrid = 1
        values = [math.nan, math.inf, -math.inf] if is_double else []
        if maximum is not None and maximum < 1e29:
            values.append(maximum * 1000 + 1 if is_double else int(maximum) * 1000 + 1)
        for value in values:
            proxy.GetProperty(name).SetData([value] * len(kept))
            said = messages_of(proxy, lambda: proxy.UpdatePipeline())
            proxy.UpdatePipelineInformation()
            times = list(getattr(proxy, "TimestepValues", []) or [])
            points = proxy.GetDataInformation().GetNumberOfPoints()
            check("%s is " % label in said and "it must be" in said and points == 0 and
                  not [t for t in times if not math.isfinite(t)],
                  "%s: %s = %g refused (%s), empty output, %d times advertised"
                  % (panel, label, value, said[said.find(label):].split("\n")[0], len(times)))
        proxy.GetProperty(name).SetData(kept)
        if explicit:
            proxy.UseExplicitGrid = 0
    said = messages_of(proxy, lambda: proxy.UpdatePipeline())
    check(proxy.GetDataInformation().GetNumberOfPoints() > 0, "%s: the defaults again give an output" % panel)

finish()
