"""Usage: run_tutorial.py VOXC SOURCE_DIR.

Runs docs/tutorial.md as written. A fenced block's info string says what it is:
- "vox PATH": an excerpt that must appear, line for line, in PATH (relative to the repository);
- "text NAME": a file the reader writes, saved as NAME in the working directory;
- "sh": commands, one a line, run in a working directory whose `examples` is the repository's,
  with `voxc` standing for the built binary (an `alias` line only says so, and is skipped).
Each step's outputs must exist afterwards. Prints "N passed, N failed" last; exits 1 on a failure.
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

voxc, root = sys.argv[1], sys.argv[2]
doc = open(os.path.join(root, "docs", "tutorial.md"), encoding="utf-8").read()
blocks = re.findall(r"^```([^\n]*)\n(.*?)^```$", doc, flags=re.S | re.M)
passed = failed = 0


def report(ok, name, why=""):
    global passed, failed
    print(("ok   " if ok else "FAIL ") + name + ("" if ok else ": " + why))
    if ok:
        passed += 1
    else:
        failed += 1


def outputs_of(words):
    """The files a command says it writes: -o, --screenshot and a `screenshot` action's path."""
    return [words[i + 1] for i, w in enumerate(words[:-1]) if w in ("-o", "--screenshot")]


shown = set()
with tempfile.TemporaryDirectory() as work:
    os.symlink(os.path.join(root, "examples"), os.path.join(work, "examples"))
    env = dict(os.environ, VOXC_CACHE_DIR=os.path.join(work, "cache"))
    for info, body in blocks:
        kind, _, target = info.partition(" ")
        if kind == "vox":
            shown.add(os.path.normpath(target))
            text = open(os.path.join(root, target), encoding="utf-8").read()
            report(body in text, f"excerpt in {target}", "the excerpt differs from the file")
        elif kind == "text":
            with open(os.path.join(work, target), "w", encoding="utf-8") as f:
                f.write(body)
            if "screenshot" in body:
                expected = [line.split()[1] for line in body.splitlines() if line.startswith("screenshot ")]
                env["TUTORIAL_SCRIPT_OUTPUTS"] = " ".join(expected)
        elif kind == "sh":
            for line in body.splitlines():
                if not line.strip() or line.startswith("alias "):
                    continue
                words = shlex.split(line)
                command = [voxc if w == "voxc" else w for w in words]
                if "voxc" not in words:
                    report(False, line, "a tutorial command that does not run voxc")
                    continue
                result = subprocess.run(command, cwd=work, env=env, capture_output=True, text=True, timeout=600)
                expected = outputs_of(words)
                if "--script" in words:
                    expected += env.get("TUTORIAL_SCRIPT_OUTPUTS", "").split()
                missing = [p for p in expected if not os.path.exists(os.path.join(work, p))]
                ok = result.returncode == 0 and not missing
                why = f"exit {result.returncode}, missing {missing}\n{result.stdout[-1500:]}{result.stderr[-1500:]}"
                report(ok, line, why)
    for name in sorted(os.listdir(os.path.join(root, "examples", "tutorial"))):
        path = os.path.join("examples", "tutorial", name)
        report(path in shown, f"{path} is shown in the tutorial", "no excerpt of it")

print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
