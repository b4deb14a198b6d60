"""pvpython test of point clouds (issue #13): a sphere and a torus sampled as points wrap to a closed,
manifold surface of the right genus that lies on the sampled shape (distances both ways on points
sampled over both surfaces, as the wrap benchmark measures them, in % of the diagonal); the wrap's
Distance array is the distance to the nearest input point; a noisy sphere (noise of 0.25% of the
diagonal) and a noisy thin ring (0.5%) wrap inside their noise bands; a sphere sampled 4 times
sparser on one side than the other (a scan's far side) wraps to one layer, not entered; a cloud is measured once while its points stay (a run after a property changed wraps as a new
filter does, and changed points are measured anew); Mesh Signed Distance gives the unsigned
distance to the points, and Input Geometry chooses polygons, points or both of a mixed input (for both filters); bad point input gets a clear error and an empty output, and the pipeline
lives on.

Usage: pvpython TestPointClouds.py <ShrinkWrap plugin .so>
"""
import math
import sys

import numpy as np
from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import reference, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkDataObject, vtkPolyData, vtkStaticCellLocator, vtkUnstructuredGrid
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline

from checks import check, finish

LoadPlugin(sys.argv[1], ns=globals())
rng = np.random.default_rng(13)


def producer(data):
    """A data object as a pipeline source."""
    source = TrivialProducer()
    source.GetClientSideObject().SetOutput(data)
    return source


def vtk_points(points):
    p = vtkPoints()
    p.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=1))
    return p


def cloud(points, kind=vtkPolyData):
    """A points-only dataset (no cells; a polydata unless `kind` says otherwise) as a pipeline source."""
    data = kind()
    data.SetPoints(vtk_points(points))
    return producer(data)


def with_loose_points(mesh, points):
    """A copy of a mesh with extra points, a vertex cell each (on none of its polygons)."""
    data = vtkPolyData()
    data.DeepCopy(mesh)
    data.GetPointData().Initialize()
    vertices = vtkCellArray()
    for q in points:
        vertices.InsertNextCell(1, [data.GetPoints().InsertNextPoint(q)])
    data.SetVerts(vertices)
    return data


def nearest_point_distance(points, queries):
    """Each query's distance to the nearest of the points (brute force)."""
    return np.array([np.min(np.linalg.norm(points - q, axis=1)) for q in queries])


def wrapped(source):
    wrap = ShrinkWrap(Input=source)
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimePerStep)
    return servermanager.Fetch(wrap)


def on_triangles(points, triangles, count):
    """Points sampled uniformly by area over a triangle surface."""
    a, b, c = points[triangles[:, 0]], points[triangles[:, 1]], points[triangles[:, 2]]
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    t = rng.choice(len(triangles), count, p=area / area.sum())
    u, v = rng.random(count), rng.random(count)
    flip = u + v > 1
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    return a[t] + u[:, None] * (b[t] - a[t]) + v[:, None] * (c[t] - a[t])


def distance_to(mesh, points):
    """Each point's distance to the mesh's triangles."""
    locator = vtkStaticCellLocator()
    locator.SetDataSet(mesh)
    locator.BuildLocator()
    closest, cell, sub, squared = [0.0, 0.0, 0.0], reference(0), reference(0), reference(0.0)
    d = np.empty(len(points))
    for i, q in enumerate(points):
        locator.FindClosestPoint(q, closest, cell, sub, squared)
        d[i] = squared.get() ** 0.5
    return d


def genus(mesh):
    triangles = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]]), axis=1)
    edges = np.unique(edges, axis=0)
    return (2 - (mesh.GetNumberOfPoints() - len(edges) + len(triangles))) // 2, len(edges) * 2 == 3 * len(triangles)


def sphere_points(count):
    x = rng.normal(size=(count, 3))
    return x / np.linalg.norm(x, axis=1)[:, None]


def torus_points(count, ring=1.0, tube=0.35):
    # Uniform by area: the angle around the tube is drawn with density proportional to the radius there.
    u = rng.random(count) * 2 * math.pi
    v = []
    while len(v) < count:
        w = rng.random(count) * 2 * math.pi
        keep = rng.random(count) * (ring + tube) < ring + tube * np.cos(w)
        v.extend(w[keep])
    v = np.array(v[:count])
    r = ring + tube * np.cos(v)
    return np.stack([r * np.cos(u), r * np.sin(u), tube * np.sin(v)], axis=1)


# The stated distance, both ways, in % of the diagonal. Measured at the defaults: mean 0.01-0.03%,
# largest 0.2-0.75% (before the fitted near field, PointSurface.h: mean 0.37-0.43%, the closing's sag).
BAR_MEAN, BAR_LARGEST = 0.1, 1.0
shapes = (
    ("sphere", sphere_points(4000), 0, lambda x: np.abs(np.linalg.norm(x, axis=1) - 1), 2.0),
    ("torus", torus_points(8000), 1,
     lambda x: np.abs(np.hypot(np.hypot(x[:, 0], x[:, 1]) - 1.0, x[:, 2]) - 0.35), 2.7),
)
for name, points, expected_genus, to_shape, diagonal in shapes:
    out = wrapped(cloud(points))
    if out.GetNumberOfPoints() == 0:
        check(False, "%s: a wrap" % name)
        continue
    g, closed = genus(out)
    status = out.GetFieldData().GetAbstractArray("Status").GetValue(0)
    check(status == "ok" and closed and g == expected_genus,
          "%s, %d points: closed, genus %d (status %s, genus %d)" % (name, len(points), expected_genus, status, g))
    wp = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    wt = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    # Wrap to shape: samples over the wrap, their exact distance to the smooth shape; shape to wrap: the
    # input points' distance to the wrap's triangles.
    to = 100 * to_shape(on_triangles(wp, wt, 20000)) / diagonal
    back = 100 * distance_to(out, points[:3000]) / diagonal
    check(to.mean() < BAR_MEAN and to.max() < BAR_LARGEST and back.mean() < BAR_MEAN and back.max() < BAR_LARGEST,
          "%s: wrap to shape mean %.3f%%, largest %.2f%%; points to wrap mean %.3f%%, largest %.2f%% of the "
          "diagonal (bars %.2f%%, %.1f%%)" % (name, to.mean(), to.max(), back.mean(), back.max(), BAR_MEAN, BAR_LARGEST))
    distance = vtk_to_numpy(out.GetPointData().GetArray("Distance"))
    exact = nearest_point_distance(points, wp[:500])
    check(np.allclose(np.abs(distance[:500]), exact, rtol=0, atol=1e-5 * diagonal),
          "%s: the Distance array is the distance to the nearest input point" % name)

def check_inside_noise(name, noisy, sigma, off_shape, expected_genus, largest_bar=None):
    """The wrap of noisy points is closed, of the shape's genus, and on average closer to the shape than
    half the points are (`off_shape`: distances to the shape); with `largest_bar`, none of it farther."""
    out = wrapped(cloud(noisy))
    if out.GetNumberOfPoints() == 0:
        check(False, "%s: a wrap" % name)
        return
    g, closed = genus(out)
    wp = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    wt = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    off = off_shape(on_triangles(wp, wt, 20000))
    band = off_shape(noisy).mean()
    largest_ok = largest_bar is None or off.max() < largest_bar
    check(closed and g == expected_genus and off.mean() < 0.5 * band and largest_ok,
          "%s (sigma %.4f): closed, genus %d; the wrap %.4f off the shape on average, largest %.4f; the points "
          "%.4f (bars: half the points'%s)" % (name, sigma, g, off.mean(), off.max(), band,
                                               "" if largest_bar is None else ", %.4f" % largest_bar))


# Noisy points (issue #13: jitter up to about 0.5% of the diagonal): 20,000 points on the unit sphere
# with Gaussian noise of 0.25% of the diagonal. The wrap lies inside the noise band, not on its bumps:
# its samples are closer to the sphere on average than half the points are (measured: 0.0012 against
# the points' 0.0040), and none is farther than 3 sigma (measured 1.3 sigma).
sigma = 0.0025 * 2.0
check_inside_noise("noisy sphere", sphere_points(20000) + rng.normal(scale=sigma, size=(20000, 3)), sigma,
                   lambda x: np.abs(np.linalg.norm(x, axis=1) - 1), 0, 3 * sigma)

# Noise of 0.5% of the diagonal on a thin part: 200,000 points on a ring whose tube (radius 0.1) is
# thinner than the widths at which its noise lets a plane show, so that on much of it no plane fits.
# The wrap still lies inside the noise band (measured 0.0026 off the tube on average, the points
# 0.0124); driven there by the closed field alone, it lay on the noise's outer envelope (0.0162, 89% of
# it outside the tube: PointSurface::firstLayer).
ring_tube = 0.1
sigma = 0.005 * math.sqrt(2 * (2 * (1 + ring_tube)) ** 2 + (2 * ring_tube) ** 2)
check_inside_noise("noisy thin ring", torus_points(200000, tube=ring_tube) + rng.normal(scale=sigma, size=(200000, 3)),
                   sigma, lambda x: np.abs(np.hypot(np.hypot(x[:, 0], x[:, 1]) - 1.0, x[:, 2]) - ring_tube), 1)

# A scan's density falls away from the scanner: 5,000 points on the unit sphere, kept with a probability
# falling 4 times from one side to the other (their own generator, so that the draws above stay). With
# the Gap Size from the median spacing alone the wrap entered through the sparse side and lined the
# inside too (a second layer: genus 2, twice the vertices); from the sparse part's spacing
# (PointSpacing) it wraps one layer on the sphere, as a uniform cloud.
thin = np.random.default_rng(29)
ramp = thin.normal(size=(40000, 3))
ramp /= np.linalg.norm(ramp, axis=1)[:, None]
ramp = ramp[thin.random(len(ramp)) < 0.25 + 0.75 * 0.5 * (1 + ramp[:, 0])][:5000]
out = wrapped(cloud(ramp))
uniform = wrapped(cloud(sphere_points(5000)))
g, closed = genus(out) if out.GetNumberOfPoints() else (None, False)
radii = np.linalg.norm(vtk_to_numpy(out.GetPoints().GetData()), axis=1) if out.GetNumberOfPoints() else np.zeros(1)
low, high = np.quantile(radii, 0.01), radii.max()
check(len(ramp) == 5000 and closed and g == 0 and low > 0.97 and high < 1.03 and
      out.GetNumberOfPoints() < 1.3 * uniform.GetNumberOfPoints(),
      "a sphere's 5,000 points, 4 times sparser on one side: closed, genus 0 (%s), one layer: 99%% of the vertices "
      "%.3f-%.3f from the centre (0.97-1.03), %d vertices (a uniform cloud's wrap %d; under 1.3 times)"
      % (g, low, high, out.GetNumberOfPoints(), uniform.GetNumberOfPoints()))

# The panel's Field Cell Size for points, before the run (the cloud shown, as in the GUI), is the cell
# the run moves on.
shown_cloud = cloud(sphere_points(3000))
shown_cloud.UpdatePipeline()
planned = ShrinkWrap(Input=shown_cloud)
planned.UpdatePipelineInformation()
shown = planned.FieldCellSize
planned.UpdatePipeline(planned.NumberOfSteps * planned.TimePerStep)
ran = servermanager.Fetch(planned).GetFieldData().GetArray("FieldCellSize").GetValue(0)
check(shown > 0 and shown == ran, "Field Cell Size of points before the run: %.6g, the run's: %.6g" % (shown, ran))

# The panel's Chosen Gap Size and Chosen Edge Length: before the run as after it (field data
# GapSize, TargetEdgeLength, and the summary line), the automatic ones from the points' median
# nearest-neighbour distance (8 and 10 of it, withPointSizes; a uniform cloud's sparse part is its
# median), and a Gap Size set by hand as set.
fd = servermanager.Fetch(planned).GetFieldData()
sample = vtk_to_numpy(shown_cloud.GetClientSideObject().GetOutputDataObject(0).GetPoints().GetData()).astype(float)
squared = ((sample[:, None, :] - sample[None, :, :]) ** 2).sum(axis=2)
np.fill_diagonal(squared, np.inf)
median = np.sort(np.sqrt(squared.min(axis=1)))[len(sample) // 2]
diagonal = np.linalg.norm(sample.max(axis=0) - sample.min(axis=0))
gap, length = planned.ChosenGapSize, planned.ChosenEdgeLength
expected_gap = max(8 * median, 1.5 * shown)
expected_length = min(max(10 * median, diagonal / 200), diagonal / 50)
check(abs(gap - expected_gap) < 1e-9 * gap and abs(length - expected_length) < 1e-9 * length and
      fd.GetArray("GapSize").GetValue(0) == gap and fd.GetArray("TargetEdgeLength").GetValue(0) == length and
      ("Gap Size %.3g" % gap) in fd.GetAbstractArray("Summary").GetValue(0),
      "Chosen Gap Size %.6g (8 median spacings or 1.5 cells: %.6g), Chosen Edge Length %.6g (10 median "
      "spacings within diagonal / 200 and / 50: %.6g), before the run as in the run's field data and summary"
      % (gap, expected_gap, length, expected_length))
planned.GapSize = 0.3
planned.UpdatePipelineInformation()
before = planned.ChosenGapSize
planned.UpdatePipeline(planned.NumberOfSteps * planned.TimePerStep)
check(before == 0.3 and servermanager.Fetch(planned).GetFieldData().GetArray("GapSize").GetValue(0) == 0.3,
      "a Gap Size set by hand is the chosen one (%.6g)" % before)

# The cloud is measured once (spacing, fitted surface and its patches) while its points stay: a run after
# another property changed gives what a new filter gives, and points that change are measured anew
# (their wrap is a new filter's on them).
def fetched_points(wrap):
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimePerStep)
    return vtk_to_numpy(servermanager.Fetch(wrap).GetPoints().GetData()).astype(float)


first, second = sphere_points(2000), 0.7 * sphere_points(2000) + np.array([0.2, 0, 0])  # as many points
changing = cloud(first)
kept = ShrinkWrap(Input=changing)
fetched_points(kept)
kept.AdvectionSpeed = 10.0
again = fetched_points(kept)
anew = fetched_points(ShrinkWrap(Input=cloud(first), AdvectionSpeed=10.0))
changing.GetClientSideObject().GetOutputDataObject(0).SetPoints(vtk_points(second))
changing.GetClientSideObject().Modified()
moved = fetched_points(kept)
moved_anew = fetched_points(ShrinkWrap(Input=cloud(second), AdvectionSpeed=10.0))
same_after_c = again.shape == anew.shape and np.array_equal(again, anew)
same_after_points = moved.shape == moved_anew.shape and np.array_equal(moved, moved_anew)
check(same_after_c and same_after_points,
      "a cloud measured once: after C changed, %d vertices as a new filter's %d (same: %s); after the points "
      "changed, %d as a new filter's %d (same: %s)"
      % (len(again), len(anew), same_after_c, len(moved), len(moved_anew), same_after_points))
# The same for an unstructured grid's points (no cells: no surface is extracted from it), its input
# switched to another such grid with as many points.
on_grid = ShrinkWrap(Input=cloud(first, vtkUnstructuredGrid))
fetched_points(on_grid)
on_grid.Input = cloud(second, vtkUnstructuredGrid)
switched = fetched_points(on_grid)
switched_anew = fetched_points(ShrinkWrap(Input=cloud(second, vtkUnstructuredGrid)))
check(switched.shape == switched_anew.shape and np.array_equal(switched, switched_anew),
      "an unstructured grid's points, the input switched to other points: %d vertices as a new filter's %d"
      % (len(switched), len(switched_anew)))

# Mesh Signed Distance on the sphere's points: unsigned, and the distance to the nearest point.
points = sphere_points(500)
field = servermanager.Fetch(MeshSignedDistance(Input=cloud(points), Resolution=24))
values = vtk_to_numpy(field.GetPointData().GetArray("SignedDistance"))
nodes = np.array([field.GetPoint(i) for i in range(field.GetNumberOfPoints())])
exact = nearest_point_distance(points, nodes)
h = field.GetSpacing()[0]
check(field.GetFieldData().GetArray("Signed").GetValue(0) == 0 and (values >= 0).all() and
      np.all(values >= exact - 1e-5 * h) and np.abs(values - exact).mean() < 0.1 * h,
      "Mesh Signed Distance of points: unsigned, never below the exact distance, mean error %.4f h"
      % (np.abs(values - exact).mean() / h))

# The grid the information pass announces (from the points' bounds alone) is the one the field fills.
algorithm = MeshSignedDistance(Input=cloud(points), Resolution=24).GetClientSideObject()
algorithm.UpdateInformation()
announced = algorithm.GetOutputInformation(0)
announced = (announced.Get(vtkStreamingDemandDrivenPipeline.WHOLE_EXTENT()), announced.Get(vtkDataObject.ORIGIN()),
             announced.Get(vtkDataObject.SPACING()))
algorithm.Update()
made = algorithm.GetOutput()
check(announced == (made.GetExtent(), made.GetOrigin(), made.GetSpacing()),
      "Mesh Signed Distance of points: the grid announced %s, the grid made %s"
      % (announced, (made.GetExtent(), made.GetOrigin(), made.GetSpacing())))

# Input Geometry: a sphere's triangles with three loose points (vertex cells) beside it. Polygons: the
# signed field of the triangles alone; Points: the unsigned distance to the nearest of all points;
# Polygons and Points: the unsigned distance to the nearest triangle or loose point (each against
# brute force: the cell locator over the cells used, never below it, on average within a tenth of a
# cell); Polygons of a cloud: a clear error.
sphere = servermanager.Fetch(Sphere(Radius=1.0, ThetaResolution=24, PhiResolution=24))
loose = np.array([[1.6, 0, 0], [0, -1.5, 0.2], [0.3, 0.2, 1.7]])
mixed = with_loose_points(sphere, loose)
mixed_source = producer(mixed)
all_points = vtk_to_numpy(mixed.GetPoints().GetData()).astype(float)
for choice in ("Polygons", "Points", "Polygons and Points"):
    field = servermanager.Fetch(MeshSignedDistance(Input=mixed_source, Resolution=24, InputGeometry=choice))
    values = vtk_to_numpy(field.GetPointData().GetArray("SignedDistance"))
    nodes = np.array([field.GetPoint(i) for i in range(field.GetNumberOfPoints())])
    h = field.GetSpacing()[0]
    signed = field.GetFieldData().GetArray("Signed").GetValue(0) == 1
    if choice == "Polygons":
        exact = distance_to(sphere, nodes)
        error = np.abs(np.abs(values) - exact)
        ok = signed and values[np.argmin(np.linalg.norm(nodes - loose[0], axis=1))] > 0.4
    elif choice == "Points":
        exact = nearest_point_distance(all_points, nodes)
        error = values - exact
        ok = not signed and (error >= -1e-5 * h).all()
    else:
        exact = distance_to(mixed, nodes)
        error = values - exact
        ok = not signed and (error >= -1e-5 * h).all()
    check(ok and np.abs(error).mean() < 0.1 * h and np.abs(error).max() < 1.0 * h,
          "Mesh Signed Distance, Input Geometry %s: %s, mean error %.4f h, largest %.3f h"
          % (choice, "signed" if signed else "unsigned", np.abs(error).mean() / h, np.abs(error).max() / h))

# Shrink Wrap, Input Geometry Points: the sphere mesh's points wrap as a cloud (its Distance array is
# the distance to the nearest point, not to the triangles); Polygons of a cloud: a clear error.
wrap = ShrinkWrap(Input=producer(sphere), InputGeometry="Points")
wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimePerStep)
out = servermanager.Fetch(wrap)
sphere_points_used = vtk_to_numpy(sphere.GetPoints().GetData()).astype(float)
if out.GetNumberOfPoints() == 0:
    check(False, "Shrink Wrap of a mesh's points: a wrap")
else:
    g, closed = genus(out)
    wp = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    distance = vtk_to_numpy(out.GetPointData().GetArray("Distance"))
    exact = nearest_point_distance(sphere_points_used, wp[:500])
    check(closed and g == 0 and np.allclose(np.abs(distance[:500]), exact, rtol=0, atol=1e-5),
          "Shrink Wrap, Input Geometry Points, of a sphere mesh: closed, genus %d, Distance to the nearest point" % g)
# Polygons and Points: the sphere's triangles and a ball of loose points (vertex cells) bulging out of
# it wrap together: one closed surface of genus 0 that reaches the ball's outer points and lies on the
# sphere; with Polygons the same input wraps the sphere alone, far from the ball's top.
ball = 0.3 * sphere_points(1500) + np.array([1.2, 0, 0])
bulging_source = producer(with_loose_points(sphere, ball))
outer = ball[np.linalg.norm(ball, axis=1) > 1.05]  # the ball's points outside the sphere
on_sphere = vtk_to_numpy(sphere.GetPoints().GetData()).astype(float)
on_sphere = on_sphere[np.linalg.norm(on_sphere - [1.2, 0, 0], axis=1) > 0.45]  # away from the ball
diagonal = np.linalg.norm(np.ptp(np.vstack([on_sphere, ball]), axis=0))
for choice in ("Polygons and Points", "Polygons"):
    wrap = ShrinkWrap(Input=bulging_source, InputGeometry=choice)
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimePerStep)
    out = servermanager.Fetch(wrap)
    if out.GetNumberOfPoints() == 0:
        check(False, "Shrink Wrap, Input Geometry %s: a wrap" % choice)
        continue
    g, closed = genus(out)
    to_ball = 100 * distance_to(out, outer) / diagonal
    to_sphere = 100 * distance_to(out, on_sphere) / diagonal
    if choice == "Polygons":
        check(closed and g == 0 and to_ball.max() > 5 and to_sphere.mean() < 0.2,
              "Shrink Wrap, Input Geometry Polygons, of a sphere with loose points: the sphere alone (the ball's top "
              "%.1f%% of the diagonal away, the sphere %.3f%%)" % (to_ball.max(), to_sphere.mean()))
    else:
        check(closed and g == 0 and to_ball.mean() < 0.2 and to_ball.max() < 1.0 and to_sphere.mean() < 0.2,
              "Shrink Wrap, Input Geometry Polygons and Points: closed, genus %d; the ball's outer points %.3f%% of the "
              "diagonal from the wrap on average, largest %.2f%%; the sphere's vertices %.3f%% (bars 0.2%%, 1%%, 0.2%%)"
              % (g, to_ball.mean(), to_ball.max(), to_sphere.mean()))

for name, make, source in (("Mesh Signed Distance", MeshSignedDistance, cloud(sphere_points(500))),
                           ("Shrink Wrap", ShrinkWrap, cloud(sphere_points(500)))):
    f = make(Input=source, InputGeometry="Polygons")
    said_errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        said_errors.append(message)

    f.GetClientSideObject().AddObserver("ErrorEvent", on_error)
    f.UpdatePipeline()
    check(servermanager.Fetch(f).GetNumberOfPoints() == 0 and "Input Geometry is Polygons" in " ".join(said_errors),
          "%s, Input Geometry Polygons, of points: a clear error, an empty output" % name)

# Bad point input: a clear error and an empty output; then the same filter wraps a good cloud.
bad = (("one point", [[1, 2, 3]], "coincide"), ("all points equal", [[1, 2, 3]] * 5, "coincide"),
       ("collinear points", [[t, 2 * t, 0] for t in np.linspace(0, 1, 50)], "on a line"),
       ("coplanar points", [[a, b, 0.5] for a in np.linspace(0, 1, 20) for b in np.linspace(0, 1, 20)], "in a plane"),
       ("a NaN point", [[0, 0, 0], [math.nan, 1, 1], [1, 0, 1], [0, 1, 1]], "NaN"))
for name, coordinates, said in bad:
    source = cloud(np.array(coordinates, dtype=float))
    source.UpdatePipeline()  # shown first, as in the GUI: the panel's sizes are planned on these points
    wrap = ShrinkWrap(Input=source)
    said_errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        said_errors.append(message)

    wrap.GetClientSideObject().AddObserver("ErrorEvent", on_error)
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimePerStep)
    text = " ".join(said_errors)
    out = servermanager.Fetch(wrap)
    sizes = (wrap.FieldCellSize, wrap.ChosenGapSize, wrap.ChosenEdgeLength)
    check(out.GetNumberOfPoints() == 0 and said in text and all(math.isfinite(v) and v >= 0 for v in sizes),
          "Shrink Wrap of %s: an error that says '%s', an empty output, the panel's sizes finite (%s)"
          % (name, said, sizes))
    wrap.Input = cloud(sphere_points(2000))
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimePerStep)
    # Its input was not computed when its information was updated (nothing planned): the panel's
    # sizes are the run's once read again, as the field data holds them.
    good = servermanager.Fetch(wrap)
    wrap.UpdatePropertyInformation()
    ran_gap = good.GetFieldData().GetArray("GapSize").GetValue(0)
    check(good.GetNumberOfPoints() > 0 and ran_gap > 0 and wrap.ChosenGapSize == ran_gap and
          wrap.ChosenEdgeLength == good.GetFieldData().GetArray("TargetEdgeLength").GetValue(0),
          "... and the pipeline lives on: it wraps a sphere's points (its Gap Size %.4g; the panel's, read "
          "again after the run, %.4g)" % (ran_gap, wrap.ChosenGapSize))

finish()
