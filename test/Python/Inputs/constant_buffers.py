"""A constant buffer from Python (`@scene.buffer(constant=True)`): the text
it traces, a run that equals the same scene computing the field inline,
and the mistakes a user can make with one."""
import sim
from sim import f64, i32

N = 96
H = 1.0 / N


def rod(field: bool):
    scene = sim.Scene("rodc", range=N, dt=2e-7, max_steps=8, precision=f64)
    ratio = scene.param("ratio", 30.0)

    def conductivity(i):
        return sim.select(i >= N // 2, 1e-2 * ratio, f64(1e-2))

    if field:
        @scene.buffer(constant=True)
        def K(i):
            return conductivity(i)
        k = lambda i: K[i]
    else:
        # Inline, with the clamp a constant buffer's boundary applies.
        k = lambda i: conductivity(sim.max(sim.min(i, N - 1), 0))

    @scene.buffer()
    def U(i):
        return 1.0 + sim.cos(6.283185307179586 * (f64(i) + 0.5) * H)

    @scene.component(writes=U)
    def Conduct(i, n, dt):
        kw = 2.0 * k(i - 1) * k(i) / (k(i - 1) + k(i))
        ke = 2.0 * k(i + 1) * k(i) / (k(i + 1) + k(i))
        flux = ke * (U[i + 1] - U[i]) - kw * (U[i] - U[i - 1])
        return U[i] + f64(n) * dt * flux / (H * H)

    @Conduct.num_steps
    def Conduct(i, t):
        kmax = sim.max(sim.max(k(i - 1), k(i)), k(i + 1))
        return i32(0.4 * H * H / (kmax * scene.params.dt))

    scene.observe(U)
    return scene


text = rod(True).mlir()
print([line.strip() for line in text.splitlines() if "@K" in line][0])

field, inline = sim.compile(rod(True)), sim.compile(rod(False))
for strategy in ["simple", "hip", "lts"]:
    a = field.session(strategy, backend="cpu").run(200, output_every=200)
    b = inline.session(strategy, backend="cpu").run(200, output_every=200)
    print(strategy, "equal:", bool((a.buffers["U"][-1] == b.buffers["U"][-1]).all()))

# Mistakes.
scene = sim.Scene("bad", range=8, dt=0.1, max_steps=2)
for what, mistake in [
    ("interp", lambda: scene.buffer(constant=True, interp="cubic")),
]:
    try:
        mistake()
    except sim.TraceError as error:
        print(f"{what}: {error}")


@scene.buffer(constant=True)
def M(i):
    return sim.f32(i)


try:
    @M.exact
    def M(i, t):
        return sim.f32(0.0)
except sim.TraceError as error:
    print(f"exact: {error}")

try:
    @scene.component(writes=M)
    def Move(i, n, dt):
        return M[i]
except sim.TraceError as error:
    print(f"writes: {error}")

try:
    scene.observe(M)
except sim.TraceError as error:
    print(f"observe: {error}")
