#!/usr/bin/env python3
"""Generates the paper's benchmark scenes in the sim dialect.

Writes gravity_like.mlir (Section 5.1, Fig. 9) and pbd_like.mlir (Section 5.2,
Fig. 10) with the scene builder in python/simscene. With --check, writes
nothing and fails (exit 1, with a diff) when the files in the output
directory differ from what it would generate; the lit suite runs it that way
so that the checked-in examples never drift from the generator.

fig5.mlir in the same directory is hand-written and not touched.
"""

from __future__ import annotations

import argparse
import difflib
import sys
from pathlib import Path

# Keep the source tree clean when the lit suite runs this script.
sys.dont_write_bytecode = True
sys.path.insert(0, str(Path(__file__).resolve().parent))

from simscene import gravity_like, pbd_like  # noqa: E402

REPO_ROOT = Path(__file__).resolve().parent.parent
DEFAULT_OUTPUT = REPO_ROOT / "examples" / "paper"

SCENES = {
    "gravity_like.mlir": gravity_like,
    "pbd_like.mlir": pbd_like,
}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Generate the paper's gravity-like and PBD-like scenes "
                    "(sim dialect) with the simscene builder.")
    parser.add_argument(
        "--output-dir", type=Path, default=DEFAULT_OUTPUT, metavar="DIR",
        help="where the .mlir files go (default: examples/paper of this "
             "repository)")
    parser.add_argument(
        "--check", action="store_true",
        help="write nothing; exit 1 with a diff if the files in DIR differ "
             "from the generated ones")
    args = parser.parse_args(argv)

    stale = []
    for file_name, make in SCENES.items():
        text = make().render()
        path = args.output_dir / file_name
        if args.check:
            old = path.read_text() if path.exists() else ""
            if old != text:
                stale.append(path)
                sys.stdout.writelines(difflib.unified_diff(
                    old.splitlines(keepends=True),
                    text.splitlines(keepends=True),
                    fromfile=f"{path} (checked in)",
                    tofile=f"{path} (generated)"))
            continue
        args.output_dir.mkdir(parents=True, exist_ok=True)
        if not path.exists() or path.read_text() != text:
            path.write_text(text)
            print(f"wrote {path}")
    if stale:
        sys.stdout.flush()  # the diff first, then the verdict
        print("error: " + ", ".join(str(p) for p in stale) + " out of date; "
              "run python3 python/gen_paper_examples.py", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
