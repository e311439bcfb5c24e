"""Lists the vectors of 8-byte elements in the runtime's FlatBuffers schemas
and whether the runtime checks their alignment before unpacking them
(runtime/src/VectorAlignment.h: FlatBuffers 2.0's verifier does not).

    vector_alignment.py SCHEMA_DIR SOURCE_DIR

prints `Table.field in file.fbs: checked` (or `NOT checked`) per vector. A
vector counts as checked when its accessor (`->field()`) is named at most
ten lines before a call of elementsAligned in a runtime source file."""

import pathlib
import re
import sys

EIGHT_BYTES = {"long", "ulong", "double", "int64", "uint64", "float64"}


def blocks(text, kind):
    """(name, body) of every `kind Name { ... }` in a schema."""
    for match in re.finditer(rf"^\s*{kind}\s+(\w+)[^{{]*\{{(.*?)\}}", text,
                             re.M | re.S):
        yield match.group(1), match.group(2)


def fields(body):
    for line in body.splitlines():
        line = line.split("//")[0].strip()
        match = re.match(r"(\w+)\s*:\s*([\w\[\].]+)", line)
        if match:
            yield match.group(1), match.group(2)


def main():
    schemas = sorted(pathlib.Path(sys.argv[1]).glob("*.fbs"))
    sources = sorted(pathlib.Path(sys.argv[2]).glob("*.cpp"))
    texts = {path: path.read_text() for path in schemas}
    # Structs aligned to 8: one 8-byte member, or a member struct that is.
    structs = {}
    for text in texts.values():
        for name, body in blocks(text, "struct"):
            structs[name] = [t for _, t in fields(body)]
    aligned8 = set()
    changed = True
    while changed:
        changed = False
        for name, types in structs.items():
            if name not in aligned8 and any(
                    t in EIGHT_BYTES or t.split(".")[-1] in aligned8
                    for t in types):
                aligned8.add(name)
                changed = True
    lines = {path: path.read_text().splitlines() for path in sources}

    def checked(field):
        for source in lines.values():
            for at, line in enumerate(source):
                if "elementsAligned(" not in line:
                    continue
                window = source[max(0, at - 10):at + 1]
                if any(f"->{field}()" in text for text in window):
                    return True
        return False

    for path, text in texts.items():
        for table, body in blocks(text, "table"):
            for field, type_ in fields(body):
                if not (type_.startswith("[") and type_.endswith("]")):
                    continue
                element = type_[1:-1].split(".")[-1]
                if element in EIGHT_BYTES or element in aligned8:
                    state = "checked" if checked(field) else "NOT checked"
                    print(f"{table}.{field} in {path.name}: {state}")


main()
