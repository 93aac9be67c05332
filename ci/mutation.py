#!/usr/bin/env python3
"""The mutation campaign (docs/mutation.md): does the suite catch a physics bug once the
goldens have been regenerated to hide it?

For each mutant of ci/mutants.txt (a small exact edit of kernel code) in a scratch clone of
the commit under test: apply it, build, regenerate the goldens with the documented update
command (a mutant that changes no golden is not a bug the goldens see: reported apart),
run every label but golden, cuda, slurm and fuzz, and call the mutant killed when a test
fails. Equivalent mutants (unbiased in expectation) are listed apart: the file names the
test of their own kind that kills them, and the campaign checks that it does.

usage: ci/mutation.py [--sample] [--only NAME[,NAME...]] [--list] [--keep DIR]
  --sample  the mutants marked "sample" in ci/mutants.txt (CI runs these)
  --only    the named mutants
  --list    print the mutants and exit
  --keep    use DIR as the scratch clone and keep it (rebuilds are incremental)
Exit 0 when every mutant run was killed (or, when equivalent, killed by its own test).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MUTANTS = os.path.join(ROOT, "ci", "mutants.txt")
# Labels that do not take part: the goldens themselves, and what needs a GPU, a cluster or a fuzzer.
EXCLUDED_LABELS = "golden|cuda|slurm|fuzz"


class Mutant:
    def __init__(self, name):
        self.name, self.feature, self.file = name, "", ""
        self.sample = False
        self.equivalent = ""  # why it is unbiased; its own test must kill it
        self.guard = ""  # why no golden shows it (input no golden holds, code no golden runs); its own test must kill it
        self.killer = ""  # for an equivalent or guard mutant: the ctest -R pattern of its test
        self.first = ""  # tests run before the rest (ctest -R): those that killed it before
        self.before, self.after = [], []


def read_mutants(path):
    """Blocks of '## key: value' lines, then '-' lines (the exact text) and '+' lines (its
    replacement). Blank lines and '#' comments between blocks are ignored."""
    mutants, current = [], None
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            where = f"{path}:{number}"
            if line.startswith("## "):
                key, _, value = line[3:].partition(": ")
                if key == "name":
                    current = Mutant(value.strip())
                    mutants.append(current)
                elif current is None:
                    sys.exit(f"{where}: '## {key}' before any '## name'")
                elif key in ("feature", "file", "equivalent", "guard", "killer", "first"):
                    setattr(current, key, value.strip())
                elif key == "sample":
                    current.sample = value.strip() == "yes"
                else:
                    sys.exit(f"{where}: unknown key '{key}'")
            elif line.startswith("-") and current is not None:
                current.before.append(line[1:])
            elif line.startswith("+") and current is not None:
                current.after.append(line[1:])
            elif line.strip() and not line.startswith("#"):
                sys.exit(f"{where}: expected '## key: value', '-TEXT', '+TEXT', a comment or a blank line")
    names = set()
    for m in mutants:
        if not (m.feature and m.file and m.before):
            sys.exit(f"{path}: mutant {m.name} needs a feature, a file and '-' lines")
        if (m.equivalent or m.guard) and not m.killer:
            sys.exit(f"{path}: {'equivalent' if m.equivalent else 'guard'} mutant {m.name} needs the killer test"
                     " that catches it")
        if m.name in names:
            sys.exit(f"{path}: mutant {m.name} twice")
        names.add(m.name)
    return mutants


def run(command, cwd, log, timeout=3600):
    with open(log, "a", encoding="utf-8") as out:
        out.write(f"$ {' '.join(command)}\n")
        out.flush()
        return subprocess.run(command, cwd=cwd, stdout=out, stderr=subprocess.STDOUT, timeout=timeout).returncode


def apply(mutant, scratch):
    path = os.path.join(scratch, mutant.file)
    with open(path, encoding="utf-8") as f:
        text = f.read()
    before, after = "\n".join(mutant.before) + "\n", "\n".join(mutant.after) + "\n"
    count = text.count(before)
    if count != 1:
        return f"stale: the text occurs {count} times in {mutant.file}"
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(before, after))
    return ""


def failed_tests(build, log):
    """The tests ctest recorded as failed in the last run."""
    failed = os.path.join(build, "Testing", "Temporary", "LastTestsFailed.log")
    if not os.path.exists(failed):
        return []
    with open(failed, encoding="utf-8") as f:
        return [line.strip().split(":", 1)[-1] for line in f if line.strip()]


TEST_DEFINITION = re.compile(r"\bTEST(?:_F|_P)?\(\s*(\w+)\s*,\s*(\w+)\s*\)")


def test_targets(scratch, pattern):
    """The test executables (tests/LABEL/NAME.cpp builds target NAME) defining a test whose
    Suite.Name the ctest pattern matches; empty when none does (then everything is built)."""
    targets = set()
    for folder, _, files in os.walk(os.path.join(scratch, "tests")):
        for name in files:
            if name.startswith("test_") and name.endswith(".cpp"):
                with open(os.path.join(folder, name), encoding="utf-8") as f:
                    for suite, test in TEST_DEFINITION.findall(f.read()):
                        if re.search(pattern, f"{suite}.{test}"):
                            targets.add(name[:-4])
    return sorted(targets)


def targets_of(mutant, scratch):
    """What a mutant's first verdict needs built: tracer (the golden update) and the
    executables of its killer or first tests; None: everything."""
    pattern = mutant.killer if mutant.equivalent else mutant.first
    tests = test_targets(scratch, pattern) if pattern else []
    return ["tracer"] + tests if tests else None


def build_command(build, jobs, targets):
    command = ["cmake", "--build", build, "-j", str(jobs)]
    return command + ["--target"] + targets if targets else command


def campaign(mutants, scratch, jobs):
    build = os.path.join(scratch, "build")
    log = os.path.join(scratch, "mutation.log")
    tracer = os.path.join(build, "tracer")
    configure = ["cmake", "-S", scratch, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DTRACER_WITH_CUDA=OFF",
                 "-DTRACER_CPU_VARIANTS=OFF"]
    # Mutants whose first verdict comes from named tests (the sample's) need only tracer and
    # those tests' executables built; the rest of the suite is built when a mutant gets past them.
    needed = [targets_of(m, scratch) for m in mutants]
    first_build = None if None in needed else sorted({t for targets in needed for t in targets})
    if run(configure, scratch, log) != 0 or run(build_command(build, jobs, first_build), scratch, log) != 0:
        sys.exit(f"the unmutated tree does not build; see {log}")
    rows = []
    for m, targets in zip(mutants, needed):
        start = time.time()
        run(["git", "checkout", "--quiet", "--", "."], scratch, log)
        row = {"mutant": m, "goldens": "-", "verdict": "", "by": ""}
        problem = apply(m, scratch)
        if problem:
            row["verdict"] = problem
        elif run(build_command(build, jobs, targets), scratch, log) != 0:
            row["verdict"] = "does not build"
        else:
            update = subprocess.run([tracer, "golden", "update", "--force", "--root", scratch],
                                    capture_output=True, text=True)
            rewritten = re.search(r"(\d+) of (\d+) matching goldens rewritten", update.stdout)
            row["goldens"] = rewritten.group(1) if rewritten else "?"
            refusal = (update.stderr.strip().splitlines() or ["?"])[-1]
            if update.returncode != 0 and ("NaN/inf" in refusal or "beyond the film's range" in refusal):
                # The update refuses images with NaN, inf or overflowing samples: nobody can hide this one.
                row["verdict"], row["by"] = "killed", "golden update refused it: " + refusal
            elif update.returncode < 0:
                # A crash under the mutant: no golden can be regenerated to hide it either.
                row["verdict"], row["by"] = "killed", "golden update crashed (signal %d)" % -update.returncode
            elif update.returncode != 0 or not rewritten:
                row["verdict"] = "golden update failed: " + refusal
            elif rewritten.group(1) == "0" and not (m.equivalent or m.guard):
                row["verdict"] = "unseen: no golden changed"
            else:
                test = ["ctest", "--test-dir", build, "-LE", EXCLUDED_LABELS, "-j", str(jobs), "--timeout", "600",
                        "--stop-on-failure"]
                # An equivalent or guard mutant runs its killer alone; another runs the tests
                # named by 'first' before the rest, which run only when none of those fails: the
                # same verdict sooner.
                if m.equivalent or m.guard:
                    passes = [test + ["-R", m.killer]]
                elif m.first:  # a pattern that matches no test falls through to the rest
                    passes = [test + ["-R", m.first, "--no-tests=ignore"], test]
                else:
                    passes = [test]
                for command in passes:
                    if command is test and targets and run(build_command(build, jobs, None), scratch, log) != 0:
                        code = None  # the rest of the suite does not build with the mutant
                        break
                    stale = os.path.join(build, "Testing", "Temporary", "LastTestsFailed.log")
                    if os.path.exists(stale):
                        os.remove(stale)  # ctest leaves the last failing run's list when all pass
                    code = run(command, scratch, log)
                    if code != 0:
                        break
                if code is None:
                    row["verdict"] = "does not build"
                else:
                    killers = failed_tests(build, log)
                    row["verdict"] = "killed" if code != 0 else "SURVIVED"
                    row["by"] = ", ".join(killers[:3])
        row["seconds"] = time.time() - start
        rows.append(row)
        print(f"{m.name:40} {row['goldens']:>3} goldens  {row['verdict']:10} {row['by']}  ({row['seconds']:.0f} s)",
              flush=True)
    run(["git", "checkout", "--quiet", "--", "."], scratch, log)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sample", action="store_true")
    parser.add_argument("--only", default="")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--check", action="store_true", help="only check that each mutant's text occurs once")
    parser.add_argument("--keep", default="")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    args = parser.parse_args()
    mutants = read_mutants(MUTANTS)
    if args.only:
        names = args.only.split(",")
        unknown = [n for n in names if n not in {m.name for m in mutants}]
        if unknown:
            sys.exit(f"--only: no mutant named {', '.join(unknown)} in {MUTANTS}")
        mutants = [m for m in mutants if m.name in names]
    elif args.sample:
        mutants = [m for m in mutants if m.sample]
    if args.check:
        stale = []
        for m in mutants:
            with open(os.path.join(ROOT, m.file), encoding="utf-8") as f:
                count = f.read().count("\n".join(m.before) + "\n")
            if count != 1:
                stale.append(f"{m.name}: its text occurs {count} times in {m.file}")
        for line in stale:
            print(line)
        print(f"{len(mutants) - len(stale)} of {len(mutants)} mutants apply")
        return 1 if stale else 0
    if args.list:
        for m in mutants:
            kind = (f"equivalent ({m.equivalent}); killed by {m.killer}" if m.equivalent
                    else f"guard ({m.guard}); killed by {m.killer}" if m.guard else "bug")
            print(f"{m.name:40} {m.feature:32} {m.file}  {kind}{'  [sample]' if m.sample else ''}")
        return 0
    scratch = args.keep or tempfile.mkdtemp(prefix="tracer-mutation-")
    if not os.path.isdir(os.path.join(scratch, ".git")):
        if os.path.exists(scratch) and os.listdir(scratch):
            sys.exit(f"--keep {scratch}: not a scratch clone and not empty")
        subprocess.run(["git", "clone", "--quiet", "--no-hardlinks", ROOT, scratch], check=True)
    subprocess.run(["git", "-C", scratch, "fetch", "--quiet", ROOT, "HEAD"], check=True)
    subprocess.run(["git", "-C", scratch, "checkout", "--quiet", "--force", "FETCH_HEAD"], check=True)
    print(f"mutation campaign: {len(mutants)} mutants of {MUTANTS} in {scratch}, labels but {EXCLUDED_LABELS}")
    rows = campaign(mutants, scratch, args.jobs)
    bugs = [r for r in rows if not (r["mutant"].equivalent or r["mutant"].guard)]
    valid = [r for r in bugs if r["verdict"] in ("killed", "SURVIVED")]
    killed = sum(r["verdict"] == "killed" for r in valid)
    equivalent = [r for r in rows if r["mutant"].equivalent]
    guards = [r for r in rows if r["mutant"].guard]
    print(f"score: {killed} of {len(valid)} mutants the goldens see killed"
          f" ({100.0 * killed / max(len(valid), 1):.0f} %); {len(bugs) - len(valid)} not run or unseen;"
          f" equivalent: {sum(r['verdict'] == 'killed' for r in equivalent)} of {len(equivalent)} killed by their own test;"
          f" guards: {sum(r['verdict'] == 'killed' for r in guards)} of {len(guards)} killed by their own test")
    if not args.keep:
        shutil.rmtree(scratch, ignore_errors=True)
    return 0 if all(r["verdict"] == "killed" for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
