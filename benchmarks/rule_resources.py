"""Every rule's declared threads and resources against what its jobs measured, and the README's table of them.

The declared values are Snakemake's own: the jobs of a dry run of a target (``snakemake -n --forceall``), each with
its benchmark file, threads and evaluated resources (``runtime`` in minutes, ``mem_mb``; expressions, callables and
the profile's ``default-resources`` included). The measured values are the benchmark files of a finished run of the
same configuration (``s`` = wall seconds, ``max_rss`` = peak resident memory in MB), matched job by job.

    python benchmarks/rule_resources.py                                   # full configuration, target everything
    python benchmarks/rule_resources.py --configfile config/ci.yaml --benchmarks DIR --check
    python benchmarks/rule_resources.py --readme README.md                # rewrite the README's table

``--check`` exits with status 1 and names every rule whose measured runtime or memory exceeds its declaration in
some job (``--margin`` > 1 demands that much headroom). ``--readme`` replaces the table between the README's markers
``<!-- rule-resources -->`` and ``<!-- /rule-resources -->``. The declared values follow one policy: at least twice
the largest measurement of a full run from a fresh clone (cold Numba cache, both cores busy), runtime in whole
minutes (at least 5), memory in steps of 500 MB (at least 1000); ``suggested`` shows what it gives.
"""

from __future__ import annotations

import argparse
import csv
import math
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
JOB = re.compile(r"^(?:local)?rule (\w+):$")
FIELD = re.compile(r"^    (\w+): (.*)$")


@dataclass
class Job:
    rule: str
    benchmark: str | None
    threads: int
    runtime_min: float | None
    mem_mb: float | None
    seconds: float | None = None  # measured
    max_rss_mb: float | None = None


def planned_jobs(target: str, configfile: str | None, project: Path = ROOT) -> list[Job]:
    """The jobs of ``target`` as Snakemake plans them from scratch, with their declared threads and resources."""
    cmd = [sys.executable, "-m", "snakemake", "-n", "--forceall", "--cores", "2", target]
    cmd += ["--configfile", configfile] if configfile else []
    run = subprocess.run(cmd, cwd=project, capture_output=True, text=True)
    if run.returncode != 0:
        raise SystemExit(f"snakemake dry run failed:\n{run.stdout[-2000:]}{run.stderr[-2000:]}")
    jobs, fields = [], None
    for line in (run.stdout + "\n" + run.stderr).splitlines():
        if m := JOB.match(line):
            fields = {"rule": m.group(1)}
            jobs.append(fields)
        elif fields is not None and (m := FIELD.match(line)):
            fields[m.group(1)] = m.group(2)
        elif fields is not None and not line.startswith("    "):
            fields = None
    defaults = cluster_defaults(project)
    out = []
    for f in jobs:
        resources = dict(kv.split("=", 1) for kv in f.get("resources", "").split(", ") if "=" in kv)
        resources = {**defaults, **resources}  # what a cluster job of a rule without its own gets
        out.append(
            Job(
                f["rule"],
                f.get("benchmark"),
                int(f.get("threads", 1)),
                float(resources["runtime"]) if "runtime" in resources else None,
                float(resources["mem_mb"]) if "mem_mb" in resources else None,
            )
        )
    return [j for j in out if j.rule not in TARGETS]


def cluster_defaults(project: Path = ROOT) -> dict:
    """``runtime`` and ``mem_mb`` of the SLURM profile's ``default-resources`` (a rule without its own gets these)."""
    import yaml

    profile = yaml.safe_load((project / "profiles" / "slurm" / "config.yaml").read_text())
    found = profile.get("default-resources") or {}
    if isinstance(found, list):
        found = dict(item.split("=", 1) for item in found)
    return {k: str(found[k]) for k in ("runtime", "mem_mb") if k in found}


TARGETS = ("all", "everything", "resolution", "verification", "fracture_energy", "sensitivity", "views")


def read_benchmark(path: Path) -> tuple[float, float]:
    """Largest wall time (s) and peak memory (MB) in one benchmark file (one row per repeat)."""
    with path.open() as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    rss = [float(r["max_rss"]) for r in rows if r["max_rss"] not in ("NA", "-", "")]
    return max(float(r["s"]) for r in rows), max(rss) if rss else math.nan


def measure(jobs: list[Job], bench_dirs: list[Path]) -> None:
    """Each job's measurement, from its benchmark file in the first of ``bench_dirs`` that has it."""
    for job in jobs:
        if job.benchmark is None:
            continue
        name = Path(job.benchmark).name
        found = next((d / name for d in bench_dirs if (d / name).exists()), None)
        if found is not None:
            job.seconds, job.max_rss_mb = read_benchmark(found)


def exceeded(jobs: list[Job], margin: float = 1.0) -> list[str]:
    """One line per rule whose measurement, times ``margin``, exceeds its declaration in some job."""
    lines = []
    for rule in dict.fromkeys(j.rule for j in jobs):
        mine = [j for j in jobs if j.rule == rule and j.seconds is not None]
        slow = [j for j in mine if j.runtime_min is not None and margin * j.seconds > 60.0 * j.runtime_min]
        big = [j for j in mine if j.mem_mb is not None and margin * j.max_rss_mb > j.mem_mb]
        if slow:
            worst = max(slow, key=lambda j: j.seconds / j.runtime_min)
            lines.append(
                f"{rule}: measured {worst.seconds:.0f} s > declared runtime {worst.runtime_min:g} min"
                f"{f' / {margin:g}' if margin != 1 else ''} ({len(slow)} of {len(mine)} jobs; {worst.benchmark})"
            )
        if big:
            worst = max(big, key=lambda j: j.max_rss_mb / j.mem_mb)
            lines.append(
                f"{rule}: measured {worst.max_rss_mb:.0f} MB > declared mem_mb {worst.mem_mb:g}"
                f"{f' / {margin:g}' if margin != 1 else ''} ({len(big)} of {len(mine)} jobs; {worst.benchmark})"
            )
    return lines


def suggested(s: float, rss: float) -> tuple[int, int]:
    """The policy: twice the measurement, rounded up (runtime: minutes, >= 5; memory: 500 MB, >= 1000)."""
    return max(5, math.ceil(2 * s / 60)), max(1000, 500 * math.ceil(2 * rss / 500))


def _span(values, fmt="{:g}") -> str:
    values = sorted({v for v in values if v is not None})
    if not values:
        return "-"
    return fmt.format(values[0]) if len(values) == 1 else f"{fmt.format(values[0])}-{fmt.format(values[-1])}"


def table(jobs: list[Job]) -> list[list[str]]:
    """One row per rule: jobs, threads, declared runtime and memory, largest measured time and memory, suggested."""
    rows = []
    for rule in dict.fromkeys(j.rule for j in jobs):
        mine = [j for j in jobs if j.rule == rule]
        done = [j for j in mine if j.seconds is not None]
        measured = "not measured"
        advice = "-"
        if done:
            s, rss = max(j.seconds for j in done), max(j.max_rss_mb for j in done)
            measured = f"{s:.0f} s, {rss:.0f} MB" + (
                f" ({len(done)} of {len(mine)} jobs)" if len(done) < len(mine) else ""
            )
            advice = "runtime={}, mem_mb={}".format(*suggested(s, rss))
        rows.append(
            [
                f"`{rule}`",
                str(len(mine)),
                _span(j.threads for j in mine),
                _span(j.runtime_min for j in mine),
                _span(j.mem_mb for j in mine),
                measured,
                advice,
            ]
        )
    return rows


HEADER = ["rule", "jobs", "threads", "runtime (min)", "mem_mb", "largest measured: time, memory", "suggested"]


def markdown(jobs: list[Job], note: str) -> str:
    rows = [HEADER, ["---"] * len(HEADER), *table(jobs)]
    lines = ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join([note, "", *lines])


def replace_block(text: str, block: str, name: str = "rule-resources") -> str:
    """``text`` with the part between the markers ``<!-- name -->`` and ``<!-- /name -->`` replaced by ``block``."""
    begin, end = f"<!-- {name} -->", f"<!-- /{name} -->"
    if begin not in text or end not in text:
        raise SystemExit(f"the README has no {begin} ... {end} block")
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    return f"{head}{begin}\n{block}\n{end}{tail}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--target", default="everything", help="the target whose jobs are listed (default: everything)")
    ap.add_argument("--configfile", default=None, help="the configuration (default: config/config.yaml)")
    ap.add_argument("--project", type=Path, default=ROOT, help="the checkout to plan in (default: this one)")
    ap.add_argument("--benchmarks", type=Path, nargs="+", default=[ROOT / "results" / "benchmarks"])
    ap.add_argument("--check", action="store_true", help="exit 1 if a measurement exceeds its declaration")
    ap.add_argument("--margin", type=float, default=1.0, help="with --check: demand margin x the measurement")
    ap.add_argument("--readme", type=Path, help="rewrite the table between the markers of this README")
    ap.add_argument("--note", default="", help="with --readme: the line above the table (where it was measured)")
    args = ap.parse_args(argv)

    jobs = planned_jobs(args.target, args.configfile, args.project)
    measure(jobs, args.benchmarks)
    measured = sum(j.seconds is not None for j in jobs)
    print(f"{len(jobs)} jobs of {args.target}; {measured} measured in {', '.join(map(str, args.benchmarks))}")
    text = markdown(jobs, args.note)
    print(text)
    if args.readme:
        args.readme.write_text(replace_block(args.readme.read_text(), text))
    over = exceeded(jobs, args.margin)
    for line in over:
        print("EXCEEDS:", line)
    return 1 if args.check and over else 0


if __name__ == "__main__":
    sys.exit(main())
