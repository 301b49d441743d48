"""The measured time of each target (``benchmarks/targets.csv``), the README's table of targets.

A row per target and configuration: its jobs (a dry run from scratch), the wall time of the whole target where it
was timed end to end (``snakemake --cores 2 TARGET`` from a fresh clone, cold Numba cache; or, ``--after-all``, in
that clone once `all` had run), the sum and the longest of its jobs' wall times from their benchmark files, where and
at which commit.

    python benchmarks/targets.py --target all --benchmarks DIR --wall 1100 --commit SHA --measured-on "..."
    python benchmarks/targets.py --target resolution --benchmarks DIR ...       # no --wall: job times only
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rule_resources import ROOT, configuration_name, measure, planned_jobs, replace_rows

TABLE = ROOT / "benchmarks" / "targets.csv"
ORDER = (
    "all",
    "variants",
    "fracture_energy",
    "docs",
    "views",
    "paper_procedure",
    "paper_settings",
    "resolution",
    "verification",
    "sensitivity",
    "everything",
)
COLUMNS = [
    "target",
    "configuration",
    "jobs",
    "jobs_measured",
    "wall_s",
    "wall_after_all_s",
    "job_wall_sum_s",
    "longest_job_s",
    "measured_on",
    "commit",
]


def row(
    target: str, configfile: str | None, benchmarks: list[Path], wall: float | None, after_all: bool, **where
) -> dict:
    """One target's row: its jobs from scratch and what their benchmark files in ``benchmarks`` measured."""
    jobs = planned_jobs(target, configfile)
    measure(jobs, benchmarks)
    done = [j.seconds for j in jobs if j.seconds is not None]
    return dict(
        target=target,
        configuration=configuration_name(configfile),
        jobs=len(jobs),
        jobs_measured=len(done),
        wall_s="" if wall is None or after_all else f"{wall:.0f}",
        wall_after_all_s=f"{wall:.0f}" if wall is not None and after_all else "",
        job_wall_sum_s=f"{sum(done):.0f}",
        longest_job_s=f"{max(done, default=0):.0f}",
        **where,
    )


def write(new: dict, path: Path = TABLE) -> None:
    """``new`` into the table at ``path``, replacing the row of its target and configuration."""

    def position(r):
        return r["configuration"], ORDER.index(r["target"]) if r["target"] in ORDER else len(ORDER)

    replace_rows(path, COLUMNS, [new], key=("target", "configuration"), order=position)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--target", required=True)
    ap.add_argument("--configfile", default=None)
    ap.add_argument("--benchmarks", type=Path, nargs="+", required=True)
    ap.add_argument("--wall", type=float, help="the target's measured wall time end to end [s]")
    ap.add_argument("--after-all", action="store_true", help="--wall was measured once `all` had run")
    ap.add_argument("--commit", required=True)
    ap.add_argument("--measured-on", required=True)
    args = ap.parse_args(argv)
    where = dict(measured_on=args.measured_on, commit=args.commit)
    new = row(args.target, args.configfile, args.benchmarks, args.wall, args.after_all, **where)
    write(new)
    print(new)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
