#!/usr/bin/env python3
"""The core sits below the filters: no file of Filters/Core includes a header of Filters/ (outside
Core) or of VTK, but for the one thread seam, Common/Parallel.cxx. Every include of a core header
names its folder ("Surface/SurfaceMesh.h").
  python3 check_layers.py <Filters folder>      exit 1, naming each offending line, when one breaks it
"""
import os
import re
import sys

SEAM = os.path.join("Common", "Parallel.cxx")
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]')


def violations(filters):
    core = os.path.join(filters, "Core")
    above = {f for f in os.listdir(filters) if f.endswith((".h", ".hxx", ".txx"))}
    headers = {}
    for folder, _, files in os.walk(core):
        for f in files:
            if f.endswith(".h"):
                headers[f] = os.path.relpath(os.path.join(folder, f), core)
    found = []
    for folder, _, files in os.walk(core):
        for f in sorted(files):
            if not f.endswith((".cxx", ".h")):
                continue
            path = os.path.join(folder, f)
            rel = os.path.relpath(path, core)
            with open(path, encoding="utf-8") as source:
                for number, line in enumerate(source, 1):
                    match = INCLUDE.match(line)
                    if not match:
                        continue
                    name = match.group(1)
                    base = os.path.basename(name)
                    where = "%s:%d: %s" % (os.path.relpath(path, filters), number, line.strip())
                    if base in above or name.startswith(".."):
                        found.append(where + "  (a header of the filters)")
                    elif re.match(r"vtk", base) and rel != SEAM:
                        found.append(where + "  (VTK outside the thread seam %s)" % SEAM)
                    elif base in headers and name != headers[base]:
                        found.append(where + '  (include it as "%s")' % headers[base])
    return found


def main():
    found = violations(sys.argv[1])
    for line in found:
        print(line)
    print("%d include(s) break the layering" % len(found) if found else "the core includes only itself, Eigen and the standard library")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
