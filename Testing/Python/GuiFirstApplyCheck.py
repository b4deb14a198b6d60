"""Run in the GUI's Python shell after the first Apply (GuiFirstApply.xml.in): writes what the view
shows to $SHRINKWRAP_OUT/result.txt (each line a fact the test expects to be True) and the view to
view.png (compared with a baseline)."""
import os

from paraview.simple import *  # noqa: F401,F403

out = os.environ["SHRINKWRAP_OUT"]
os.makedirs(out, exist_ok=True)
view = GetActiveView()
wrap = FindSource("ShrinkWrap1")
target = FindSource("Target")
facts = []
try:
    shown = GetDisplayProperties(wrap, view)
    time = GetAnimationScene().AnimationTime
    facts.append(("the view shows the wrap's last step", abs(time - wrap.TimestepValues[-1]) < 1e-12))
    facts.append(("the wrap is coloured by Distance", shown.ColorArrayName[1] == "Distance"))
    lut = GetColorTransferFunction("Distance")
    low, high = wrap.PointData["Distance"].GetRange()
    points = lut.RGBPoints
    span = high - low
    facts.append(("the legend spans the shown wrap's Distance range",
                  span > 0 and abs(points[0] - low) <= 1e-6 * span and abs(points[-4] - high) <= 1e-6 * span))
    facts.append(("the legend is shown", GetScalarBar(lut, view).Visibility == 1))
    look = GetDisplayProperties(target, view)
    facts.append(("the target is drawn grey beside it",
                  look.Visibility == 1 and look.ColorArrayName[1] in ("", None) and
                  max(look.DiffuseColor) - min(look.DiffuseColor) < 1e-9 and look.DiffuseColor[0] < 0.5))
    SaveScreenshot(os.path.join(out, "view.png"), view, ImageResolution=[640, 480])
    # The target as measured: output port 1, hidden until the user shows it; shown, it is coloured by
    # DistanceToWrap on a diverging map centred at 0 that spans its largest value either way.
    measured = OutputPort(wrap, 1)
    shown_at_first = [r for r in view.Representations
                      if r.GetProperty("Input") is not None and r.Input == wrap and
                      r.GetProperty("Input").GetOutputPortForConnection(0) == 1 and
                      r.Visibility]
    facts.append(("the target measured is an output of its own, hidden at first",
                  wrap.GetNumberOfOutputPorts() == 2 and not shown_at_first))
    look = Show(measured, view)
    Hide(wrap, view)
    Hide(target, view)
    Render(view)
    facts.append(("shown, the target measured is coloured by DistanceToWrap",
                  look.ColorArrayName[1] == "DistanceToWrap"))
    low, high = measured.GetDataInformation().GetPointDataInformation().GetArrayInformation(
        "DistanceToWrap").GetComponentRange(0)
    largest = max(abs(low), abs(high))
    points = GetColorTransferFunction("DistanceToWrap").RGBPoints
    facts.append(("on a diverging map centred at 0 over its largest distance",
                  len(points) == 12 and abs(points[0] + largest) <= 1e-6 * largest and
                  abs(points[8] - largest) <= 1e-6 * largest and abs(points[4]) <= 1e-9 * largest and
                  points[3] > points[1] and points[9] > points[11] and
                  min(points[5:8]) > 0.8 and max(points[5:8]) - min(points[5:8]) < 0.05))
    SaveScreenshot(os.path.join(out, "measured.png"), view, ImageResolution=[640, 480])
except Exception as error:  # written down, so that the test after this one fails and says why
    facts.append(("the check ran (%s)" % error, False))
with open(os.path.join(out, "result.txt"), "w") as f:
    f.writelines("%s: %s\n" % fact for fact in facts)
