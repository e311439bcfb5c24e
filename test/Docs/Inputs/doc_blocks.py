#!/usr/bin/env python3
"""Extracts fenced code blocks from a Markdown page for doc tests.

  doc_blocks.py PAGE N          prints block N (0-based) as it is
  doc_blocks.py PAGE N --checks prints block N as FileCheck CHECK lines, one
                                per line, skipping lines that are just "..."
                                (elisions on the page)
  doc_blocks.py PAGE --containing TEXT
                                prints the first block that contains TEXT
                                (for pages whose blocks others add to, such
                                as the README)
"""
import argparse
import re
import sys


def blocks(text):
    found, current = [], None
    for line in text.splitlines():
        if re.match(r"^\s*```", line):
            if current is None:
                current = []
            else:
                found.append(current)
                current = None
            continue
        if current is not None:
            current.append(line)
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawTextHelpFormatter)
    parser.add_argument("page")
    parser.add_argument("index", type=int, nargs="?")
    parser.add_argument("--checks", action="store_true")
    parser.add_argument("--containing", metavar="TEXT")
    args = parser.parse_args()
    with open(args.page, encoding="utf-8") as f:
        found = blocks(f.read())
    if args.containing is not None:
        matches = [n for n, block in enumerate(found)
                   if args.containing in "\n".join(block)]
        if not matches:
            sys.exit(f"{args.page} has no code block containing "
                     f"{args.containing!r}")
        args.index = matches[0]
    elif args.index is None:
        parser.error("give a block index or --containing TEXT")
    if args.index >= len(found):
        sys.exit(f"{args.page} has {len(found)} code blocks, not {args.index + 1}")
    for line in found[args.index]:
        if not args.checks:
            print(line)
        elif line.strip() != "...":
            # FileCheck treats [[ and {{ specially; the pages contain neither.
            print("CHECK: " + line.strip())


if __name__ == "__main__":
    main()
