"""One `chute run` of a case with `--set` values into a directory, and what it left: its
summary.json and probes.csv rows. Shared by the bench scripts that run ensembles of cases."""
import csv
import json
import os
import subprocess


def run_case(chute, case, out, sets=(), env=None, check=False):
    """Runs `chute run case --out out --quiet --set s ...`; returns (summary, rows), rows [] when
    the run wrote no probes.csv. check: raise if chute exits with an error."""
    cmd = [chute, "run", case, "--out", out, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=check, capture_output=True, env=env)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    rows = []
    if os.path.exists(os.path.join(out, "probes.csv")):
        with open(os.path.join(out, "probes.csv")) as f:
            rows = list(csv.DictReader(f))
    return summary, rows
