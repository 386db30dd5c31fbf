#!/usr/bin/python3
"""Writes docs/verification.md from the tests' own output and docs/performance.md from the
benchmarks' results (bench/results/*.csv). Nothing in either page is typed in by hand.

    python3 scripts/gen-docs.py                  # both pages (runs the listed tests: a few minutes)
    python3 scripts/gen-docs.py performance      # only docs/performance.md (no runs)
    python3 scripts/gen-docs.py verification --build build

verification.md: every test of the test programs below is run; each row is the test, its result
and time, and the figures it prints (measured errors, with the tolerance it asserts in its
source). performance.md: the tables of bench/results, as the benchmark scripts wrote them
(bench/run_all regenerates those), with bench/summarize.py's acceptance table on top.
"""
import argparse, csv, datetime, math, os, platform, re, subprocess, sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = os.path.join(ROOT, "docs")
RESULTS = os.path.join(ROOT, "bench", "results")

# Test programs whose figures make the verification page, with what they check.
VERIFICATION = [
    ("test_verification", "the paper's pulley (F13) and bead (ellipse ODE) against independent references"),
    ("test_central_difference", "explicit central differences: stable step vs wave speeds and the assembled system's highest frequency, pulley and bead vs their references, massless nodes, mass scaling, restart"),
    ("test_references", "the independent references themselves (closed forms, ODE solutions, Hencky)"),
    ("test_cable", "two-node cable: force vs energy, tangent vs force (central differences), slack/taut switch"),
    ("test_sliding_cable", "sliding element: force vs energy, tangent vs force (central differences)"),
    ("test_sliding_group", "sliding groups: search, hand-overs, mass and gravity of the active element"),
    ("test_slider_friction", "the friction element (FR1-FR12): tangents vs central differences, capstan condition"),
    ("test_capstan", "friction at sliders against analytic capstan mechanics (FR13-FR16)"),
    ("test_membrane", "membranes: tangents vs central differences, patch tests, the explicit triangle bit for bit"),
    ("test_stiffness_bound", "the membranes' stable-step estimate (EX6m) against computed highest frequencies"),
    ("test_wrinkling", "the plane-stress wrinkling law: tangent vs stress, continuity across states"),
    ("test_pressure", "follower pressure: load stiffness vs central differences"),
    ("test_line_drag", "line drag: tangents vs central differences"),
    ("test_canopy", "canopy problems: Hencky's membrane, the airbag, energy and momentum"),
    ("test_face_drag", "face drag (FD1): tangents vs central differences, force vs an independent evaluation"),
    ("test_face_drag_plate", "a falling flat plate against its terminal speed"),
    ("test_coupling", "the coupling interface: tangents, case-file vs coupled pressure, implicit vs monolithic"),
    ("test_parachute_mesh", "the generated parachute: areas, lengths, groups, stress-free starts"),
    ("test_generated_flight", "generated parachute cases fly unchanged: completion, skirt radius"),
    ("test_triangle_flow_loads", "the airflow's face law in the membranes' pass (FL13) against the airflow term's, four at a time bit for bit"),
    ("test_mesh_import", "gmsh import: groups, round trip, errors"),
    ("test_bad_input", "bad input: one clear line and exit status 2 for each kind"),
    ("test_stress", "stability stress suite (short versions)"),
    ("test_c9_slider", "the half-scale C-9 with its slider to 1 s"),
    ("test_cable_discrete_gradient", "energy-momentum cable force (EM3-EM5, EM8): discrete-gradient property, tangent vs central differences"),
    ("test_membrane_discrete_gradient", "energy-momentum membrane force (EM9-EM10): discrete-gradient property across wrinkling states, tangent"),
    ("test_sliding_discrete_gradient", "energy-momentum sliding element (EM11): discrete-gradient property, tangent"),
    ("test_polyline_discrete_gradient", "energy-momentum condensed massless chain (EM12): discrete-gradient property, tangent, momenta, the placement of its nodes"),
    ("test_slider_whirl_damping", "whirl damping of a line node beside a slider (RG8): derivatives vs central differences, dissipation, momentum"),
    ("test_energy_momentum", "energy_momentum: stiff pendulums against the exact period and peak force, momenta of spinning free structures, dissipation, restart"),
    ("test_energy_momentum_cases", "energy_momentum on bead_1 and bead_5 (condensed chain) against the ellipse ODE, beside Bossak; a bead on a rope with mass against central differences"),
    ("test_static_far_start", "static ring on a rope from starts up to one rope length away (ST1) against the analytic equilibrium"),
    ("test_signals", "signals while the case loads and during a static solve: exit status and what is written"),
]

CSV_TABLES = [
    ("case_timings.csv", "Shipped cases: run time and error (`python3 bench/case_timings.py`; medians of 7 runs)"),
    ("work_precision_orders.csv", "Observed order in dt (`bench/work_precision.py`)"),
    ("output_cost.csv", "Cost of the VTU series (`python3 bench/output_cost.py`)"),
    ("scaling.csv", "Cost per Newton iteration against model size (`bench/scaling`)"),
    ("scaling_fit.csv", "Fitted exponents of the cost per iteration in dof"),
    ("stress.csv", "Stability stress suite, long runs (`python3 bench/stress.py`)"),
    ("explicit_vs_implicit.csv", "Implicit (Bossak) against explicit (central differences) on the same scenes (`bench/explicit_vs_implicit.py`; docs/explicit.md)"),
    ("peer_calculix.csv", "chute against CalculiX on the same membrane problems (`bench/peer/run_peer.py`)"),
]

# Result pages the benchmark scripts write as Markdown, included as they are.
MD_PAGES = [
    ("c9_speed_before_after.md", "The C-9 slider case before and after, one sitting (`bench/c9_speed/before_after.py`)"),
    ("c9_convergence_after.md", "The C-9 slider case: convergence in the step and the method (`bench/c9_convergence.py`)"),
    ("explicit_crossover.md", "Implicit against explicit over the canopy mesh (`bench/explicit_crossover.py`)"),
    ("energy_momentum_c9.md", "The C-9 slider case with the energy-momentum integrator"),
    ("lean_canopy_step.md", "The lean loop and chute's step: the table (`bench/speed/run.py`)"),
    ("explicit_step_before_after.md", "The explicit step before and after, one sitting"),
    ("face_loads_in_membrane_pass.md",
     "Face loads in the membranes' pass, and two threads in the caches, one sitting"),
    ("c9_slider_roundoff_band.md", "The C-9 slider case: what round-off alone moves (`bench/speed/roundoff_band.py`)"),
    ("flight_in_membrane_pass.md",
     "The airflow's loads in the membranes' pass, and the membranes in two halves, one sitting"),
    ("flight_per_node_work.md", "The airflow's per-node work in an explicit step, one sitting"),
    ("two_threads_whole_step.md", "Both threads on more of the explicit step, one sitting"),
    ("c9_slider_real_time_2026-11-28.md",
     "The C-9 slider case as shipped: line elements four at a time and mass scaling, one sitting"),
    ("serial_work_2026-11-28.md",
     "Both threads on the step's serial work, and the airflow's per-step cost, one sitting"),
    ("threads_generated_c9.md", "One thread against two on the generated C-9 (`bench/speed/threads.py`)"),
    ("settle_in_parts_2026-11-28.md",
     "The sliders' settling and commits on both threads, and the render plugin, one sitting"),
    ("mass_scaling_flight.md",
     "Selective mass scaling in the generated cases: flight figures and speed "
     "(`bench/flight/mass_scaling_flight.py`)"),
    ("line_step_margin.md", "Suspension lines that set the explicit step (`bench/flight/line_step_margin.py`)"),
    ("lean_line_residuals_2026-11-28.md",
     "The lines' residual-only kernels and the energy balance's line energies, one sitting"),
]


def cell(text):
    return str(text).replace("|", "\\|").replace("\n", " ")


def number(text):
    try:
        x = float(text)
    except ValueError:
        return text
    if not math.isfinite(x):
        return text
    if x == int(x) and abs(x) < 1e15 and "." not in text and "e" not in text.lower():
        return text
    return f"{x:.4g}"


def header(what, how, machine):
    stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    where = ""
    if machine:  # the runs happen now, on this machine
        where = (f" on {platform.node() or 'this machine'} ({os.cpu_count()} cores, load "
                 f"{' / '.join(f'{l:.1f}' for l in os.getloadavg())})")
    return (f"<!-- Generated by scripts/gen-docs.py ({how}); do not edit by hand. -->\n\n"
            f"# {what}\n\n"
            f"Generated {stamp}{where} by `python3 scripts/gen-docs.py {how}`.\n")


# --- verification ---------------------------------------------------------------------------

RUN = re.compile(r"^\[ RUN      \] (\S+)")
END = re.compile(r"^\[\s+(OK|FAILED|SKIPPED)\s+\] (\S+)(?: \((\d+) ms\))?")


def run_tests(binary):
    """[(test, result, ms, printed lines)] from one gtest program."""
    p = subprocess.run([binary, "--gtest_color=no"], capture_output=True, text=True,
                       env={k: v for k, v in os.environ.items() if k != "DISPLAY"})
    rows, current, printed = [], None, []
    for line in p.stdout.splitlines():
        if m := RUN.match(line):
            current, printed = m.group(1), []
        elif (m := END.match(line)) and m.group(2) == current:
            rows.append((current, m.group(1).lower(), m.group(3) or "", printed))
            current = None
        elif current is not None and not line.startswith("["):
            if line.strip() and not line.startswith(("Note:", "/")):
                printed.append(line.strip())
    return rows, p.returncode


def verification(build):
    out = [header("Verification", "verification", True),
           "\nEach test compares chute with an analytic or independent reference and asserts a "
           "tolerance (in its source); the figures are what the test printed in this run. "
           "The equations are in [formulation.md](formulation.md).\n"]
    total = failed = 0
    for name, what in VERIFICATION:
        binary = os.path.join(build, "bin", name)
        if not os.path.exists(binary):
            print(f"gen-docs: {binary}: not built, skipped", file=sys.stderr)
            continue
        print(f"gen-docs: running {name}", file=sys.stderr)
        rows, status = run_tests(binary)
        out.append(f"\n## `{name}`: {what}\n")
        out.append("| test | result | measured (as printed by the test) |")
        out.append("|---|---|---|")
        for test, result, ms, printed in rows:
            total += 1
            failed += result == "failed"
            shown = "<br>".join(cell(l) for l in printed[:12])
            if len(printed) > 12:
                shown += f"<br>(… {len(printed) - 12} more lines)"
            out.append(f"| `{test}` | {result}{f' ({int(ms) / 1000:.2f} s)' if ms else ''} | {shown} |")
    out.insert(1, f"\n**{total - failed} of {total} tests passed.**\n")
    open(os.path.join(DOCS, "verification.md"), "w").write("\n".join(out) + "\n")
    print(f"gen-docs: docs/verification.md: {total} tests, {failed} failed", file=sys.stderr)
    return failed == 0


# --- performance ----------------------------------------------------------------------------

TWO_THREADS = """
## Two threads

Assembly runs in two parts at once (`StructuralSystem::splitAssembly`,
`assembly/TwoPartRunner`): membranes, pressure, face drag, cables, line drag (which reads the
sliding groups' active elements, set between assemblies) and a coupled flow's surface loads may
go to a second thread; sliding groups and point masses stay on the first. The split is made once
per scene from costs per element measured on the C-9 slider case (one thread, residual only, in
units of the explicit membrane triangle: pressure face 0.42, face-drag face 0.72 (a load the
membranes' pass takes, P2: 0.23 added to the membranes), line element 0.7 (four at a time,
CB1: 0.55, and 0.6 for the drag of its set taken into that pass), line-drag segment 0.7, sliding element 0.9 and 8 more per slider, quad 5; the airflow's face 1.3,
measured on the generated C-9 in free flight, or 0.85 added to the membranes where their pass
takes it, FL13; largest first, each to the lighter part, a tie to the second; the membranes as
two halves of their cost, halved where the halves land in different parts), never from timings,
the thread count or the instruction set. Over 0.5 s of the C-9
slider case on one thread the two parts take 0.31 s and 0.32 s; the costs used before (line drag
at 0.4 where its kernel, since made shorter, cost 0.85; sliding groups and line drag held on the
first) gave the first 0.49 s of 0.87 s. The second part's residual and matrix are added to the
first's in a fixed order: a run gives the same bits on one thread or two
(`TwoPartAssembly.OneThreadAndTwoGiveTheSameBits`). `CHUTE_THREADS=1` runs both parts one after
the other on one thread. Against the single-pass sum before it, results differ by round-off only:
the 19 shipped cases' probes (C-9 cases and payload_fixed_slider to 0.3 s) by at most 7e-11 of
a column's largest value (columns zero by symmetry: 4e-16 absolute; 10 cases identical), except
the folded-start C-9 runs, whose dynamics amplify round-off (c9_slider 6.8e-10, c9_no_slider
7.7e-7 of the strain energy at 0.3 s with Bossak; with central differences the C-9's skirt
radius moves by 1e-3 at 0.3 s, round-off growing about e-fold every 5 ms). The worker polls for 0.3 ms after each part before it sleeps (the gap
between two explicit steps' assemblies is under 0.1 ms on the C-9; an implicit iteration costs
the second core up to 0.3 ms of polling per assembly); OpenMP was tried first and left out: libgomp's spin, fixed at
program start, doubled the CPU time of implicit runs. Two other evaluations of the explicit path
that do not touch each other's data share the threads the same way: the lumped mass of the
sliding elements at the step's new positions runs alongside the assembly, on the thread that
finishes its part first (`StructuralSystem::assemble(p, wantMatrix, alongside)`), and so does,
before a step that estimates its stable step, the stiffness bound at those positions of the
terms whose bound is a function of positions and time alone (`Term::stiffnessBoundOfPositions`:
membranes, cables; the sliding groups' and contact's bounds read their state and are added after
it, in every estimate, so that the sum is the same made alongside or in place); the energy balance's load
residual and energy run one on each thread (`StructuralSystem::runTwo`). The sliders' work
at the step's new positions (EX3: the notes of nodes passed, the moves onto nodes reached, the
search, the moves at the step's end; `StructuralSystem::settleExplicitMotion`) runs in two parts
of the sliding groups that share no free node (`solver/TwoPartSplit`: on the C-9 the four
grommets' lines, seven each; the confluence they all reach is held), each part's groups in
order, the same bits as all of them in order
(`C9Slider.SettlingTheSlidersInTwoPartsGivesTheBitsOfTheSourcesInOrder`); their commits
likewise, in two parts by cost (`Term::commitsApart`). A job
reaches the worker through tickets it polls, each on a cache line of its own, the mutex taken only
by a thread that stopped polling and sleeps. Each is done by one
thread in its own order, so none changes a bit (`GeneratedFlight.OneThreadAndTwoFlyTheSameBits`:
a folded generated flight, rows and steps bit for bit). On the generated 12k and 24k C-9 two
threads run 1.45x and 1.35x faster than one (whole process; target 1.7x; 1.47-1.56x before the
membranes took four triangles at a time): the airflow's passes and the membranes fill the two
parts about equally, and what is left is the step's own work between assemblies on the first
thread (the update, the commit, the energy balance's larger half: 0.30 s of the 12k mesh's
1.69 s on one thread over 0.06 s) and the moving mass and stable-step bound alongside the
assembly (about 0.17 s), which did not shrink with the parts.

Two threads pay only while the machine has a core free for the second. On a loaded machine the
first thread waits for a worker that waits for a core: with the CPU taken by a build or by two
busy loops, the explicit C-9 (0.5 s) took 4.4-5.5 s on two threads against 3.3-3.8 s on one
(before the explicit step's work was cut). So the runner times windows of 16 assemblies in each
mode (`summary.json`: `system.assemblies_on_two_threads` and
`system.assemblies_split_on_one_thread`) and keeps two threads unless one was more than 15 %
faster (window medians), timing the other again every 32 windows, and after a switch to one
thread after 2, 4, 8, ... windows; where two threads were more than 1.25 times faster at each
timing of one, one thread is timed again after 64, 128, then 256 windows (at every 32, 3 % of the
C-9 slider case's assemblies ran on one thread); since the parts' results do not depend on the
mode, this changes no bit. At start-up the BLAS library's worker spins on the second core for about 0.1 s:
two threads timed then lost to one, and keeping the faster outright for 32 windows put a third
of a generated C-9 run (0.06 s, 12k triangles) on one thread (1.54-1.74 s in the run against
1.34-1.39 s now, six runs each). Under two busy loops that run takes 3.09-3.25 s with the runner
and 3.06-3.28 s on one thread. The worker belongs to the BLAS the sparse solvers link (OpenBLAS
on Debian) and is made before `main`, so chute cannot stop it; `OPENBLAS_NUM_THREADS=1` in the
environment does (the C-9 slider case, 1 s: wall 0.96x, five pairs; c9_payload_reorientation,
implicit, 0.99x in three). Yielding the core while polling was tried instead of the runner's
choice and made loaded runs far slower (7-9 s: a yielded thread waits for a whole time slice).
The first measurements of the two parts: the C-9 slider case, 1 s, medians of paired runs
(bench/results/two_threads.md); today's: bench/results/explicit_step_before_after.md.
"""

LEAN_LOOP = """
## The explicit step against a lean fused canopy loop (`bench/speed/run.py`)

One process times both on the generated full-scale C-9 in free flight (28 gores, loads from the
airflow, gravity): a lean, fused pass over the canopy's triangles (membrane with branch-free
wrinkling, pressure, face drag: gather, compute, scatter; built for the baseline instruction set)
and chute's whole explicit step (every term, lines included, the update, the energy balance, the
stable step), CPU per triangle, one thread.
[bench/results/lean_canopy_step.md](../bench/results/lean_canopy_step.md) (below): chute's step
is 1.23-1.59 times the lean loop at 3.4k-24.5k triangles in its latest run (1.41 at 12k, 1.59 at
24k; the target is 2.0), 92-108 ns per triangle and step against the lean loop's 66-75 ns on that
day's host. Without AVX2 (`CHUTE_SIMD=baseline`,
[bench/results/lean_canopy_step_baseline.md](../bench/results/lean_canopy_step_baseline.md)):
2.18-2.29, 88-92 ns. The lean loop's own time moves by up to 15 % from run to run on this shared
machine (40-47 ns), the ratio with it.

What brought it there, each kept because it paid (bench/results/explicit_step_before_after.md):
the residual scattered node by node, the update in one pass, cached cable forces and masses, the
membranes' weight from shares made once; the explicit triangle (`kernels/MembraneTriangleForce.hpp`:
a record laid out for the pass, the law's constants made once, the wrinkling state selected by
bits rather than branches; membraneForce's bits); the triangles four at a time with AVX2 (below);
line drag with one square root and one division on its path (it had two roots and a division
waiting on one another) and face drag with none (g from the unnormalised area vector); the
explicit cable's fast path kept with gravity (the general path had cost three times as much in
free flight); the airflow's face passes multiplying by reciprocals where they divided by
constants; the airflow's loads in the membranes' own pass (below). Tried and not kept: the
airflow's passes four faces at a time on their own (bit for bit the scalar ones, and no faster:
gathering six node vectors per face into lanes cost what the arithmetic saved; inside the
membranes' kernel the positions are gathered already). Fewer steps:
`solver.mass_scaling_quantile` (docs/explicit.md, selective mass scaling): on this parachute the
least nodal step is 0.66-0.68 of the 1 % quantile, and scaling the 1 % that set it takes 1.4x
fewer steps; the generated cases carry it (q = 0.01): steps per simulated second 24,000 at 24.5k
triangles against 33,500 without, the exponents of steps and CPU per simulated second against
triangles ^0.23 and ^1.29 against ^0.38 and ^1.44, and 1 s of the 12.4k and 24.5k C-9 on two
threads 13.7 and 33.4 s of wall time against 19.1 and 45.6 s, their flight figures within
round-off ([bench/results/mass_scaling_flight.md](../bench/results/mass_scaling_flight.md)).

## Four at a time

The explicit step's membrane triangles go through `kernels/MembraneTriangleBatch` four at a time:
the operations of `membraneTriangleForce` in its order, each on four triangles side by side (GCC's
vector extension), so that each lane gives that function's bits; the test
`MembraneKernel.FourTrianglesAtATimeAreTheExplicitTriangleBitForBit` compares 216,000 numbers over
taut, wrinkled and slack lanes with wrinkling on and off, on each copy the processor can run.
The kernel is built twice, for the baseline instruction set and for AVX2
(`kernels/SimdCopies`: the AVX2 copy where the processor has it, unless `CHUTE_SIMD=baseline`);
neither fuses a multiply and an add, so a run gives the same bits on either processor. Without
AVX2 the step takes the triangles one at a time: the baseline copy, two SSE2 operations for each
of the kernel's, was slower than that (chute's step 113 ns per triangle against 100). The nodes'
positions are read straight into the lanes: staged through memory by single stores, each
four-lane load waited for those stores. On the C-9 slider case the membranes went from 0.34 s to
0.19 s of 0.5 s simulated (one thread), on the generated 12k C-9 from 28 to 21 % of the step.

## Face loads in the membranes' pass

On an explicit step the pressure and face drag of a triangle are one vector per node,
`((c g - p)/3) a` (docs/formulation.md P2): the same kernel adds it to the triangle's forces from
the positions it has already gathered, with the velocities gathered beside them, and scatters both
at once (`membraneTriangleForcesAndLoads`; `triangleFaceLoad` its one-at-a-time twin, each lane its
bits). The membrane term takes the loads of every triangle whose set has at most one pressure and
one face drag (`MembraneTerm::takeFaceLoads`); the pressure and face-drag terms then leave those
faces out on the explicit step's evaluations only (`fusedFaceLoads`), and every other evaluation
(the start, the energy balance's loads, output, implicit steps) has each term add its own. The
loads the energy balance keeps are captured in the pass (`SystemAssembler::captureFusedLoads`).
On the C-9 slider case the three terms' 0.858 s became 0.687 s of the step's 1 s (two threads);
whole runs 0.87-0.91x on one thread and 0.95-1.01x on two: the second thread now reads the
velocities too, and the first thread's update waits on the cache lines it shares. On that case
one thread is now the faster (1.61-1.62 s of wall time per simulated second against 1.68-1.71 s
on two; bench/results/face_loads_in_membrane_pass.md); the generated 12k C-9 in free flight still
runs 1.43x faster on two.

## The airflow's loads in the membranes' pass, and the membranes in two halves

The airflow's loads (docs/flight.md, FL1-FL12) first lost their second pass over the faces: the
canopy's velocity (FL1) is its nodes' velocities weighted by their area shares at the step's
start, and the cloth's outflow is linearised about the step's start pressure (FL9), so every
face's loads are made in the pass that makes its area vector. Then, on explicit steps, a canopy
of triangles has them made inside the membranes' four-lane kernel (docs/formulation.md FL13,
`membraneTriangleForcesAndFlow`, `triangleFlowLoad` its one-at-a-time twin, each lane its bits):
the face law at the ambient inside pressure added to the triangle's forces, the volume, area and
cloth outflow summed lane by lane, and each node's shares of the area vectors and area added to
the airflow term's per-node records; the term then finds the captured air's update and adds the
inside pressure per node. On `cases/c9_flight.toml` (bench/flight/cost.sh, one sitting) the
airflow's step costs 1.553x the instructions of a constant-pressure step at the start of the day,
1.429x with one pass, 1.263x with the loads in the membranes' pass, 1.273x with that pass in two
halves (below; the criterion of docs/flight.md is 1.2x).

The canopy's loads and membranes were then one term, on one thread of two: the membranes' pass is
made in two halves of its batches, one in each of the assembly's parts, when the split puts them
there (`Term::assemblesInHalves`), and the airflow's per-node work after it in two halves of the
nodes. Every number is the same on one thread or two. The two halves' lane sums must not share
a cache line: while they did, both threads adding to it at every batch made two threads slower
than one at 24k triangles. Generated 12k C-9 in free flight
(bench/results/flight_in_membrane_pass.md, wall medians of 9 pairs): one thread 0.892x the start
of the day, two threads 0.944x; two threads are 1.32x one (1.43x before: one thread gained more).
At 24k: 58.8 s and 42.6 s of wall time per simulated second on one and two threads (65.7 s and
44.8 s at the start). The C-9 slider case: one thread 0.998x, two threads 0.960x, both about
1.62 s of wall time per simulated second.

What the airflow's loads then still cost was mostly per node, not per face: its air's mass (FL11)
is a mass that changes at commit (`Term::massChangesAtCommit`, EX2), formed with each lumped mass
from the term's per-node values straight to their equations, where as a mass that moved with the
positions it took an inertia-only assembly, a clearing of its equations and a comparison and copy
of every position at every step; the halves' node records are merged and loaded in one pass
(`SystemAssembler::addPerNode`). Same bits. On `cases/c9_flight.toml` the airflow's step costs
1.198x the instructions of the constant-pressure step (1.277x before; the criterion 1.2x); the
generated 12k C-9 in free flight runs in 0.925x (one thread) and 0.929x (two) of its wall time
before (bench/results/flight_per_node_work.md).

On systems of 2000 dofs or more (`ExplicitSettings::halvesFromDofs`; 6000 before the C-9 slider
case's measurement below) the step's passes over all
dofs (EX1's prediction and update, EX7's shifted positions) run in halves on the assembly's two
threads; each assembly part clears its own residual on its thread and the parts' sum is made
half by half just before each half's update (`StructuralSystem::assembleForHalves`,
`useResidualInHalves`), instead of a serial pass of its own; the membranes' energy for the
balance is made in the same halves as their assembly (`Term::addEnergyHalf`). Same bits. The
generated 12k C-9 in flight: two threads 1.53x one (1.46x before), 0.901x of the day's first
build's wall time on two threads and 0.923x on one; at 24k two threads are 1.59x one
(bench/results/two_threads_whole_step.md). The second thread still spins for 7.7 % of the run
while the first works alone between assemblies (the airflow's commit, the canopy's velocity, the
stable step, the balance's bookkeeping).

On the C-9 slider case (2,448 equations, 28 sliding groups) the first thread worked alone for
about a third of each two-thread step (perf: the second thread spinning 30 % of its time), and
then waited for the second thread's longer part (23 % of its time). Kept, same bits
(bench/results/c9_slider_serial_work.md): the membranes' and cables' stiffness bound made
alongside the assembly also where sliding groups are (their own bound added after it), the step's
passes in halves from 2000 dofs, the explicit cable force and the line drag's residual inlined
into their terms' loops (1.3 % and 0.7 % of the case's instructions); and the energy balance's
membrane strain energy is made four triangles at a time (`kernels::membraneTriangleEnergies`,
the same bits as one at a time: 25 % fewer instructions in that pass). The case to 1 s with its
frames on two threads: 0.918x the wall time before (9 pairs). Measured and not kept: the terms'
assembly costs measured again (a cable element 1.1 of a triangle, a line-drag segment 0.9-1.2,
where 0.7 had been taken) put the cables in the first part: the first thread waited less, the
run was no faster (1.025x, 15 pairs).
"""


def performance():
    out = [header("Performance", "performance", False),
           "\nThe benchmark results in `bench/results/` (`bench/run_all` regenerates them; "
           "[bench/README.md](../bench/README.md) explains each benchmark). Wall times depend on "
           "the machine and its load; the machine notes are in `bench/results/machine.txt`.\n",
           TWO_THREADS, LEAN_LOOP]
    sys.path.insert(0, os.path.join(ROOT, "bench"))
    try:
        import summarize
        out.append("\n## Acceptance figures (`bench/summarize.py`)\n")
        out.append(summarize.summary_table())
    except (ImportError, AttributeError, KeyError, ValueError) as e:
        print(f"gen-docs: bench/summarize.py: {e}", file=sys.stderr)
    for name, what in MD_PAGES:
        path = os.path.join(RESULTS, name)
        if not os.path.exists(path):
            continue
        text = open(path).read()
        # The page's own title, if any, gives way to this one.
        lines = [l for l in text.splitlines() if not l.startswith("# ")]
        out.append(f"\n## {what}\n\n`bench/results/{name}`\n")
        out.append("\n".join(lines).strip() + "\n")
    for name, what in CSV_TABLES:
        path = os.path.join(RESULTS, name)
        if not os.path.exists(path):
            continue
        rows = list(csv.reader(open(path)))
        if not rows:
            continue
        out.append(f"\n## {what}\n\n`bench/results/{name}`\n")
        out.append("| " + " | ".join(cell(h) for h in rows[0]) + " |")
        out.append("|" + "---|" * len(rows[0]))
        for r in rows[1:]:
            out.append("| " + " | ".join(cell(number(x)) for x in r) + " |")
    open(os.path.join(DOCS, "performance.md"), "w").write("\n".join(out) + "\n")
    print("gen-docs: docs/performance.md written", file=sys.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("pages", nargs="*", help="verification, performance (default: both)")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    a = ap.parse_args()
    pages = a.pages or ["performance", "verification"]
    for p in pages:
        if p not in ("verification", "performance"):
            ap.error(f"unknown page '{p}' (verification, performance)")
    ok = True
    if "performance" in pages:
        performance()
    if "verification" in pages:
        ok = verification(a.build)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
