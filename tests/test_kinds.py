"""The kinds of job name their files and runs as the rules and scripts did before them (sphgag.jobs.kinds): a run's
results, log, benchmark and provenance record and its run name are part of what a rerun must find again."""

import re
from types import SimpleNamespace

import pytest

from sphgag import jobs
from sphgag.jobs import kinds

from .conftest import ROOT

SWELL = dict(law="prescribed", pool="particles", model="passive", case="I", pressure="103")
SC = dict(law="prescribed", pool="particles", model="active", dx="6")
EXPLICIT = dict(model="passive", case="I", factor="2")
DAMAGE = dict(poolset="single", sigma="40", factor="1")
RUN = dict(law="conserved", run="single_40kPa_averaged")

# kind, wildcards -> (log, benchmark, provenance, run name), as the rules and scripts spelled them
EXPECTED = [
    (
        kinds.pool_stresses,
        SWELL,
        "logs/pool_stresses/prescribed/particles/passive_I_103mmHg.log",
        "results/benchmarks/pool_stresses_prescribed_particles_passive_I_103mmHg.tsv",
        "results/provenance/pool_stresses_prescribed_particles_passive_I_103mmHg.json",
        "pool_stresses_prescribed_particles_passive_I_103mmHg",
    ),
    (
        kinds.swelling_convergence_dx,
        SC,
        "logs/swelling_convergence/prescribed/particles/active_dx6.log",
        "results/benchmarks/swelling_convergence_prescribed_particles_active_dx6.tsv",
        "results/provenance/swelling_convergence_prescribed_particles_active_dx6.json",
        "swelling_convergence_prescribed_particles_active_dx6",
    ),
    (
        kinds.swelling_convergence_stresses,
        SC,
        "logs/swelling_convergence/prescribed/particles/stresses_active_dx6.log",
        "results/benchmarks/swelling_convergence_stresses_prescribed_particles_active_dx6.tsv",
        "results/provenance/swelling_convergence_stresses_prescribed_particles_active_dx6.json",
        "swelling_convergence_stresses_prescribed_particles_active_dx6",
    ),
    (
        kinds.bilayer_pressure_diameter,
        dict(model="active"),
        "logs/bilayer_pressure_diameter_active.log",
        "results/benchmarks/bilayer_pressure_diameter_active.tsv",
        "results/provenance/bilayer_pressure_diameter_active.json",
        "bilayer_active",
    ),
    (
        kinds.procedure_start,
        dict(model="passive"),
        "logs/paper_procedure/passive/start.log",
        "results/benchmarks/procedure_start_passive.tsv",
        "results/provenance/procedure_start_passive.json",
        "procedure_start_passive",
    ),
    (
        kinds.procedure_explicit,
        EXPLICIT,
        "logs/paper_procedure/passive/I_x2.log",
        "results/benchmarks/procedure_explicit_passive_I_x2.tsv",
        "results/provenance/procedure_explicit_passive_I_x2.json",
        "procedure_passive_I_x2",
    ),
    (
        kinds.procedure_delaminate,
        DAMAGE,
        "logs/paper_procedure/single/40kPa_x1.log",
        "results/benchmarks/procedure_delaminate_single_40kPa_x1.tsv",
        "results/provenance/procedure_delaminate_single_40kPa_x1.json",
        "procedure_single_40kPa_x1",
    ),
    (
        kinds.paraview_swelling,
        SWELL,
        "logs/paraview/swelling/prescribed/particles/passive_I_103mmHg.log",
        "results/benchmarks/paraview_swelling_prescribed_particles_passive_I_103mmHg.tsv",
        "results/provenance/paraview_swelling_prescribed_particles_passive_I_103mmHg.json",
        "paraview_swelling_prescribed_particles_passive_I_103mmHg",
    ),
    (
        kinds.paraview_delamination,
        RUN,
        "logs/paraview/delamination/conserved/single_40kPa_averaged.log",
        "results/benchmarks/paraview_delamination_conserved_single_40kPa_averaged.tsv",
        "results/provenance/paraview_delamination_conserved_single_40kPa_averaged.json",
        "paraview_delamination_conserved_single_40kPa_averaged",
    ),
    (
        kinds.animation,
        RUN,
        "logs/animation/conserved/single_40kPa_averaged.log",
        "results/benchmarks/animation_conserved_single_40kPa_averaged.tsv",
        "results/provenance/animation_conserved_single_40kPa_averaged.json",
        "animation_conserved_single_40kPa_averaged",
    ),
    (
        kinds.variant,
        dict(form="paper"),
        "logs/variants/hourglass_paper.log",
        "results/benchmarks/variant_hourglass_paper.tsv",
        "results/provenance/variant_hourglass_paper.json",
        "variant_hourglass_paper",
    ),
]


@pytest.mark.parametrize(
    "kind, wildcards, log, bench, provenance, name", EXPECTED, ids=lambda v: getattr(v, "rule", None)
)
def test_a_kind_names_its_files_and_runs_as_before(kind, wildcards, log, bench, provenance, name):
    assert kind.log.format(**wildcards) == log
    assert kind.benchmark.format(**wildcards) == bench
    assert kind.provenance.format(**wildcards) == provenance
    assert kind.name(wildcards) == name
    assert jobs.kind(kind.rule) is kind


def test_a_kinds_outputs_nest_by_its_key():
    assert kinds.swelling_convergence_dx.output("swelling/convergence/states", ".npz").format(**SC) == (
        "results/swelling/convergence/states/prescribed/particles/active_dx6.npz"
    )
    assert kinds.variant.output("variants", "_growth.csv").format(form="energy") == (
        "results/variants/hourglass_energy_growth.csv"
    )


def test_a_job_types_the_numbers_of_its_key():
    sm = SimpleNamespace(wildcards=dict(DAMAGE), rule="procedure_delaminate")
    w = jobs.typed(sm.wildcards)
    assert (w.poolset, w.sigma, w.factor) == ("single", 40.0, 1)
    assert kinds.procedure_delaminate.name(sm.wildcards) == "procedure_single_40kPa_x1"


def test_a_number_becomes_file_name_text_in_one_place():
    """jobs.text gives a wildcard's text (``:g``) and typed() reads it back; the rules format no number themselves."""
    assert jobs.text(103.0) == "103" and jobs.text([0.5, 2.0]) == ["0.5", "2"]
    assert jobs.typed({"sigma": jobs.text(30.0), "dx": jobs.text(2.12)}).dx == 2.12
    rules = "".join(p.read_text() for p in (ROOT / "workflow" / "rules").glob("*.smk"))
    assert not re.findall(r"\{[^{}]*:[^{}]*g\}", rules)
