"""The README's generated blocks, from committed tables (nothing in them is typed by hand).

* ``targets``: ``benchmarks/targets.csv`` (``benchmarks/targets.py``), each target's measured time;
* ``what-holds``: ``docs/measured/claims.csv`` (a full run's ``results/claims.csv``), what holds and what does not;
* ``figure4-gci``: ``docs/measured/swelling_gci.csv`` (a full run's ``results/swelling/gci.csv``), figure 4's
  discretisation error.

Each is written between the README's markers ``<!-- name -->`` and ``<!-- /name -->`` by the table functions of
:mod:`sphgag.views.pages`, which also write the documentation site's results pages.

    python benchmarks/readme_tables.py                     # print the blocks
    python benchmarks/readme_tables.py --readme README.md  # rewrite them in the README
    python benchmarks/readme_tables.py --check README.md   # exit 1 where the README differs from the tables
"""

from __future__ import annotations

import argparse
from pathlib import Path

import pandas as pd
from rule_resources import replace_block

from sphgag.views import pages

ROOT = Path(__file__).resolve().parents[1]


def _minutes(seconds: float) -> str:
    return "-" if pd.isna(seconds) else f"{int(seconds // 60)} min {int(seconds % 60):02d} s"


def targets_table(targets: pd.DataFrame) -> str:
    """Per target and configuration: jobs, the measured wall time from a fresh clone and once `all` has run (where
    timed), the sum and the longest of its jobs' wall times, where and at which commit."""
    rows = [
        "| target | jobs | time on 2 cores: fresh clone | after `all` | job time (sum; longest job) | measured on "
        "| commit |",
        "|" + " --- |" * 7,
    ]
    for r in targets.itertuples():
        jobs = f"{r.jobs}" + (f" ({r.jobs_measured} measured)" if r.jobs_measured < r.jobs else "")
        rows.append(
            f"| `{r.target}` ({r.configuration}) | {jobs} | {_minutes(r.wall_s)} | {_minutes(r.wall_after_all_s)} | "
            f"{_minutes(r.job_wall_sum_s)}; {_minutes(r.longest_job_s)} | {r.measured_on} | `{str(r.commit)[:7]}` |"
        )
    return "\n".join(rows)


SOURCES = {  # README marker -> (the committed table, the function that writes it)
    "targets": ("benchmarks/targets.csv", targets_table),
    "what-holds": ("docs/measured/claims.csv", pages.holds_table),
    "figure4-gci": ("docs/measured/swelling_gci.csv", pages.gci_summary),
}


def blocks(root: Path = ROOT) -> dict[str, str]:
    """Every block, by the name of its README markers."""
    return {name: table(pd.read_csv(root / path)) for name, (path, table) in SOURCES.items()}


def rewritten(text: str, root: Path = ROOT) -> str:
    """``text`` (a README) with every block rewritten from the tables."""
    for name, table in blocks(root).items():
        text = replace_block(text, table, name)
    return text


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--readme", type=Path, help="rewrite the blocks of this README")
    ap.add_argument("--check", type=Path, help="exit 1 if this README's blocks differ from the tables")
    args = ap.parse_args(argv)
    if args.check:
        same = rewritten(args.check.read_text()) == args.check.read_text()
        print("the README's blocks match the tables" if same else f"{args.check}: blocks differ from the tables")
        return 0 if same else 1
    if args.readme:
        args.readme.write_text(rewritten(args.readme.read_text()))
        return 0
    print("\n\n".join(f"<!-- {name} -->\n{table}" for name, table in blocks().items()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
