"""`chute run CASE --out DIR --restart FILE` on a fresh copy of a run's output directory, then
the promise of a refused restart: nothing in DIR changed. Prints chute's stderr as it came and,
when a refused restart (exit 2) changed the directory, one more line, so the harness sees a
broken promise.
   restart_check.py CHUTE CASE PRISTINE_DIR WORK_DIR CHECKPOINT"""
import hashlib
import os
import shutil
import subprocess
import sys

chute, case, pristine, work, ckpt = sys.argv[1:6]


def digest(d):
    h = hashlib.sha256()
    for root, dirs, files in sorted(os.walk(d)):
        dirs.sort()
        for f in sorted(files):
            p = os.path.join(root, f)
            h.update(os.path.relpath(p, d).encode())
            with open(p, "rb") as fh:
                h.update(fh.read())
    return h.hexdigest()


shutil.rmtree(work, ignore_errors=True)
shutil.copytree(pristine, work)
before = digest(work)
p = subprocess.run([chute, "run", case, "--quiet", "--out", work, "--restart", ckpt],
                   stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
sys.stderr.write(p.stderr.decode("utf-8", "replace"))
if p.returncode == 2 and digest(work) != before:
    sys.stderr.write("restart_check: a refused restart changed the output directory\n")
shutil.rmtree(work, ignore_errors=True)
sys.exit(p.returncode if p.returncode >= 0 else 128 - p.returncode)
