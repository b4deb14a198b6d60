"""The genus a closed target keeps once its gaps narrower than a Gap Size are bridged: the surface of its
morphological closing by a ball of radius gap / 2 (dilate, then erode), from two Mesh Signed Distance
fields and their contours. Issue #13's genus bar asks for the truth's genus "where the holes are wider
than the gap size"; this tells which handles a wrap at that gap may rightly have (two fingers or legs
closer than the gap make one). The dilation by gap / 2 is printed too: an offset start at that
distance has its topology. Each connected component's genus from its Euler characteristic; inner
components are cavities the closing left. Meaningless for open targets (their sign is not defined).
Usage: pvpython closing_genus.py <ShrinkWrap plugin .so> <target.vtp, as BenchShrinkWrap --out writes it>
<gap> [resolution, default 300]"""
import sys

from paraview import servermanager as sm
from paraview.simple import *  # noqa: F401,F403
from vtkmodules.vtkFiltersCore import vtkCleanPolyData, vtkExtractEdges, vtkPolyDataConnectivityFilter

plugin, target, gap = sys.argv[1], sys.argv[2], float(sys.argv[3])
resolution = int(sys.argv[4]) if len(sys.argv) > 4 else 300
LoadPlugin(plugin, ns=globals())


def component_genera(source):
    """(genus, triangles) of each connected component of a closed triangle surface."""
    merged = vtkCleanPolyData()
    merged.SetInputData(sm.Fetch(source))
    merged.Update()
    regions = vtkPolyDataConnectivityFilter()
    regions.SetInputData(merged.GetOutput())
    regions.SetExtractionModeToAllRegions()
    regions.Update()
    genera = []
    for region in range(regions.GetNumberOfExtractedRegions()):
        one = vtkPolyDataConnectivityFilter()
        one.SetInputData(merged.GetOutput())
        one.SetExtractionModeToSpecifiedRegions()
        one.AddSpecifiedRegion(region)
        clean = vtkCleanPolyData()
        clean.SetInputConnection(one.GetOutputPort())
        clean.Update()
        surface = clean.GetOutput()
        edges = vtkExtractEdges()
        edges.SetInputData(surface)
        edges.Update()
        euler = surface.GetNumberOfPoints() - edges.GetOutput().GetNumberOfLines() + surface.GetNumberOfPolys()
        genera.append(((2 - euler) // 2, surface.GetNumberOfPolys()))
    return genera


def level_set(mesh, level):
    field = MeshSignedDistance(Input=mesh, Resolution=resolution)
    field.UpdatePipeline()
    return Contour(Input=field, ContourBy=["POINTS", field.PointData.keys()[0]], Isosurfaces=[level])


mesh = XMLPolyDataReader(FileName=[target])
dilation = level_set(mesh, gap / 2)
closing = level_set(dilation, -gap / 2)
print("target: genus and triangles of each component", component_genera(mesh))
print("dilated by %g:" % (gap / 2), component_genera(dilation))
print("closed at gap %g:" % gap, component_genera(closing))
