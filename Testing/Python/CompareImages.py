"""Compares images with baselines: CompareImages.py <max share %> <image> <baseline> [<image> <baseline> ...]
[--text <file> <line> ...] (then the file must also hold every such line).
An image fails when it is missing, differs in size, or when more than <max share %> of its pixels differ
from the baseline by more than 10 (of 255) in some channel. (vtkImageDifference's thresholded error is
normalised per pixel in this VTK, so a threshold on it hardly ever fails.)"""
import os
import sys

from vtkmodules.vtkIOImage import vtkPNGReader

limit = float(sys.argv[1])
arguments = sys.argv[2:]
lines = []
if "--text" in arguments:
    at = arguments.index("--text")
    text_file, lines = arguments[at + 1], arguments[at + 2:]
    arguments = arguments[:at]
pairs = list(zip(arguments[0::2], arguments[1::2]))


def pixels(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    return image.GetDimensions(), scalars.GetNumberOfComponents(), scalars


failed = 0
for image, baseline in pairs:
    if not os.path.exists(image):
        print("FAIL %s was not written" % image)
        failed += 1
        continue
    (dims, comps, a), (dims_b, comps_b, b) = pixels(image), pixels(baseline)
    if dims != dims_b or comps != comps_b:
        print("FAIL %s: size %s x %d, baseline %s x %d" % (os.path.basename(image), dims, comps, dims_b, comps_b))
        failed += 1
        continue
    channels = min(comps, 3)
    different = sum(
        1 for i in range(a.GetNumberOfTuples())
        if max(abs(a.GetComponent(i, c) - b.GetComponent(i, c)) for c in range(channels)) > 10)
    share = 100.0 * different / a.GetNumberOfTuples()
    ok = share <= limit
    failed += not ok
    print("%s %s: %.2f%% of pixels differ (limit %g%%)" % ("ok  " if ok else "FAIL", os.path.basename(image), share, limit))
for line in lines:
    held = os.path.exists(text_file) and line in open(text_file).read().splitlines()
    failed += not held
    print("%s %s holds '%s'" % ("ok  " if held else "FAIL", os.path.basename(text_file), line))
print("%d passed, %d failed" % (len(pairs) + len(lines) - failed, failed))
sys.exit(1 if failed else 0)
