"""The tracer: Python calls on traced values become `sim` dialect text.

A body (a buffer's `init` or `exact`, a component's `num_steps` or
`evaluate`, a total) is a Python function that the tracer calls once with
`Value`s for its arguments (`i`, `t`, `n`, `dt`). Every operator and `sim.*`
function on a `Value` appends one MLIR operation to the current `Block`,
with the Python source location of the user's line as its location
(`loc("scene.py":12:9)`), and returns the `Value` of its result. What a
Python function cannot express as operations (a Python `if` on a value, a
data-dependent loop bound, a value carried out of its body by a side
effect, an unsupported type) raises `TraceError` at the user's line.

Constants and parameter reads are emitted once per body, at its top; a
`sim.loop` body is a nested `Block` (the region of an `scf.for`).
"""

from __future__ import annotations

import linecache
import os
import re
import sys
from contextlib import contextmanager
from typing import Callable, Iterable, Sequence

from .errors import TraceError
from .types import DType, float_literal, int_literal

__all__ = [
    "Location", "Value", "Block", "Body", "LocationTable", "current_block",
    "current_body", "user_location", "trace_error", "emit", "constant",
    "call_body",
]

_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__)) + os.sep

# A call of Python's max() or min() (not sim.max, not a method) in a line.
_BUILTIN_MINMAX = re.compile(r"(?<![\w.])(?:max|min)\s*\(")


# -- Source locations ------------------------------------------------------------

class Location:
    """A Python source position: file, line and 1-based column."""

    __slots__ = ("filename", "line", "column")

    def __init__(self, filename: str, line: int, column: int | None = None):
        self.filename = filename
        self.line = line
        self.column = column

    def key(self):
        return (self.filename, self.line, self.column or 1)

    def mlir(self) -> str:
        escaped = self.filename.replace("\\", "\\\\").replace('"', '\\"')
        return f'loc("{escaped}":{self.line}:{self.column or 1})'

    def __str__(self) -> str:
        return f"{self.filename}:{self.line}:{self.column or 1}"


_positions: dict = {}


def _frame_location(frame) -> Location:
    code = frame.f_code
    column = None
    try:
        positions = _positions.get(code)
        if positions is None:
            positions = _positions[code] = list(code.co_positions())
        index = frame.f_lasti // 2
        if 0 <= index < len(positions):
            start_line, _, start_col, _ = positions[index]
            if start_col is not None and start_line == frame.f_lineno:
                column = start_col + 1
    except AttributeError:  # Python < 3.11: no column information
        pass
    return Location(code.co_filename, frame.f_lineno, column)


def _internal(filename: str) -> bool:
    return os.path.abspath(filename).startswith(_PACKAGE_DIR)


def user_location(depth: int = 1) -> Location | None:
    """The innermost stack frame outside the sim package."""
    frame = sys._getframe(depth)
    while frame is not None and _internal(frame.f_code.co_filename):
        frame = frame.f_back
    return _frame_location(frame) if frame is not None else None


def trace_error(message: str, loc: Location | None = None,
                notes: Sequence[str] = ()) -> TraceError:
    """A TraceError at `loc` (default: the user's current line)."""
    if loc is None:
        loc = user_location(2)
    if loc is None:
        return TraceError(message, notes=list(notes))
    return TraceError(message, loc.filename, loc.line, loc.column,
                      notes=list(notes))


class LocationTable:
    """Location aliases of one scene (`#loc3 = loc("f.py":4:9)`)."""

    def __init__(self):
        self._aliases: dict = {}
        self._order: list[Location] = []

    def ref(self, loc: Location | None) -> str:
        """` loc(#locN)` for an operation, or '' without a location."""
        if loc is None:
            return ""
        key = loc.key()
        if key not in self._aliases:
            self._aliases[key] = len(self._order)
            self._order.append(loc)
        return f" loc(#loc{self._aliases[key]})"

    def render(self) -> str:
        return "".join(f"#loc{n} = {loc.mlir()}\n"
                       for n, loc in enumerate(self._order))


# -- Where operations go ------------------------------------------------------------

class Block:
    """A list of operations: the top of a body or an `scf.for` region."""

    def __init__(self, body: "Body", parent: "Block | None",
                 what: str = "body"):
        self.body = body
        self.parent = parent
        self.what = what
        self.items: list = []  # str lines, or (header, Block, footer)

    def encloses(self, other: "Block") -> bool:
        """Whether values of this block are visible in `other`."""
        while other is not None:
            if other is self:
                return True
            other = other.parent
        return False

    def render(self, indent: str) -> list[str]:
        lines = []
        for item in self.items:
            if isinstance(item, str):
                lines.append(indent + item)
            else:
                header, block, footer = item
                lines.append(indent + header)
                lines.extend(block.render(indent + "  "))
                lines.append(indent + footer)
        return lines


class Body:
    """One region of a scene op, traced from a Python function."""

    def __init__(self, scene, kind: str, owner: str, default_float: DType):
        self.scene = scene          # the tracer state of the scene
        self.kind = kind            # init, exact, num_steps, evaluate, total
        self.owner = owner          # "@B" or "@C"
        self.default_float = default_float
        self.root = Block(self, None)
        self.hoisted: list[str] = []  # constants and parameter reads
        self._constants: dict = {}
        self._params: dict = {}
        self._counters: dict[str, int] = {}
        self.args: dict[str, Value] = {}

    @property
    def title(self) -> str:
        return f"the {self.kind} body of {self.owner}"

    def fresh(self, prefix: str = "") -> str:
        count = self._counters.get(prefix, 0)
        self._counters[prefix] = count + 1
        return f"%{prefix}{count}"

    def render(self, indent: str) -> list[str]:
        return ([indent + line for line in self.hoisted] +
                self.root.render(indent))


class _State:
    block: Block | None = None


_state = _State()


def current_block(what: str = "this operation") -> Block:
    if _state.block is None:
        raise trace_error(f"{what} is only possible inside a traced body "
                          "(a buffer's init or exact, a component's "
                          "num_steps or evaluate, a total)")
    return _state.block


def current_body(what: str = "this operation") -> Body:
    return current_block(what).body


def in_trace() -> bool:
    return _state.block is not None


@contextmanager
def entered(block: Block):
    saved = _state.block
    _state.block = block
    try:
        yield block
    finally:
        _state.block = saved


# -- Values --------------------------------------------------------------------

class Value:
    """The result of a traced operation (or a body or loop argument).

    Python operators on it emit `arith` operations; see `sim.ops` for the
    functions. It has no Python value: using it where Python needs one (an
    `if`, `bool()`, `int()`, `range()`) raises TraceError.
    """

    __slots__ = ("name", "dtype", "block", "from_read", "loc", "const")

    def __init__(self, name: str, dtype: DType, block: Block,
                 from_read: bool = False, loc: Location | None = None,
                 const=None):
        self.name = name
        self.dtype = dtype
        self.block = block
        self.from_read = from_read
        self.loc = loc
        self.const = const

    __hash__ = object.__hash__

    def __repr__(self) -> str:
        return f"<sim.Value {self.name} : {self.dtype.mlir}>"

    # Python needs a concrete value: the tracer has none.
    def __bool__(self):
        loc = user_location(2)
        if loc is not None and _BUILTIN_MINMAX.search(
                linecache.getline(loc.filename, loc.line)):
            # Python's max() and min() compare their arguments and take
            # bool() of the comparison: that is how they come here.
            raise trace_error(
                "Python's max() or min() on a traced value: they compare "
                "with bool(), whose value is not known while tracing; use "
                "sim.max(a, b, ...) or sim.min(a, b, ...) (or, for a Python "
                "`if` on a traced value, sim.select(condition, a, b))", loc)
        raise trace_error(
            "a Python `if`, `while`, `and`, `or`, `not`, `assert`, "
            "comparison chain or bool() on a traced value: its value is not "
            "known while tracing; use sim.select(condition, a, b) (or "
            "sim.where) instead", loc)

    def __index__(self):
        raise trace_error(
            "a traced value used as a Python integer (range(), a list "
            "index, a slice, a repeat count): its value is not known while "
            "tracing, so a loop over it is a data-dependent loop bound; use "
            "sim.loop(lo, hi, carry=...) for a loop whose bound is a "
            "parameter")

    def __int__(self):
        raise trace_error("int() of a traced value: its value is not known "
                          "while tracing; convert it with sim.i32(x) or "
                          "sim.i64(x)")

    def __float__(self):
        raise trace_error("float() of a traced value (or a function of "
                          "Python's math module on it): its value is not "
                          "known while tracing; use sim.f32(x) / sim.f64(x) "
                          "and the functions of sim (sim.exp, sim.sqrt, ...)")

    __complex__ = __float__

    def __iter__(self):
        if self.dtype.is_vector:
            return iter([self[k] for k in range(self.dtype.lanes)])
        raise trace_error(f"iterating over a traced {self.dtype} scalar")

    def __len__(self):
        if self.dtype.is_vector:
            return self.dtype.lanes
        raise trace_error(f"len() of a traced {self.dtype} scalar")

    def __setitem__(self, key, value):
        raise trace_error("traced vectors are values, not arrays: use "
                          "v.replace(lane, x) (vector.insert) for a copy "
                          "with one lane changed")

    # __array_ufunc__ (numpy scalars in operators, numpy functions) is
    # attached in sim.ops with the operators.

    def __array__(self, *args, **kwargs):
        raise trace_error("a traced value cannot become a numpy array")

    def __format__(self, spec):
        return repr(self)


# Operators, properties and methods are attached in sim.ops.


def check_visible(value: Value, block: Block, loc: Location | None):
    """Raises unless `value` may be used in `block`."""
    if value.block.body is not block.body:
        where = value.block.body.title
        raise trace_error(
            f"a value traced in {where}"
            + (f" (line {value.loc.line})" if value.loc else "")
            + f" is used in {block.body.title}: a Python side effect (a "
            "global, a list or an attribute set in one body and read in "
            "another) cannot carry traced values between bodies; read the "
            "buffer or compute the value again", loc)
    if not value.block.encloses(block):
        raise trace_error(
            "a value traced inside a sim.loop body"
            + (f" (line {value.loc.line})" if value.loc else "")
            + " is used outside it: a Python side effect (appending to a "
            "list, setting a variable or attribute outside the loop) cannot "
            "carry traced values out of a loop; return them from the loop "
            "body (carry=...)", loc)


def emit(text: str, operands: Iterable[Value], result: DType | None,
         loc: Location | None = None, from_read: bool | None = None) -> Value | None:
    """Appends `<result> = <text><loc>` to the current block.

    `text` is the operation with its operands' names already in it;
    `operands` are checked for visibility and give `from_read`.
    """
    block = current_block()
    if loc is None:
        loc = user_location(2)
    operands = list(operands)
    for operand in operands:
        check_visible(operand, block, loc)
    if from_read is None:
        from_read = any(o.from_read for o in operands)
    ref = block.body.scene.locations.ref(loc)
    if result is None:
        block.items.append(text + ref)
        return None
    name = block.body.fresh()
    block.items.append(f"{name} = {text}{ref}")
    return Value(name, result, block, from_read, loc)


def constant(value, dtype: DType, loc: Location | None = None) -> Value:
    """A constant of `dtype` (a splat for a vector type; a sequence of
    `lanes` numbers for a vector constant), emitted once per body."""
    body = current_body("a constant")
    if loc is None:
        loc = user_location(2)
    elem = dtype.elem
    try:
        if isinstance(value, (list, tuple)):
            if not dtype.is_vector or len(value) != dtype.lanes:
                raise ValueError(f"{len(value)} values for {dtype.mlir}")
            parts = [_scalar_literal(v, elem) for v in value]
            literal = "dense<[" + ", ".join(parts) + "]>"
            python = tuple(value)
        else:
            literal = _scalar_literal(value, elem)
            if dtype.is_vector:
                literal = f"dense<{literal}>"
            python = value
    except (ValueError, OverflowError) as error:
        raise trace_error(f"the constant {value!r} is not a valid "
                          f"{dtype}: {error}", loc) from None
    key = (literal, dtype.mlir)
    found = body._constants.get(key)
    if found is not None:
        if found.dtype is not dtype:  # u64 and i64 share i64 constants
            return Value(found.name, dtype, found.block, False, found.loc,
                         found.const)
        return found
    name = body.fresh("c")
    ref = body.scene.locations.ref(loc)
    # A bool is MLIR's `true` or `false`, an i1 by itself: `true : i1` is
    # no attribute the parser reads (a vector's `dense<true>` takes its
    # type).
    typed = "" if dtype.is_bool and not dtype.is_vector else f" : {dtype.mlir}"
    body.hoisted.append(f"{name} = arith.constant {literal}{typed}{ref}")
    result = Value(name, dtype, body.root, False, loc, const=python)
    body._constants[key] = result
    return result


def _scalar_literal(value, elem: DType) -> str:
    if elem.kind == "float":
        return float_literal(float(value), elem)
    if isinstance(value, float):
        if not value.is_integer():
            raise ValueError("not an integer")
        value = int(value)
    return int_literal(int(value), elem)


def get_param(name: str, dtype: DType, loc: Location | None = None) -> Value:
    """`sim.get_param @name : type`, emitted once per body."""
    body = current_body(f"reading the parameter @{name}")
    found = body._params.get(name)
    if found is not None:
        return found
    if loc is None:
        loc = user_location(2)
    value_name = body.fresh("p")
    ref = body.scene.locations.ref(loc)
    body.hoisted.append(
        f"{value_name} = sim.get_param @{name} : {dtype.mlir}{ref}")
    result = Value(value_name, dtype, body.root, False, loc)
    body._params[name] = result
    return result


# -- Calling user functions -----------------------------------------------------------

class _ReturnRecorder:
    """Records where user functions return (the line of their `return`),
    through sys.setprofile while a scene is traced."""

    def __init__(self):
        self.returns: dict = {}
        self._previous = None
        self._active = 0

    def _profile(self, frame, event, arg):
        if event == "return":
            self.returns[frame.f_code] = _frame_location(frame)

    @contextmanager
    def active(self):
        if self._active or sys.getprofile() is not None:
            # Nested, or another profiler runs: leave it alone (yields
            # then get the function's first line as their location).
            self._active += 1
            try:
                yield
            finally:
                self._active -= 1
            return
        self._active += 1
        sys.setprofile(self._profile)
        try:
            yield
        finally:
            sys.setprofile(None)
            self._active -= 1


returns = _ReturnRecorder()


def function_location(fn: Callable) -> Location | None:
    code = getattr(fn, "__code__", None)
    if code is None:
        return None
    return Location(code.co_filename, code.co_firstlineno, 1)


def def_location(fn: Callable) -> Location | None:
    """The line of `fn`'s `def` (or its `lambda`), past its decorators: a
    decorated function's code starts at its first decorator."""
    loc = function_location(fn)
    if loc is None:
        return None
    if fn.__code__.co_name == "<lambda>":
        column = linecache.getline(loc.filename, loc.line).find("lambda")
        return Location(loc.filename, loc.line, column + 1 if column >= 0
                        else 1)
    for line in range(loc.line, loc.line + 50):
        text = linecache.getline(loc.filename, line)
        stripped = text.lstrip()
        if stripped.startswith(("def ", "async def ")):
            return Location(loc.filename, line, len(text) - len(stripped) + 1)
        if not text:
            break
    return loc


def call_body(fn: Callable, args: dict[str, Value], order: Sequence[str],
              what: str):
    """Calls a body function with its arguments; returns (result, the
    location of its `return`).

    A body's parameters bind in one of two ways, never silently mixed:

    - by name, when every parameter without a default is named like one
      of the body's arguments (`order`: i, t, n, dt for an evaluate body):
      a body takes only those it uses, in any order (`def f(i, dt)`);
      parameters with defaults named so get them too, others keep their
      defaults;
    - else by position, in the order `order` (`def f(k, time, steps, h)`):
      the required parameters get the first arguments. A parameter named
      like an argument must then be in that argument's place (`def f(j, n,
      dt)` would give `n` the argument t): anything else is a TraceError at
      the `def` line that names the argument names and their order.
    """
    import inspect
    try:
        signature = inspect.signature(fn)
    except (TypeError, ValueError):
        signature = None
    call_args: list = []
    call_kwargs: dict = {}
    if signature is not None:
        params = [p for p in signature.parameters.values()
                  if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD,
                                p.KEYWORD_ONLY)]
        variadic = any(p.kind == p.VAR_POSITIONAL
                       for p in signature.parameters.values())
        required = [p for p in params if p.default is p.empty]
        by_name = all(p.name in args and p.kind != p.POSITIONAL_ONLY
                      for p in required) and (required or not variadic)
        if by_name:
            call_kwargs = {p.name: args[p.name] for p in params
                           if p.name in args and p.kind != p.POSITIONAL_ONLY}
        else:
            names = ", ".join(order)
            if len(required) > len(order) or any(
                    p.kind == p.KEYWORD_ONLY for p in required):
                raise trace_error(
                    f"{what} takes {len(required)} arguments; it gets "
                    f"({names})", def_location(fn))
            count = len(order) if variadic and not required else len(required)
            positional = [p for p in params
                          if p.kind != p.KEYWORD_ONLY][:count]
            for k, p in enumerate(params):
                got = order[k] if p in positional else None
                if p.name in args and p.name != got:
                    gets = (f"would get the argument `{got}` by position"
                            if got is not None else
                            f"would not get the argument `{p.name}`")
                    listed = ", ".join(q.name for q in params)
                    raise trace_error(
                        f"{what} has the parameters ({listed}): `{p.name}` "
                        f"{gets}. A body's parameters are either all named "
                        f"among {names} (any of them, in any order; each "
                        f"gets its namesake) or take the arguments by "
                        f"position in the order ({names}), a parameter "
                        f"named like an argument in that argument's place",
                        def_location(fn))
            call_args = [args[n] for n in order[:count]]
    else:
        call_args = [args[n] for n in order]
    code = getattr(fn, "__code__", None)
    with returns.active():
        result = fn(*call_args, **call_kwargs)
        loc = returns.returns.get(code) if code is not None else None
    return result, (loc or function_location(fn))
