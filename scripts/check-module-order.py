#!/usr/bin/python3
"""Check that ArchDam's modules depend one way: every `#include <archdam/...>`
in include/archdam/ and source/ names a module at or below the including one
in the order written in doc/theory/conventions.md §2 (the numbered list after
the line "Module order"). A module is a folder under include/archdam/ (and
source/), physics/NAME counted as its own module.

Prints each include against the order (file, line, the two modules) and exits
1 if there is one, or if a module is missing from the list; prints one line
and exits 0 otherwise. Run by the test `module_order`.

usage: check-module-order.py [ROOT]
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else
                       os.path.join(os.path.dirname(__file__), ".."))
ORDER_PAGE = os.path.join("doc", "theory", "conventions.md")


def documented_order():
    """The modules of the numbered list under "Module order", bottom first."""
    order, inside = [], False
    with open(os.path.join(ROOT, ORDER_PAGE), encoding="utf-8") as page:
        for line in page:
            if line.startswith("Module order"):
                inside = True
                continue
            if inside:
                item = re.match(r"\s*\d+\.\s+`([a-z_/]+)`", line)
                if item:
                    order.append(item.group(1).rstrip("/"))
                elif order and not line.strip():
                    break
    return order


def module_of(parts):
    """The module of a path below include/archdam/ or source/."""
    return "/".join(parts[:2]) if parts[0] == "physics" else parts[0]


def main():
    order = documented_order()
    if not order:
        print(f"check-module-order: no 'Module order' list in {ORDER_PAGE}")
        return 1
    rank = {m: k for k, m in enumerate(order)}
    problems = []
    for top in (os.path.join("include", "archdam"), "source"):
        for folder, _, files in os.walk(os.path.join(ROOT, top)):
            for name in sorted(files):
                path = os.path.join(folder, name)
                relative = os.path.relpath(path, os.path.join(ROOT, top)).split(os.sep)
                if len(relative) < 2:
                    continue
                source = module_of(relative)
                if source not in rank:
                    problems.append(f"{os.path.relpath(path, ROOT)}: module '{source}' is not in "
                                    f"the order of {ORDER_PAGE}")
                    continue
                with open(path, encoding="utf-8") as text:
                    for number, line in enumerate(text, 1):
                        included = re.match(r"\s*#\s*include\s*<archdam/([^>]+)>", line)
                        if not included:
                            continue
                        target = module_of(included.group(1).split("/"))
                        if target not in rank:
                            problems.append(f"{os.path.relpath(path, ROOT)}:{number}: includes "
                                            f"module '{target}', which is not in the order")
                        elif rank[target] > rank[source]:
                            problems.append(f"{os.path.relpath(path, ROOT)}:{number}: "
                                            f"'{source}' includes '{target}', which comes after "
                                            f"it in {ORDER_PAGE} (<archdam/{included.group(1)}>)")
    for problem in problems:
        print(problem)
    if problems:
        print(f"check-module-order: {len(problems)} include(s) against the module order")
        return 1
    print("check-module-order: every include follows the module order (" +
          " < ".join(order) + ")")
    return 0


if __name__ == "__main__":
    sys.exit(main())
