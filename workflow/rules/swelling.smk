import re


wildcard_constraints:
    case="|".join(re.escape(c) for c in CASES),
    pressure="|".join(re.escape(p) for p in SWELL_PRESSURES),


rule swell:
    """One GAG pool ({case}, as {pool}) in the {model} wall at {pressure} mmHg, {law} charge: conversion, then swelling
    (states)."""
    input:
        code=SPHGAG,
        state=STATE,
    output:
        states="results/swelling/states/{law}/{pool}/{model}_{case}_{pressure}mmHg.npz",
        provenance="results/provenance/swell_{law}_{pool}_{model}_{case}_{pressure}mmHg.json",
    log:
        "logs/swell/{law}/{pool}/{model}_{case}_{pressure}mmHg.log",
    benchmark:
        "results/benchmarks/swell_{law}_{pool}_{model}_{case}_{pressure}mmHg.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=7,
        mem_mb=1500,
    params:
        state_slice=lambda wildcards: dict(PRESSURISED_SLICE, model=wildcards.model),
        pool=lambda wildcards: SW["cases"][wildcards.case],
        settings=swell_settings,
        gag=lambda wildcards: GAG[wildcards.law],
    script:
        "../scripts/swell.py"


rule pool_stresses:
    """The stresses around the pool ({case} as {pool}, {model} wall, {pressure} mmHg, {law} charge) in every state of
    its run."""
    input:
        code=SPHGAG,
        states=rules.swell.output.states,
    output:
        table="results/swelling/runs/{law}/{pool}/{model}_{case}_{pressure}mmHg.csv",
        provenance="results/provenance/pool_stresses_{law}_{pool}_{model}_{case}_{pressure}mmHg.json",
    log:
        "logs/pool_stresses/{law}/{pool}/{model}_{case}_{pressure}mmHg.log",
    benchmark:
        "results/benchmarks/pool_stresses_{law}_{pool}_{model}_{case}_{pressure}mmHg.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    params:
        state_slice=lambda wildcards: dict(PRESSURISED_SLICE, model=wildcards.model),
        pool=lambda wildcards: SW["cases"][wildcards.case],
        settings=swell_settings,
        gag=lambda wildcards: GAG[wildcards.law],
        probe_length=SW["probe_length_um"],
    script:
        "../scripts/pool_stresses.py"


rule tip_stress:
    """All swelling runs (every charge law and pool model) in one tidy table (figure 4)."""
    input:
        SWELL_RUNS,
    output:
        report(
            "results/swelling/tip_stress.csv",
            caption="../report/tip_stress.rst",
            category="3 Swelling",
            labels={"result": "Table: every swelling run (figure 4)"},
        ),
    log:
        "logs/tip_stress.log",
    benchmark:
        "results/benchmarks/tip_stress.tsv"
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/concat_tables.py"


SC = config["swelling_convergence"]
CONVERGENCE_DX = [f"{dx:g}" for dx in SC["dx_um"]]
# what the study's simulations depend on besides their charge law (params gag; the measurement adds
# swelling.probe_length_um)
SC_SIMULATION = dict(
    bilayer=config["bilayer"],
    numerics=config["numerics"],
    homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
    settings=swell_settings,
    cases={c: SW["cases"][c] for c in SC["cases"]},
    pressure=SC["pressure_mmHg"],
)


wildcard_constraints:
    dx="|".join(re.escape(dx) for dx in CONVERGENCE_DX),


rule swelling_convergence_dx:
    """Resolution study, one particle spacing (dx = {dx} um), {law} charge, pools as {pool}: passive wall, every study
    pool swollen."""
    input:
        code=SPHGAG,
    output:
        states="results/swelling/convergence/states/{law}/{pool}/dx{dx}.npz",
        provenance="results/provenance/swelling_convergence_{law}_{pool}_dx{dx}.json",
    log:
        "logs/swelling_convergence/{law}/{pool}/dx{dx}.log",
    benchmark:
        "results/benchmarks/swelling_convergence_{law}_{pool}_dx{dx}.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=26,
        mem_mb=2500,
    params:
        **SC_SIMULATION,
        gag=lambda wildcards: GAG[wildcards.law],
    script:
        "../scripts/swelling_convergence.py"


rule swelling_convergence_stresses:
    """Resolution study, one particle spacing (dx = {dx} um), {law} charge, pools as {pool}: the pool stresses of the
    saved states."""
    input:
        code=SPHGAG,
        states=rules.swelling_convergence_dx.output.states,
    output:
        table="results/swelling/convergence/{law}/{pool}/dx{dx}.csv",
        provenance="results/provenance/swelling_convergence_stresses_{law}_{pool}_dx{dx}.json",
    log:
        "logs/swelling_convergence/{law}/{pool}/stresses_dx{dx}.log",
    benchmark:
        "results/benchmarks/swelling_convergence_stresses_{law}_{pool}_dx{dx}.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1500,
    params:
        **SC_SIMULATION,
        gag=lambda wildcards: GAG[wildcards.law],
        probe_length=SW["probe_length_um"],
    script:
        "../scripts/swelling_convergence_stresses.py"


rule swelling_convergence:
    """The resolution study of the pool stresses (every charge law and pool model) in one tidy table."""
    input:
        swell_runs(rules.swelling_convergence_stresses.output.table, model=[], case=[], pressure=[], dx=CONVERGENCE_DX),
    output:
        report(
            "results/swelling/convergence.csv",
            caption="../report/swelling_convergence_table.rst",
            category="3 Swelling",
            labels={"result": "Resolution study of the pool stresses (table)"},
        ),
    log:
        "logs/swelling_convergence.log",
    benchmark:
        "results/benchmarks/swelling_convergence.tsv"
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/concat_tables.py"
