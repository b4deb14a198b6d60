"""Compares images with baselines: CompareImages.py <threshold> <image> <baseline> [<image> <baseline> ...].
Fails (exit 1) when an image is missing or differs by more than the threshold (vtkImageDifference)."""
import os
import sys

from paraview import vtk  # noqa: F401
from vtkmodules.vtkImagingCore import vtkImageDifference
from vtkmodules.vtkIOImage import vtkPNGReader

threshold = float(sys.argv[1])
pairs = list(zip(sys.argv[2::2], sys.argv[3::2]))
failed = 0
for image, baseline in pairs:
    if not os.path.exists(image):
        print("FAIL %s was not written" % image)
        failed += 1
        continue
    readers = []
    for path in (image, baseline):
        r = vtkPNGReader()
        r.SetFileName(path)
        r.Update()
        readers.append(r)
    diff = vtkImageDifference()
    diff.SetInputConnection(readers[0].GetOutputPort())
    diff.SetImageConnection(readers[1].GetOutputPort())
    diff.Update()
    error = diff.GetThresholdedError()
    ok = error <= threshold
    failed += not ok
    print("%s %s: error %.2f (threshold %g)" % ("ok  " if ok else "FAIL", os.path.basename(image), error, threshold))
print("%d passed, %d failed" % (len(pairs) - failed, failed))
sys.exit(1 if failed else 0)
