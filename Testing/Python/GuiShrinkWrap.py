"""GUI test: the real ParaView client (paraview --script=...), the plugin auto-loaded from
PV_PLUGIN_PATH. Shrink Wrap is applied to a bunny (CGAL's bunny00), the animation is played to the end
through the animation scene, as a user presses Play; the frames at t = 0 and in the middle are saved to
$SHRINKWRAP_FRAMES (compared with baselines by CompareImages.py), and ParaView's test utility compares
the final view with Testing/Baseline/GuiShrinkWrapEnd.png. A Python error leaves the view empty and
the comparison fails.
"""
import os
import traceback

from paraview.simple import *  # noqa: F401,F403

try:
    GetLayout().SetSize(500, 400)
    frames = os.environ["SHRINKWRAP_FRAMES"]
    os.makedirs(frames, exist_ok=True)
    reader = OpenDataFile(os.environ["SHRINKWRAP_MESH"])
    wrap = ShrinkWrap(Input=reader, NumberOfSteps=100, Resolution=80)
    view = GetActiveView()
    view.OrientationAxesVisibility = 0
    target = Show(reader, view)
    target.ColorArrayName = ["POINTS", ""]
    target.DiffuseColor = [0.75, 0.75, 0.7]
    shown = Show(wrap, view)
    ColorBy(shown, ("POINTS", "Distance"))
    shown.SetRepresentationType("Surface With Edges")
    shown.Opacity = 0.6
    lut = GetColorTransferFunction("Distance")
    lut.ApplyPreset("Cool to Warm", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(-0.06, 0.06)  # about two cells of the field
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
