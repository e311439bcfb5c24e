#!/usr/bin/env python3
"""Extracts fenced code blocks from a Markdown page for doc tests.

  doc_blocks.py PAGE N          prints block N (0-based) as it is
  doc_blocks.py PAGE N --checks prints block N as FileCheck CHECK lines, one
                                per line, skipping lines that are just "..."
                                (elisions on the page)
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
    parser.add_argument("index", type=int)
    parser.add_argument("--checks", action="store_true")
    args = parser.parse_args()
    with open(args.page, encoding="utf-8") as f:
        found = blocks(f.read())
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
