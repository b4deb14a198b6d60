#!/usr/bin/env python3
"""Fails when the build uses a file from a Debian package that the setup script would not install.

Usage: check_packages.py CMakeCache.txt PACKAGE...   (PACKAGE...: shrinkwrap.sh's list, `bash shrinkwrap.sh packages`)

Every PATH and FILEPATH entry of the cache (what find_package, find_library and find_program resolved
to) is traced to the package that owns it (dpkg -S). Each must be in the closure of the list: the
listed packages and, recursively, their installed Depends and Pre-Depends (the setup installs without
Recommends), plus what a fresh minbase Debian already has (Essential and Priority required). A file
owned by nothing outside the source and build folders fails too: a fresh machine would not have it.
A machine that has a package only because someone installed it by hand thus fails here, naming it,
instead of passing CI and failing on a newcomer's machine.
"""
import os
import re
import subprocess
import sys


def cache_paths(cache_file, ignored):
    """(variable, path) for the absolute, existing PATH/FILEPATH values of a CMakeCache.txt."""
    entries = []
    with open(cache_file) as cache:
        for line in cache:
            m = re.match(r"^([^#/][^:]*):(PATH|FILEPATH)=(.*)$", line.rstrip("\n"))
            if not m or m.group(1).startswith("CMAKE_INSTALL_"):  # install folders, not found things
                continue
            for value in m.group(3).split(";"):
                if os.path.isabs(value) and os.path.exists(value) and \
                        not any(os.path.realpath(value).startswith(p) for p in ignored):
                    entries.append((m.group(1), value))
    return entries


def installed_packages():
    """name -> (dependency groups, provided names, is base) for every installed package."""
    fmt = "${Package}\t${Status}\t${Pre-Depends}, ${Depends}\t${Provides}\t${Essential}\t${Priority}\n"
    out = subprocess.run(["dpkg-query", "-W", "-f", fmt], capture_output=True, text=True, check=True).stdout
    packages = {}
    for line in out.splitlines():
        name, status, depends, provides, essential, priority = line.split("\t")
        if not status.endswith(" installed"):
            continue
        groups = [[alt.split()[0].split(":")[0] for alt in group.split("|") if alt.strip()]
                  for group in depends.split(",") if group.strip()]
        provided = [p.split()[0] for p in provides.split(",") if p.strip()]
        packages[name] = (groups, provided, essential == "yes" or priority == "required")
    return packages


def closure(roots, packages):
    """The packages that installing `roots` brings along (and the base system has)."""
    providers = {}
    for name, (_, provided, _) in packages.items():
        for virtual in provided:
            providers.setdefault(virtual, []).append(name)
    todo = [r for r in roots if r in packages] + [n for n, (_, _, base) in packages.items() if base]
    seen = set()
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        for group in packages[name][0]:
            for alternative in group:
                todo += [alternative] if alternative in packages else providers.get(alternative, [])
    return seen


def owners(paths):
    """path -> set of packages that own it (or, through links, the file it points to)."""
    def ask(candidates):
        found = {}
        out = subprocess.run(["dpkg", "-S"] + candidates, capture_output=True, text=True).stdout
        for line in out.splitlines():
            if line.startswith("diversion by"):
                continue
            names, path = line.rsplit(": ", 1)
            found.setdefault(path, set()).update(n.strip().split(":")[0] for n in names.split(","))
        return found

    result = ask(paths) if paths else {}
    unowned = [p for p in paths if p not in result]
    linked = ask(sorted({os.path.realpath(p) for p in unowned})) if unowned else {}
    for path in unowned:
        result[path] = linked.get(os.path.realpath(path), set())
    return result


class Inventory:
    """What the configured build resolved, and what this machine's packages own and depend on."""

    def __init__(self, cache_file):
        build = os.path.realpath(os.path.dirname(os.path.abspath(cache_file)))
        source = os.path.realpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
        self.entries = cache_paths(cache_file, [build + "/", source + "/"])
        self.packages = installed_packages()
        self.owned = owners(sorted({path for _, path in self.entries}))

    def problems(self, listed):
        """package (or "(no Debian package)") -> the cache entries it serves, for what `listed` lacks."""
        brought = closure(listed, self.packages)
        problems = {}
        for variable, path in self.entries:
            if not self.owned[path] & brought:
                key = " or ".join(sorted(self.owned[path])) or "(no Debian package)"
                problems.setdefault(key, []).append("%s = %s" % (variable, path))
        for package in listed:
            if package not in self.packages:
                problems.setdefault(package, []).append("the list (it is not installed)")
        return problems


def check(cache_file, listed):
    inventory = Inventory(cache_file)
    problems = inventory.problems(listed)
    for package, uses in sorted(problems.items()):
        print("MISSING from shrinkwrap.sh's package list: %s, used by %s%s"
              % (package, ", ".join(uses[:3]), " and %d more" % (len(uses) - 3) if len(uses) > 3 else ""))
    print("%d paths that CMake resolved; the package list brings all their packages: %s"
          % (len(inventory.entries), "no" if problems else "yes"))
    return not problems


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    sys.exit(0 if check(sys.argv[1], sys.argv[2:]) else 1)
