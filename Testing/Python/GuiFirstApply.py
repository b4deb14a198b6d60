"""GUI test of the first Apply, startup script: the real client opens the target file
($SHRINKWRAP_MESH) and shows it, as File > Open and Apply do. The recorded events
(GuiFirstApply.xml.in) then create Shrink Wrap from the Filters menu, press Apply, and run
GuiFirstApplyCheck.py in the client's Python shell."""
import os

from paraview.simple import *  # noqa: F401,F403

GetLayout().SetSize(640, 480)
target = OpenDataFile(os.environ["SHRINKWRAP_MESH"], registrationName="Target")
Show(target)
Render()
