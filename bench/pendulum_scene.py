"""The stiff pendulum of issue 19 (tests/cases/test_pendulum.cpp's scene) as a case file: a point
mass on a massless truss or cable of stiffness E A, released from rest at an angle, with its
exact period. Shared by bench/energy_monitor.py and bench/pendulum_acceptance.py."""
import math

G, EA, M, L = 9.81, 1.0e8, 1.0, 1.0


def period(theta0):
    """Exact period of the rigid pendulum released at theta0 (radians): 4 sqrt(L/g) K(sin(theta0/2)),
    K by the arithmetic-geometric mean."""
    k = math.sin(theta0 / 2)
    a, b = 1.0, math.sqrt(1 - k * k)
    while abs(a - b) > 1e-15:
        a, b = (a + b) / 2, math.sqrt(a * b)
    return 4 * math.sqrt(L / G) * math.pi / (2 * a)


def case(name, kind, deg, solver, position_probe=False):
    """The case text; `solver` holds the [solver] lines. The member is prestrained to carry the
    weight's component along it at release (no initial stretch wave)."""
    th = math.radians(deg)
    probe = '[[output.probes]]\nname = "mass"\nkind = "node_position"\n' if position_probe else ''
    return f'''name = "{name}"
[nodes]
anchor = [0.0, 0.0, 0.0]
mass = [{L * math.sin(th)!r}, 0.0, {-L * math.cos(th)!r}]
[materials.rod]
kind = "{kind}"
E = {EA!r}
area = 1.0
[[cables]]
name = "rod"
material = "rod"
path = ["anchor", "mass"]
prestrain = {M * G * math.cos(th) / EA!r}
[[point_masses]]
node = "mass"
mass = {M!r}
[boundary]
fixed = ["anchor"]
[loads]
gravity = [0.0, 0.0, {-G!r}]
[solver]
{solver}[output]
every = 1
{probe}[[output.probes]]
name = "rod"
kind = "line_force"
set = "rod"
[[output.probes]]
name = "energy"
kind = "energy"
'''
