"""Measured against declared resources, per rule.

Reads the benchmark files of one or more runs (``results/benchmarks/*.tsv``, written by
every rule with a ``benchmark:`` directive: ``s`` = wall seconds, ``max_rss`` = peak
resident memory in MB; a rule without the directive is matched to ``<rule>.tsv``, as
written by a run with the directive added) and the ``threads:`` and ``resources:`` (``runtime`` in minutes, ``mem_mb``)
declared in ``workflow/rules/*.smk``, and prints one row per rule: the largest measured
time and memory over the rule's jobs, the declared values, and their ratio.

The declared values follow one policy: twice the largest measurement of a full run from a
fresh clone (cold Numba cache), rounded up (runtime to whole minutes, at least 5;
memory to 500 MB, at least 1000 MB). ``suggested`` shows what the policy gives for the
benchmarks read. Rules without a ``resources:`` block get the profile's
``default-resources``.

    python benchmarks/rule_resources.py [--benchmarks results/benchmarks [other/results/benchmarks ...]] [--check]

With ``--check`` the exit status is 1 if a declared value is below ``--margin`` (1.5)
times its measurement.
"""

from __future__ import annotations

import argparse
import csv
import math
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

RULE = re.compile(r"^rule (\w+):")
DIRECTIVE = re.compile(r"^    (\w+):\s*(.*)$")
ASSIGNMENT = re.compile(r"^\s+(\w+)\s*=\s*([^,#]+?)\s*,?\s*(#.*)?$")
WILDCARD = re.compile(r"\{(\w+)(?:,[^}]*)?\}")


def declared_rules(rules_dir: Path) -> dict[str, dict]:
    """Per rule (in file order): its benchmark pattern, threads and resources, read from the .smk files."""
    rules: dict[str, dict] = {}
    for path in sorted(rules_dir.glob("*.smk")):
        rule, directive = None, None
        for line in path.read_text().splitlines():
            if m := RULE.match(line):
                rule, directive = rules.setdefault(m.group(1), dict(file=path.name, resources={})), None
                continue
            if rule is None:
                continue
            if line and not line[0].isspace():  # top-level code ends the rule
                rule = None
                continue
            if m := DIRECTIVE.match(line):
                directive, value = m.groups()
                if directive == "threads" and value:
                    rule["threads"] = int(value)
                elif directive == "benchmark" and value:
                    rule["benchmark"] = value.strip("\"'")
                continue
            if directive == "benchmark" and line.strip() and "benchmark" not in rule:
                rule["benchmark"] = line.strip().rstrip(",").strip("\"'")
            elif directive == "resources" and (m := ASSIGNMENT.match(line)):
                rule["resources"][m.group(1)] = int(m.group(2))
    return rules


def pattern_regex(pattern: str) -> re.Pattern:
    """``results/benchmarks/swell_{model}_{case}.tsv`` -> a regex matching the file names of its jobs."""
    name = Path(pattern).name
    parts, last = [], 0
    for m in WILDCARD.finditer(name):
        parts += [re.escape(name[last : m.start()]), r"[^/]+?"]
        last = m.end()
    parts.append(re.escape(name[last:]))
    return re.compile("".join(parts) + r"\Z")


def read_benchmark(path: Path) -> tuple[float, float]:
    """Largest wall time (s) and peak memory (MB) in one benchmark file (one row per repeat)."""
    with path.open() as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    return max(float(r["s"]) for r in rows), max(float(r["max_rss"]) for r in rows if r["max_rss"] != "NA")


def measured(rules: dict[str, dict], bench_dirs: list[Path]) -> dict[str, dict]:
    """Per rule: number of benchmark files, largest s and max_rss over every directory."""
    benchmark = {name: r.get("benchmark", f"{name}.tsv") for name, r in rules.items()}
    patterns = {name: pattern_regex(b) for name, b in benchmark.items()}
    # a longer literal pattern first, so that a file is given to the most specific rule
    order = sorted(patterns, key=lambda n: -len(WILDCARD.sub("", benchmark[n])))
    out: dict[str, dict] = {}
    for path in sorted(p for d in bench_dirs for p in d.glob("*.tsv")):
        rule = next((n for n in order if patterns[n].match(path.name)), None)
        if rule is None:
            continue
        s, rss = read_benchmark(path)
        m = out.setdefault(rule, dict(jobs=0, s=0.0, max_rss=0.0))
        m["jobs"] += 1
        m["s"], m["max_rss"] = max(m["s"], s), max(m["max_rss"], rss)
    return out


def suggested(s: float, rss: float) -> tuple[int, int]:
    """The policy: twice the measurement, rounded up (runtime: minutes, >= 5; memory: 500 MB, >= 1000)."""
    return max(5, math.ceil(2 * s / 60)), max(1000, 500 * math.ceil(2 * rss / 500))


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--benchmarks", type=Path, nargs="+", default=[ROOT / "results" / "benchmarks"])
    ap.add_argument("--rules", type=Path, default=ROOT / "workflow" / "rules")
    ap.add_argument("--check", action="store_true", help="exit 1 if a declared value is below margin x measured")
    ap.add_argument("--margin", type=float, default=1.5)
    args = ap.parse_args(argv)

    rules = declared_rules(args.rules)
    meas = measured(rules, args.benchmarks)
    header = [
        "rule",
        "jobs",
        "max s",
        "max_rss MB",
        "threads",
        "runtime min",
        "mem_mb",
        "runtime/s",
        "mem/rss",
        "suggested",
    ]
    rows, low = [], []
    for name, r in rules.items():
        res, m = r["resources"], meas.get(name)
        if m is None and not res:
            continue  # no measurement, no declaration: the profile's default-resources
        runtime, mem = res.get("runtime"), res.get("mem_mb")
        row = [
            name,
            "-",
            "-",
            "-",
            str(r.get("threads", "-")),
            str(runtime or "default"),
            str(mem or "default"),
            "-",
            "-",
            "-",
        ]
        if m is not None:
            row[1:4] = [str(m["jobs"]), f"{m['s']:.1f}", f"{m['max_rss']:.0f}"]
            if runtime:
                row[7] = f"{runtime * 60 / max(m['s'], 1e-9):.1f}"
                if runtime * 60 < args.margin * m["s"]:
                    low.append(f"{name}: runtime {runtime} min < {args.margin} x {m['s']:.0f} s")
            if mem:
                row[8] = f"{mem / max(m['max_rss'], 1e-9):.1f}"
                if mem < args.margin * m["max_rss"]:
                    low.append(f"{name}: mem_mb {mem} < {args.margin} x {m['max_rss']:.0f} MB")
            row[9] = "runtime={}, mem_mb={}".format(*suggested(m["s"], m["max_rss"]))
        rows.append(row)
    widths = [max(len(x) for x in col) for col in zip(header, *rows)]
    print(f"benchmarks: {', '.join(map(str, args.benchmarks))} ({sum(m['jobs'] for m in meas.values())} files)")
    for row in [header, ["-" * w for w in widths], *rows]:
        print("  ".join(x.ljust(w) for x, w in zip(row, widths)).rstrip())
    for line in low:
        print("LOW:", line)
    return 1 if args.check and low else 0


if __name__ == "__main__":
    sys.exit(main())
