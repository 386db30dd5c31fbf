"""`chute mesh parachute ARGS` writing a mesh and a case, then the promise of a generated case:
`chute run` takes it and flies it two steps. Prints chute's stderr as it came; when the
generation succeeded but the case is not valid TOML, is refused or fails, one more line, so the
harness sees a broken promise. ARGS may name --out and --case themselves (paths with quotes,
newlines, ...); otherwise they go into WORK_DIR.
   parachute_check.py CHUTE WORK_DIR [ARGS...]"""
import os
import shutil
import subprocess
import sys
import tomllib

chute, work = sys.argv[1:3]
args = sys.argv[3:]
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
if "--out" not in args:
    args += ["--out", os.path.join(work, "p.msh")]
if "--case" not in args:
    args += ["--case", os.path.join(work, "p.toml")]
case = args[args.index("--case") + 1]
p = subprocess.run([chute, "mesh", "parachute", "--quiet"] + args, stdin=subprocess.DEVNULL,
                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
sys.stderr.write(p.stderr.decode("utf-8", "replace"))
if p.returncode != 0:
    sys.exit(p.returncode if p.returncode >= 0 else 128 - p.returncode)
try:
    with open(case, "rb") as f:
        dt = tomllib.load(f)["solver"]["dt"]
except Exception as e:  # the generated case must be TOML with a [solver] dt
    sys.stderr.write("parachute_check: the generated case is not a valid case: %s\n" % e)
    sys.exit(9)
r = subprocess.run([chute, "run", case, "--quiet", "--out", os.path.join(work, "out"), "--set",
                    "solver.t_end=%r" % (2 * dt)], stdin=subprocess.DEVNULL,
                   stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
if r.returncode != 0:
    sys.stderr.write("parachute_check: the generated case did not fly two steps (exit %d): %s\n"
                     % (r.returncode, r.stderr.decode("utf-8", "replace").strip()[:300]))
    sys.exit(9)
shutil.rmtree(work, ignore_errors=True)
sys.exit(0)
