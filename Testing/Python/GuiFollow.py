"""GUI test: the real ParaView client (paraview --script=...), the plugin auto-loaded from
PV_PLUGIN_PATH. A series is opened as a user opens one (a .pvd of 12 frames of a torus that bends
up at both ends as it moves: the same triangles every frame), Shrink Wrap is applied with its defaults and follows it
(Time Mode: Automatic); Play walks the series' frames, the wrap following, coloured by the magnitude
of its Velocity. Frames 0, 6 and 11 are saved to $SHRINKWRAP_FRAMES side by side with the target
(compared with baselines by CompareImages.py); the script writes what it checked to
$SHRINKWRAP_FRAMES/checks.txt ("ok ..." or "FAIL ..." lines), and ParaView's test utility compares the
final view with Testing/Baseline/GuiFollowEnd.png. A Python error leaves the view empty and the
comparison fails.
"""
import os
import sys
import traceback

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

# The test helpers (a --script has no __file__ to find them by).
sys.path.insert(0, os.environ["SHRINKWRAP_PYTHON"])
from series import torus, write_series  # noqa: E402

FRAMES = 12


def bent(x, y, z, phase):
    """The torus moved along x and bent up at both ends: z grows by 0.6 x^2 over the series."""
    return (x + 1.2 * phase, y, z + 0.6 * phase * x * x)


frames = os.environ["SHRINKWRAP_FRAMES"]
os.makedirs(frames, exist_ok=True)
checks = []
try:
    GetLayout().SetSize(600, 400)
    reader = OpenDataFile(write_series(frames, "bent", torus(0.35, 72, 24), range(FRAMES),
                                       lambda p, k: bent(*p, k / (FRAMES - 1))))
    wrap = ShrinkWrap(Input=reader)
    view = GetActiveView()
    view.OrientationAxesVisibility = 0
    shown = Show(wrap, view)  # (over the target, which it hides)
    ColorBy(shown, ("POINTS", "Velocity", "Magnitude"))
    shown.SetRepresentationType("Surface With Edges")
    shown.EdgeColor = [0.35, 0.35, 0.35]
    lut = GetColorTransferFunction("Velocity")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(0.0, 0.2)
    bar = GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = "|Velocity|", ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    shown.SetScalarBarVisibility(view, True)
    view.CameraPosition = [0.6, -7.5, 3.5]
    view.CameraFocalPoint = [0.6, 0.0, 0.4]
    view.CameraViewUp = [0.0, 0.0, 1.0]

    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.PlayMode = "Snap To TimeSteps"
    print("the wrap's times:", list(wrap.TimestepValues))
    checks.append(("ok " if list(wrap.TimestepValues) == list(range(FRAMES)) else "FAIL ")
                  + "the wrap's times are the series'")
    for k in (0, FRAMES // 2, FRAMES - 1):
        scene.AnimationTime = k
        SaveScreenshot(os.path.join(frames, "frame%02d.png" % k), view, ImageResolution=[600, 400])
    scene.AnimationTime = 0
    scene.Play()  # to the end, every frame shown
    Render(view)
    data = servermanager.Fetch(wrap)
    time = data.GetFieldData().GetAbstractArray("Time").GetValue(0)
    print("after Play: time %g, %d vertices" % (time, data.GetNumberOfPoints()))
    checks.append(("ok " if time == FRAMES - 1 else "FAIL ") + "Play ends on the last frame")
    ids = data.GetPointData().GetArray("TrackId")
    checks.append(("ok " if ids is not None and data.GetNumberOfPoints() > 500 else "FAIL ")
                  + "the last frame wrapped with TrackIds")
except Exception:
    checks.append("FAIL " + traceback.format_exc().replace("\n", " | "))
    traceback.print_exc()
with open(os.path.join(frames, "checks.txt"), "w") as out:
    out.write("\n".join(checks) + "\n")
