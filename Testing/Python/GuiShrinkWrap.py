"""GUI test: the real ParaView client (paraview --script=...), the plugin auto-loaded from
PV_PLUGIN_PATH. Shrink Wrap is applied to a bunny (CGAL's bunny00), the animation is played to the end
through the animation scene, as a user presses Play; the frames at t = 0 and in the middle are saved to
$SHRINKWRAP_FRAMES (compared with baselines by CompareImages.py), and ParaView's test utility compares
the final view with Testing/Baseline/GuiShrinkWrapEnd.png. A Python error leaves the view empty and
the comparison fails. (The GUI sets the colour range from the first frame, whatever the script asks;
the baselines show that range.)
"""
import os
import sys
import traceback

from paraview.simple import *  # noqa: F401,F403

try:
    sys.path.insert(0, os.environ["SHRINKWRAP_EXAMPLES"])
    from demo import show_wrap

    GetLayout().SetSize(500, 400)
    frames = os.environ["SHRINKWRAP_FRAMES"]
    os.makedirs(frames, exist_ok=True)
    reader = OpenDataFile(os.environ["SHRINKWRAP_MESH"])
    wrap = ShrinkWrap(Input=reader)  # the defaults: 25 steps, Resolution 80
    view = GetActiveView()
    b = reader.GetDataInformation().GetBounds()
    show_wrap(reader, wrap, view, 3.3 * max(b[1] - b[0], b[3] - b[2], b[5] - b[4]) / 80)  # h of the field
    view.CameraPosition = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera(*wrap.GetDataInformation().GetBounds())

    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.PlayMode = "Snap To TimeSteps"
    times = wrap.TimestepValues
    scene.AnimationTime = times[0]
    SaveScreenshot(os.path.join(frames, "start.png"), view, ImageResolution=[500, 400])
    scene.AnimationTime = times[len(times) // 2]
    SaveScreenshot(os.path.join(frames, "middle.png"), view, ImageResolution=[500, 400])
    scene.AnimationTime = times[0]
    scene.Play()  # to the end, every step shown
    Render(view)
except Exception:
    traceback.print_exc()
