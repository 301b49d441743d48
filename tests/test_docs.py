"""The README and the documentation: their size, their generated blocks, the resource declarations they promise, and
no project history in the tree."""

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def script(name, *args, cwd=ROOT) -> subprocess.CompletedProcess:
    """``python benchmarks/<name> *args``."""
    return subprocess.run(
        [sys.executable, str(ROOT / "benchmarks" / name), *args], cwd=cwd, capture_output=True, text=True
    )


def test_the_readme_is_at_most_250_lines():
    assert len((ROOT / "README.md").read_text().splitlines()) <= 250


def test_the_readme_blocks_are_what_the_script_writes_from_the_committed_tables(tmp_path):
    run = script("readme_tables.py", "--check", str(ROOT / "README.md"))
    assert run.returncode == 0, run.stdout + run.stderr
    # and the check could fail: a hand-edited number in a block
    edited = tmp_path / "README.md"
    edited.write_text((ROOT / "README.md").read_text().replace("| prescribed |", "| prescribed (edited) |", 1))
    assert script("readme_tables.py", "--check", str(edited)).returncode == 1


@pytest.mark.parametrize("configfile", [None, "config/ci.yaml"], ids=["full", "ci"])
def test_every_rule_declares_at_least_1_5_times_its_longest_measured_job(configfile):
    args = ["--check"] + (["--configfile", configfile] if configfile else [])
    run = script("rule_resources.py", *args)
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-3000:]
    assert "EXCEEDS" not in run.stdout


def test_the_resource_check_names_a_rule_whose_table_row_outgrew_its_declaration(tmp_path):
    table = tmp_path / "resources.csv"
    shutil.copyfile(ROOT / "benchmarks/resources.csv", table)
    rows = table.read_text().splitlines()
    # the full configuration's fig4 took 250 s (declared 5 min: 1.2 times, below 1.5)
    rows = [re.sub(r"^fig4,full,(\d+),[^,]*,", r"fig4,full,\1,250.0,", r) for r in rows]
    table.write_text("\n".join(rows) + "\n")
    run = script("rule_resources.py", "--check", "--table", str(table))
    assert run.returncode == 1, run.stdout[-3000:]
    assert "EXCEEDS: fig4: measured 250 s > declared runtime 5 min / 1.5" in run.stdout
    assert run.stdout.count("EXCEEDS:") == 1


def test_the_api_page_documents_every_module():
    listed = set(re.findall(r"^::: (\S+)$", (ROOT / "docs/api.md").read_text(), re.M))
    modules = {
        ".".join(p.relative_to(ROOT / "src").with_suffix("").parts).removesuffix(".__init__")
        for p in (ROOT / "src/sphgag").rglob("*.py")
    }
    assert listed == modules, (sorted(modules - listed), sorted(listed - modules))


def test_no_file_test_or_heading_is_named_after_an_issue():
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True).stdout.splitlines()
    if not files:
        pytest.skip("not a git checkout")
    issue = re.compile(r"issue[ _-]?\d+", re.I)
    assert not [f for f in files if issue.search(f)]
    texts = [f for f in files if f.endswith((".py", ".md", ".smk", ".yaml", ".rst")) and Path(ROOT, f).exists()]
    named = [f"{f}: {line}" for f in texts for line in Path(ROOT, f).read_text().splitlines() if issue.search(line)]
    assert not named, named[:10]


def mkdocs_build(project: Path) -> subprocess.CompletedProcess:
    """``mkdocs build --strict`` of ``project`` (its mkdocs.yml and docs/) into a folder of its own."""
    cmd = [sys.executable, "-m", "mkdocs", "build", "--strict", "--site-dir", str(project / "site_test")]
    return subprocess.run(cmd, cwd=project, capture_output=True, text=True)


@pytest.mark.pipeline
def test_the_site_build_fails_on_a_broken_link_and_on_a_missing_results_page(workdir, tmp_path):
    """The site of the CI run builds in strict mode, and the same build fails once a page links to a page that does
    not exist, or once a results page (a table the pipeline did not write) is missing."""
    project = tmp_path / "project"
    project.mkdir()
    for name in ("mkdocs.yml", "docs", "src"):
        copy = shutil.copytree if (workdir / name).is_dir() else shutil.copyfile
        copy(workdir / name, project / name)
    assert mkdocs_build(project).returncode == 0
    claims = project / "docs/results/claims.md"
    text = claims.read_text()
    claims.write_text(text + "\n[the swelling study](swelling_study.md)\n")
    broken = mkdocs_build(project)
    assert broken.returncode != 0 and "swelling_study.md" in broken.stdout + broken.stderr
    claims.unlink()
    missing = mkdocs_build(project)
    assert missing.returncode != 0 and "results/claims.md" in missing.stdout + missing.stderr
