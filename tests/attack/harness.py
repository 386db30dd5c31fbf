"""Runs hostile inputs against the real `chute` binary and classifies each outcome.

Used by tests/attack/corpus.py (the short corpus in ctest) and bench/attack/attack.py (the long,
generated and mutated run). Every input runs in its own process group with a wall-time limit and
a memory limit (RLIMIT_AS in a plain build; ASan's hard RSS limit in a sanitizer build, where an
address-space limit cannot be used), and is put in exactly one class:

  error     exit 2 and exactly one stderr line "chute: ..." (the promised clean error)
  success   exit 0, stderr only "chute: ..." lines (no foreign log lines)
  failed    exit 3 (a run that started and stopped early) with one stderr line
  crash     killed by a signal, or a sanitizer report
  hang      still running at the time limit
  memory    out of memory (bad_alloc reported, RLIMIT_AS or ASan's RSS limit hit)
  command   a marker file the input's script would create exists (a command ran)
  broken    anything else: another exit status, several or foreign stderr lines, or an outcome
            the input's expectation does not allow (e.g. success for an input that must fail)
"""

import collections
import os
import re
import resource
import shutil
import signal
import subprocess
import time

SANITIZER = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:|UndefinedBehaviorSanitizer")
SANITIZER_MEMORY = re.compile(r"hard rss limit|allocation-size-too-big|out of memory|exceeds maximum supported size")
CLASSES = ["error", "success", "failed", "crash", "hang", "memory", "command", "broken"]
BAD = ["crash", "hang", "memory", "command", "broken"]


class Outcome:
    def __init__(self, cls, rc, stderr, seconds, why=""):
        self.cls, self.rc, self.stderr, self.seconds, self.why = cls, rc, stderr, seconds, why


def sanitized(binary):
    """True when the binary was built with AddressSanitizer."""
    try:
        out = subprocess.run(["ldd", binary], capture_output=True, text=True, timeout=30).stdout
    except (OSError, subprocess.SubprocessError):
        return False
    return "libasan" in out


def runtime_libraries():
    """The compiler's ASan and UBSan runtimes (to preload into an uninstrumented host)."""
    libs = []
    for name in ("libasan.so", "libubsan.so"):
        try:
            path = subprocess.run(["gcc", "-print-file-name=" + name], capture_output=True,
                                  text=True, timeout=30).stdout.strip()
        except (OSError, subprocess.SubprocessError):
            path = ""
        if os.path.isabs(path):
            libs.append(path)
    return libs


def run(cmd, cwd, expect, timeout=20.0, mem_mb=4096, asan=False, marker=None, env=None):
    """Runs cmd (a list) in cwd; expect is the set of classes this input may end in."""
    if asan:
        # An ASan/UBSan build runs 2-3x slower (measured on the corpus): its limits are 3x, so
        # a slow input is not taken for a hang; an endless loop still is.
        timeout *= 3
    full_env = dict(os.environ if env is None else env)
    full_env.setdefault("LC_ALL", "C")
    if asan:
        full_env["ASAN_OPTIONS"] = (
            "detect_leaks=0:hard_rss_limit_mb=%d:max_allocation_size_mb=%d:"
            "allocator_may_return_null=1" % (mem_mb, mem_mb))
        full_env["UBSAN_OPTIONS"] = "print_stacktrace=1:halt_on_error=1"
        if any(str(a).endswith(".so") for a in cmd):
            # A host (Python) loading the instrumented libchute_coupling.so: the sanitizer
            # runtimes must come first in its library list.
            full_env["LD_PRELOAD"] = " ".join(runtime_libraries())

    def limits():
        os.setsid()
        if not asan:
            resource.setrlimit(resource.RLIMIT_AS, (mem_mb << 20, mem_mb << 20))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    if marker and os.path.exists(marker):
        os.remove(marker)
    out = written_dir(cmd, cwd)
    if out and os.path.exists(out):
        out = None  # there before the run: not the run's to leave alone
    start = time.time()
    p = subprocess.Popen(cmd, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, preexec_fn=limits, env=full_env)
    hung = False
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        hung = True
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = p.communicate()
    try:  # whatever the input left running in its group
        os.killpg(p.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    seconds = time.time() - start
    err = err.decode("utf-8", "replace")
    outcome = classify(p.returncode, err, hung, seconds, expect, marker)
    # A refused `chute run` writes nothing: an --out directory that did not exist must not exist
    # after it.
    if outcome.cls == "error" and out and os.path.exists(out):
        return Outcome("broken", p.returncode, err, seconds, "a refused run wrote " + out)
    return outcome


def written_dir(cmd, cwd):
    """The --out directory of a `chute run` command (not a restart, which has its own check),
    or None."""
    cmd = [str(a) for a in cmd]
    if len(cmd) < 2 or cmd[1] != "run" or "--restart" in cmd or "--out" not in cmd:
        return None
    i = cmd.index("--out")
    return os.path.join(cwd, cmd[i + 1]) if i + 1 < len(cmd) else None


def classify(rc, err, hung, seconds, expect, marker):
    lines = [l for l in err.splitlines() if l.strip()]
    if marker and os.path.exists(marker):
        return Outcome("command", rc, err, seconds, "marker file created")
    if hung:
        return Outcome("hang", rc, err, seconds, "no exit within the time limit")
    if SANITIZER_MEMORY.search(err) and (SANITIZER.search(err) or "AddressSanitizer" in err):
        return Outcome("memory", rc, err, seconds, "sanitizer memory limit")
    if SANITIZER.search(err):
        return Outcome("crash", rc, err, seconds, "sanitizer report")
    if rc is None or rc < 0:
        return Outcome("crash", rc, err, seconds, "signal %s" % (-rc if rc else "?"))
    if "out of memory" in err or "bad_alloc" in err:
        return Outcome("memory", rc, err, seconds, "out of memory")
    one_line = len(lines) == 1 and lines[0].startswith("chute: ")
    if rc == 0:
        cls = "success" if all(l.startswith("chute: ") for l in lines) else "broken"
        why = "" if cls == "success" else "foreign stderr lines on success"
    elif rc == 2:
        cls, why = ("error", "") if one_line else ("broken", "exit 2 without one 'chute:' line")
    elif rc == 3:
        cls, why = ("failed", "") if one_line else ("broken", "exit 3 without one 'chute:' line")
    else:
        cls, why = "broken", "exit status %d" % rc
    if cls != "broken" and cls not in expect:
        return Outcome("broken", rc, err, seconds, "%s, expected %s" % (cls, "/".join(sorted(expect))))
    return Outcome(cls, rc, err, seconds, why)


class Table:
    """Outcomes per input class; prints the table of the acceptance criteria."""

    def __init__(self):
        self.rows = collections.OrderedDict()
        self.bad = []

    def add(self, input_class, name, outcome):
        row = self.rows.setdefault(input_class, collections.Counter())
        row["inputs"] += 1
        row[outcome.cls] += 1
        if outcome.cls in BAD:
            first = outcome.stderr.strip().splitlines()[:1]
            self.bad.append((input_class, name, outcome.cls, outcome.why,
                             first[0][:160] if first else ""))

    def markdown(self):
        head = ["input class", "inputs", "clean error (2)", "success (0)", "run failed (3)",
                "crashes", "hangs", "memory over limit", "commands executed", "broken promises"]
        keys = ["inputs", "error", "success", "failed", "crash", "hang", "memory", "command",
                "broken"]
        out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
        total = collections.Counter()
        for cls, row in self.rows.items():
            out.append("| " + cls + " | " + " | ".join(str(row[k]) for k in keys) + " |")
            total.update(row)
        out.append("| **total** | " + " | ".join("**%d**" % total[k] for k in keys) + " |")
        return "\n".join(out)

    def failures(self):
        return len(self.bad)


def fresh_dir(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path
