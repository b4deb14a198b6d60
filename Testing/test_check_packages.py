"""The package check fails when a package the build needs is left out of shrinkwrap.sh's list.

Usage: python3 test_check_packages.py CMakeCache.txt PACKAGE...   (the whole list)
Issue #8: CI was green while libqt5opengl5-dev was missing from the list (the machine had it anyway).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_packages import Inventory  # noqa: E402

cache, listed = sys.argv[1], sys.argv[2:]
inventory = Inventory(cache)
failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message)
    if not condition:
        failures.append(message)


check(not inventory.problems(listed), "the whole list brings every file the build resolved")
caught = [p for p in listed if p in inventory.problems([q for q in listed if q != p])]
print("left out one at a time, %d of %d listed packages are named by the check: %s"
      % (len(caught), len(listed), " ".join(caught)))
check("libqt5opengl5-dev" in caught, "without libqt5opengl5-dev (issue #8's gap) the check names it")
check("paraview-dev" in caught and "xvfb" in caught, "without ParaView's headers or Xvfb it names them")
check("no-such-package" in inventory.problems(listed + ["no-such-package"]),
      "a listed package that is not installed is named")
print("%d passed, %d failed" % (4 - len(failures), len(failures)))
sys.exit(1 if failures else 0)
