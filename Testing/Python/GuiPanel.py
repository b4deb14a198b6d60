"""GUI test of the Properties panel (issue #12), startup script: the real client opens a mesh and makes
its distance field (Mesh Signed Distance, applied), a wrap whose Distance Field is connected as Change
Input connects it ("ChangedInput"), and a wrap without one ("PanelWrap"), the active source. The
recorded events (GuiPanel.xml.in) then pick the field in PanelWrap's panel, apply, and run
GuiPanelCheck.py in the client's Python shell; then select the mesh and the field together, create
Shrink Wrap from the Filters menu, apply, and run GuiPanelCheck.py again.
"""
import os

from paraview.simple import *  # noqa: F401,F403

reader = OpenDataFile(os.environ["SHRINKWRAP_MESH"], registrationName="Mesh")
field = MeshSignedDistance(registrationName="Field", Input=reader, Resolution=60)
field.UpdatePipeline()  # applied, as a user has it before picking it
changed = ShrinkWrap(registrationName="ChangedInput", Input=reader)
changed.DistanceField = field  # what Change Input... does
wrap = ShrinkWrap(registrationName="PanelWrap", Input=reader)
Show(wrap)
Render()
SetActiveSource(wrap)
