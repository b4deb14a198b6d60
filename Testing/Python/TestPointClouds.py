"""pvpython test of point clouds (issue #13): a sphere and a torus sampled as points wrap to a closed,
manifold surface of the right genus that lies on the sampled shape (distances both ways on points
sampled over both surfaces, as the wrap benchmark measures them, in % of the diagonal); the wrap's
Distance array is the distance to the nearest input point; a noisy sphere wraps inside its noise
band; Mesh Signed Distance gives the unsigned
distance to the points; bad point input gets a clear error and an empty output, and the pipeline
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
from vtkmodules.vtkCommonDataModel import vtkPolyData, vtkStaticCellLocator

from checks import check, finish

LoadPlugin(sys.argv[1], ns=globals())
rng = np.random.default_rng(13)


def cloud(points):
    """A points-only polydata (no cells) as a pipeline source."""
    p = vtkPoints()
    p.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=np.float64), deep=1))
    data = vtkPolyData()
    data.SetPoints(p)
    source = TrivialProducer()
    source.GetClientSideObject().SetOutput(data)
    return source


def wrapped(source):
    wrap = ShrinkWrap(Input=source)
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimeStep)
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
    exact = np.array([np.min(np.linalg.norm(points - q, axis=1)) for q in wp[:500]])
    check(np.allclose(np.abs(distance[:500]), exact, rtol=0, atol=1e-5 * diagonal),
          "%s: the Distance array is the distance to the nearest input point" % name)

# Noisy points (issue #13: jitter up to about 0.5% of the diagonal): 20,000 points on the unit sphere
# with Gaussian noise of 0.25% of the diagonal. The wrap lies inside the noise band, not on its bumps:
# its samples are closer to the sphere on average than half the points are (measured: 0.0012 against
# the points' 0.0040), and none is farther than 3 sigma (measured 1.3 sigma).
sigma = 0.0025 * 2.0
noisy = sphere_points(20000) + rng.normal(scale=sigma, size=(20000, 3))
out = wrapped(cloud(noisy))
if out.GetNumberOfPoints() == 0:
    check(False, "noisy sphere: a wrap")
else:
    g, closed = genus(out)
    wp = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    wt = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    off = np.abs(np.linalg.norm(on_triangles(wp, wt, 20000), axis=1) - 1)
    band = np.abs(np.linalg.norm(noisy, axis=1) - 1).mean()
    check(closed and g == 0 and off.mean() < 0.5 * band and off.max() < 3 * sigma,
          "noisy sphere (sigma %.4f): closed, genus %d; the wrap %.4f off the sphere on average, largest %.4f; the "
          "points %.4f (bars: half the points', 3 sigma)" % (sigma, g, off.mean(), off.max(), band))

# The panel's Field Cell Size for points, before the run (the cloud shown, as in the GUI), is the cell
# the run moves on.
shown_cloud = cloud(sphere_points(3000))
shown_cloud.UpdatePipeline()
planned = ShrinkWrap(Input=shown_cloud)
planned.UpdatePipelineInformation()
shown = planned.FieldCellSize
planned.UpdatePipeline(planned.NumberOfSteps * planned.TimeStep)
ran = servermanager.Fetch(planned).GetFieldData().GetArray("FieldCellSize").GetValue(0)
check(shown > 0 and shown == ran, "Field Cell Size of points before the run: %.6g, the run's: %.6g" % (shown, ran))

# Mesh Signed Distance on the sphere's points: unsigned, and the distance to the nearest point.
points = sphere_points(500)
field = servermanager.Fetch(MeshSignedDistance(Input=cloud(points), Resolution=24))
values = vtk_to_numpy(field.GetPointData().GetArray("SignedDistance"))
nodes = np.array([field.GetPoint(i) for i in range(field.GetNumberOfPoints())])
exact = np.array([np.min(np.linalg.norm(points - q, axis=1)) for q in nodes])
h = field.GetSpacing()[0]
check(field.GetFieldData().GetArray("Signed").GetValue(0) == 0 and (values >= 0).all() and
      np.all(values >= exact - 1e-5 * h) and np.abs(values - exact).mean() < 0.1 * h,
      "Mesh Signed Distance of points: unsigned, never below the exact distance, mean error %.4f h"
      % (np.abs(values - exact).mean() / h))

# Bad point input: a clear error and an empty output; then the same filter wraps a good cloud.
bad = (("one point", [[1, 2, 3]], "coincide"), ("all points equal", [[1, 2, 3]] * 5, "coincide"),
       ("collinear points", [[t, 2 * t, 0] for t in np.linspace(0, 1, 50)], "on a line"),
       ("coplanar points", [[a, b, 0.5] for a in np.linspace(0, 1, 20) for b in np.linspace(0, 1, 20)], "in a plane"),
       ("a NaN point", [[0, 0, 0], [math.nan, 1, 1], [1, 0, 1], [0, 1, 1]], "NaN"))
for name, coordinates, said in bad:
    source = cloud(np.array(coordinates, dtype=float))
    wrap = ShrinkWrap(Input=source)
    said_errors = []

    @calldata_type(VTK_STRING)
    def on_error(caller, event, message):
        said_errors.append(message)

    wrap.GetClientSideObject().AddObserver("ErrorEvent", on_error)
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimeStep)
    text = " ".join(said_errors)
    out = servermanager.Fetch(wrap)
    check(out.GetNumberOfPoints() == 0 and said in text,
          "Shrink Wrap of %s: an error that says '%s', an empty output" % (name, said))
    wrap.Input = cloud(sphere_points(2000))
    wrap.UpdatePipeline(wrap.NumberOfSteps * wrap.TimeStep)
    check(servermanager.Fetch(wrap).GetNumberOfPoints() > 0, "... and the pipeline lives on: it wraps a sphere's points")

finish()
