#!/usr/bin/python3
"""Regenerate doc/bad-input.md, the table of bad input and what ArchDam says
about it, from the expected outputs of the error tests (tests/*.output): every
row is a case a test runs, with the exact message the test checks. The test
bad_input_table fails when the table is out of date.

Usage: scripts/make-bad-input-table.py [--print]
"""
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent

# The tests whose cases are bad input, in the order of the table, with the
# heading of their section.
TESTS = [
    ("cli_errors", "Command line and parameter file"),
    ("input_errors", "Values out of range, inconsistent values, monitors, joints"),
    ("mesh_errors", "Gmsh mesh files and mesh ids"),
    ("arch_dam_errors", "Arch-dam generator"),
    ("ground_motion_errors", "Ground-motion files and parameters"),
    ("reservoir_errors", "Reservoir"),
    ("foundation_errors", "Foundation"),
    ("checkpoint_resume", "Resuming from a checkpoint (`--resume`)"),
    ("record_suite", "Record suites as independent jobs (`--record`, `--gather`)"),
    ("motion_command", "`archdam-motion`"),
]

INTRO = """# Bad input and what ArchDam says about it

Every bad input ArchDam rejects ends the run with one message that names the
parameter or file (and line) and what is wrong, and exit code 1; it never
crashes, hangs or runs on with a silently wrong value. The table lists each
case with the exact message and the test that tries it (`tests/NAME.cc`, its
expected output `tests/NAME.output`). Tests that drive the command line show
the message as the user sees it (`archdam: error: ...`); tests of a module
show the message of the `InputError` it throws, which the command line prints
the same way. A run that starts but diverges (`archdam: run stopped: ...`,
doc/user-guide.md, "When a run stops") also exits with code 1, after writing
its results so far.

This page is generated from the tests' expected outputs by
`scripts/make-bad-input-table.py`; the test `bad_input_table` fails when it is
out of date. To add a row, add the case to an error test.
"""


def cases(test):
    """(case, message) pairs of one test's expected output."""
    lines = (ROOT / "tests" / (test + ".output")).read_text().splitlines()
    result, title, message = [], None, None

    def close():
        if title is not None and message is not None:
            result.append((title, message))

    # A case is a line at the left margin ("* what" or "what:"); its message
    # is the first indented line that is one: the command line's
    # "archdam: error: ...", "InputError: ...", the line after
    # "InputError: yes", or (foundation_errors) the only line.
    after_marker = False
    for line in lines:
        if not line.strip():
            continue
        if not line.startswith(" "):
            close()
            title, message = line.strip().removeprefix("* ").rstrip(":"), None
            continue
        text = line.strip()
        if message is not None:
            continue
        if text == "InputError: yes":
            after_marker = True
        elif after_marker or text.startswith(("archdam: error: ", "archdam-motion: error: ")):
            message = text
        elif text.startswith("InputError: "):
            message = text.removeprefix("InputError: ")
        elif test == "foundation_errors":
            message = text
        after_marker = after_marker and message is None
    close()
    return result


# Checks in the code that no test tries yet: they guard against states that
# need a large or special model to reach, or failures of the machine.
UNTRIED = """
## Checked, but not yet tried by a test

| check | where |
|---|---|
| the contact problem of a step does not converge (`Contraction joints/On non-convergence = stop`) | `source/analysis/joint_stages.cc` |
| the modal stage finds no converged mode, or a rigid-body mode | `source/analysis/modal_analysis.cc` |
| the static displacement is not finite | `source/analysis/static_stage.cc` |
| Gmsh's own reader fails on a file that passed the format checks | `source/geometry/gmsh_mesh.cc` |
| a joint vertex on two joints, a joint face without its partner on the next block | `source/joints/joint_faces.cc` |
| a result file cannot be appended to (disk full) | `source/output/atomic_file.cc` |
| `archdam-motion` option combinations (`--baseline-degree` without `--baseline`, `--target-pga` <= 0) | `source/application/motion_command.cc` |
"""


def table():
    out = [INTRO]
    for test, heading in TESTS:
        rows = cases(test)
        out.append(f"\n## {heading}\n\n`tests/{test}.cc`\n\n| input | message |\n|---|---|")
        for title, message in rows:
            cell = lambda s: s.replace("|", "\\|")
            out.append(f"| {cell(title)} | {cell(message)} |")
    out.append(UNTRIED)
    return "\n".join(out)


if __name__ == "__main__":
    text = table()
    if "--print" in sys.argv:
        sys.stdout.write(text)
    else:
        (ROOT / "doc" / "bad-input.md").write_text(text)
        print("wrote doc/bad-input.md")
