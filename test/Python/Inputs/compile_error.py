"""A compiler diagnostic comes back as CompileError at the user's Python line
(sim-compile-error.test; this file is also the FileCheck file).

@Push reads @P, a buffer declared interp(none), inside its big step (it
sub-steps: num_steps): under hip that read needs an interpolated value,
which --sim-plan-memory rejects with an error at the read and a note at the
buffer.
"""
import sim
from sim import f32

s = sim.Scene("bad", range=16, dt=1e-3, max_steps=4)


# CHECK: bad.py:[[@LINE+1]]:2: note: @P is declared interp(none) here
@s.buffer(f32, interp="none")
def P(i):
    return 0.0


@s.buffer(f32)
def Q(i):
    return 1.0


@s.component(writes=P)
def Pull(i, n, dt):
    return P[i] + Q[i] * dt


@s.component(writes=Q)
def Push(i, n, dt):
    # CHECK: error: bad.py:[[@LINE+1]]:19: 'sim.read' op reads @P at an intermediate time of the big step {{.*}} but @P is declared interp(none)
    return Q[i] - P[i] * dt


@Push.num_steps
def Push(i, t):
    return sim.i32(2)


s.schedule(Pull)
s.observe(Q)

try:
    sim.compile(s, strategies=["hip"])
except sim.CompileError as error:
    for note in error.notes:  # printed first: this file checks them first
        print(note.replace(__file__, "bad.py"))
    print("error:", f"bad.py:{error.line}:{error.column}:", error.message)
    print("message:", str(error).splitlines()[1].strip())
else:
    print("no error")
# CHECK: message: return Q[i] - P[i] * dt

# The same scene compiles for simple, where nothing is interpolated.
bundle = sim.compile(s, strategies=["simple"])
print("simple:", bundle.strategies, f"{bundle.compile_seconds > 0}")
# CHECK: simple: ['simple'] True
