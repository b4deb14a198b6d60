#!/usr/bin/env python3
"""check_layers.py fails on a copy of Filters/ whose core includes a filter's header, VTK, or a core
header without its folder, and passes on the tree as it is.
  python3 test_check_layers.py <Filters folder>"""
import os
import shutil
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
check = os.path.join(here, "check_layers.py")
filters = sys.argv[1]


def run(folder):
    done = subprocess.run([sys.executable, check, folder], capture_output=True, text=True)
    return done.returncode, done.stdout


failed = 0
code, out = run(filters)
if code != 0:
    print("FAIL: the tree as it is breaks the layering:\n" + out)
    failed += 1
for bad, kind in [('#include "VTKConversions.h"', "a header of the filters"),
                  ("#include <vtkSMPTools.h>", "VTK outside the thread seam"),
                  ('#include "SurfaceMesh.h"', 'include it as "Surface/SurfaceMesh.h"')]:
    with tempfile.TemporaryDirectory() as copy:
        tree = os.path.join(copy, "Filters")
        shutil.copytree(filters, tree)
        victim = os.path.join(tree, "Core", "Evolution", "StartingSurface.cxx")
        with open(victim, "a", encoding="utf-8") as f:
            f.write("\n" + bad + "\n")
        code, out = run(tree)
        if code == 0 or kind not in out or "StartingSurface.cxx" not in out:
            print("FAIL: %s was not caught:\n%s" % (bad, out))
            failed += 1
print("FAIL" if failed else "check_layers.py catches each break: ok")
sys.exit(1 if failed else 0)
