"""Every rule's declared threads and resources against what its jobs measured, and the committed table of those
measurements (``benchmarks/resources.csv``).

The declared values are Snakemake's own: the jobs of a dry run of a target (``snakemake -n --forceall``), each with
its benchmark file, threads and evaluated resources (``runtime`` in minutes, ``mem_mb``; expressions, callables and
the profile's ``default-resources`` included). The measured values are the benchmark files of a finished run of the
same configuration (``s`` = wall seconds, ``max_rss`` = peak resident memory in MB), matched job by job, or the
committed table: per rule and configuration, the longest wall time and the largest peak memory of its jobs, where
and at which commit they were measured.

    python benchmarks/rule_resources.py --check                      # the table against the full configuration
    python benchmarks/rule_resources.py --configfile config/ci.yaml --check          # ... and the reduced one
    python benchmarks/rule_resources.py --benchmarks DIR --check     # a finished run's own jobs
    python benchmarks/rule_resources.py --benchmarks DIR --record --commit SHA --measured-on "2 cores, ..."
    python benchmarks/rule_resources.py --guide docs/guide.md        # rewrite the guide's table

``--check`` exits with status 1 and names every rule whose declaration is below its measurement: against the table,
below ``--margin`` (default 1.5) times the rule's longest job; against a run's benchmarks (``--benchmarks``), below
the job itself (margin 1). ``--record`` writes the rules measured in ``--benchmarks`` into the table (replacing
their rows for this configuration: the newest measurement of a rule wins). The declared values follow one policy:
about twice the longest measurement on the full configuration from a fresh clone (cold Numba cache, both cores
busy), runtime in whole minutes (at least 5), memory in steps of 500 MB (at least 1000); ``suggested`` shows it.
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
TABLE = ROOT / "benchmarks" / "resources.csv"
TABLE_COLUMNS = ["rule", "configuration", "jobs", "longest_wall_s", "peak_rss_mb", "measured_on", "commit"]
MARGIN = 1.5  # a declaration is at least this many times its rule's longest measured job
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
    for f in (f for f in jobs if "output" in f):  # a target rule (all, everything, ...) has no output: no job
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
    return out


def cluster_defaults(project: Path = ROOT) -> dict:
    """``runtime`` and ``mem_mb`` of the SLURM profile's ``default-resources`` (a rule without its own gets these)."""
    import yaml

    profile = yaml.safe_load((project / "profiles" / "slurm" / "config.yaml").read_text())
    found = profile.get("default-resources") or {}
    if isinstance(found, list):
        found = dict(item.split("=", 1) for item in found)
    return {k: str(found[k]) for k in ("runtime", "mem_mb") if k in found}


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


def configuration_name(configfile: str | None) -> str:
    """The table's name of a configuration: ``full`` (config/config.yaml), else the file's stem (``ci``)."""
    return "full" if configfile is None else Path(configfile).stem


def read_table(path: Path, configuration: str) -> dict[str, tuple[float, float]]:
    """The committed measurements of one configuration: rule -> (longest wall s, peak RSS MB)."""
    with path.open() as f:
        rows = [r for r in csv.DictReader(f) if r["configuration"] == configuration]
    return {r["rule"]: (float(r["longest_wall_s"]), float(r["peak_rss_mb"])) for r in rows}


def from_table(jobs: list[Job], table: dict[str, tuple[float, float]]) -> None:
    """Each job's measurement: its rule's longest job in the table (every job of a rule must fit that one)."""
    for job in jobs:
        if job.rule in table:
            job.seconds, job.max_rss_mb = table[job.rule]


def record(jobs: list[Job], path: Path, configuration: str, measured_on: str, commit: str) -> int:
    """Write the rules of ``jobs`` that have measurements into the table at ``path`` (their rows of
    ``configuration`` replaced); the number of rules written."""
    new = {}
    for rule in dict.fromkeys(j.rule for j in jobs):
        done = [j for j in jobs if j.rule == rule and j.seconds is not None]
        if done:
            new[rule] = dict(
                rule=rule,
                configuration=configuration,
                jobs=len(done),
                longest_wall_s=f"{max(j.seconds for j in done):.1f}",
                peak_rss_mb=f"{max(j.max_rss_mb for j in done):.0f}",
                measured_on=measured_on,
                commit=commit,
            )
    replace_rows(path, TABLE_COLUMNS, list(new.values()), key=("configuration", "rule"))
    return len(new)


def replace_rows(path: Path, columns: list[str], new: list[dict], key: tuple[str, ...], order=None) -> None:
    """Write ``new`` into the CSV table at ``path``, in place of its rows with the same ``key`` columns, sorted by
    ``order`` (a row's sort key; default: the key columns)."""
    rows = list(csv.DictReader(path.open())) if path.exists() else []
    keys = {tuple(str(r[k]) for k in key) for r in new}
    rows = [r for r in rows if tuple(r[k] for k in key) not in keys] + new
    rows.sort(key=order or (lambda r: tuple(str(r[k]) for k in key)))
    with path.open("w", newline="") as f:
        writer = csv.DictWriter(f, columns, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)


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
        raise SystemExit(f"the file has no {begin} ... {end} block")
    head, rest = text.split(begin, 1)
    _, tail = rest.split(end, 1)
    return f"{head}{begin}\n{block}\n{end}{tail}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--target", default="everything", help="the target whose jobs are listed (default: everything)")
    ap.add_argument("--configfile", default=None, help="the configuration (default: config/config.yaml)")
    ap.add_argument("--project", type=Path, default=ROOT, help="the checkout to plan in (default: this one)")
    ap.add_argument("--benchmarks", type=Path, nargs="+", help="a finished run's benchmark folders (else: the table)")
    ap.add_argument("--table", type=Path, default=TABLE, help="the committed measurements (benchmarks/resources.csv)")
    ap.add_argument("--check", action="store_true", help="exit 1 if a declaration is below its measurement")
    ap.add_argument(
        "--margin", type=float, help=f"with --check: demand margin x the measurement ({MARGIN:g} on the table)"
    )
    ap.add_argument("--record", action="store_true", help="write the rules measured in --benchmarks into the table")
    ap.add_argument("--commit", default="", help="with --record: the commit the run was made at")
    ap.add_argument("--measured-on", default="", help="with --record: the machine and how the run was made")
    ap.add_argument("--guide", type=Path, help="rewrite the table between the rule-resources markers of this file")
    ap.add_argument("--note", default="", help="with --guide: the line above the table (where it was measured)")
    args = ap.parse_args(argv)

    configuration = configuration_name(args.configfile)
    jobs = planned_jobs(args.target, args.configfile, args.project)
    if args.benchmarks:
        measure(jobs, args.benchmarks)
        source, margin = ", ".join(map(str, args.benchmarks)), args.margin or 1.0
    else:
        from_table(jobs, read_table(args.table, configuration))
        source, margin = f"{args.table} ({configuration})", args.margin or MARGIN
    measured = sum(j.seconds is not None for j in jobs)
    print(f"{len(jobs)} jobs of {args.target}; {measured} measured in {source}")
    if args.record:
        if not args.benchmarks:
            raise SystemExit("--record needs --benchmarks: the run whose measurements go into the table")
        print(
            f"recorded {record(jobs, args.table, configuration, args.measured_on, args.commit)} rules in {args.table}"
        )
    text = markdown(jobs, args.note)
    print(text)
    if args.guide:
        args.guide.write_text(replace_block(args.guide.read_text(), text))
    unmeasured = sorted({j.rule for j in jobs if j.seconds is None})
    if unmeasured:
        print("NOT MEASURED:", ", ".join(unmeasured))
    over = exceeded(jobs, margin)
    for line in over:
        print("EXCEEDS:", line)
    return 1 if args.check and over else 0


if __name__ == "__main__":
    sys.exit(main())
