import re

SW = config["swelling"]
CASES = list(SW["cases"])
SWELL_PRESSURES = [f"{p:g}" for p in SW["pressures_mmHg"]]
# what the simulations depend on; probe_length_um only sets where rule pool_stresses measures
SWELL_SETTINGS = {k: v for k, v in SW.items() if k not in ("cases", "models", "pressures_mmHg", "probe_length_um")}
SWELL_RUNS = expand(
    "results/swelling/runs/{model}_{case}_{pressure}mmHg.csv", model=SW["models"], case=CASES, pressure=SWELL_PRESSURES
)


wildcard_constraints:
    case="|".join(re.escape(c) for c in CASES),
    pressure="|".join(re.escape(p) for p in SWELL_PRESSURES),


rule swell:
    """One GAG pool ({case}) in the {model} wall at {pressure} mmHg: conversion, then swelling 0-150 mEq/l (states)."""
    input:
        code=SPHGAG,
        state="results/states/{model}_{pressure}mmHg.npz",
    output:
        states="results/swelling/states/{model}_{case}_{pressure}mmHg.npz",
        provenance="results/provenance/swell_{model}_{case}_{pressure}mmHg.json",
    log:
        "logs/swell/{model}_{case}_{pressure}mmHg.log",
    benchmark:
        "results/benchmarks/swell_{model}_{case}_{pressure}mmHg.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    params:
        state_slice=lambda wildcards: dict(PRESSURISED_SLICE, model=wildcards.model),
        pool=lambda wildcards: SW["cases"][wildcards.case],
        settings=SWELL_SETTINGS,
        gag=config["gag"],
    script:
        "../scripts/swell.py"


rule pool_stresses:
    """The stresses around the pool ({case}, {model} wall, {pressure} mmHg) in every state of its swelling run."""
    input:
        code=SPHGAG,
        states=rules.swell.output.states,
    output:
        table="results/swelling/runs/{model}_{case}_{pressure}mmHg.csv",
        provenance="results/provenance/pool_stresses_{model}_{case}_{pressure}mmHg.json",
    log:
        "logs/pool_stresses/{model}_{case}_{pressure}mmHg.log",
    benchmark:
        "results/benchmarks/pool_stresses_{model}_{case}_{pressure}mmHg.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    params:
        state_slice=lambda wildcards: dict(PRESSURISED_SLICE, model=wildcards.model),
        pool=lambda wildcards: SW["cases"][wildcards.case],
        settings=SWELL_SETTINGS,
        gag=config["gag"],
        probe_length=SW["probe_length_um"],
    script:
        "../scripts/pool_stresses.py"


rule tip_stress:
    """All swelling runs in one tidy table (figure 4)."""
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
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/concat_tables.py"


SC = config["swelling_convergence"]
CONVERGENCE_DX = [f"{dx:g}" for dx in SC["dx_um"]]
# what the study's simulations depend on (its measurement adds swelling.probe_length_um)
SC_SIMULATION = dict(
    bilayer=config["bilayer"],
    numerics=config["numerics"],
    homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
    settings=SWELL_SETTINGS,
    gag=config["gag"],
    cases={c: SW["cases"][c] for c in SC["cases"]},
    pressure=SC["pressure_mmHg"],
)


wildcard_constraints:
    dx="|".join(re.escape(dx) for dx in CONVERGENCE_DX),


rule swelling_convergence_dx:
    """Resolution study, one particle spacing (dx = {dx} um): passive wall, every study pool swollen (states)."""
    input:
        code=SPHGAG,
    output:
        states="results/swelling/convergence/states/dx{dx}.npz",
        provenance="results/provenance/swelling_convergence_dx{dx}.json",
    log:
        "logs/swelling_convergence/dx{dx}.log",
    benchmark:
        "results/benchmarks/swelling_convergence_dx{dx}.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=2500,
    params:
        **SC_SIMULATION,
    script:
        "../scripts/swelling_convergence.py"


rule swelling_convergence_stresses:
    """Resolution study, one particle spacing (dx = {dx} um): the pool stresses of the saved states."""
    input:
        code=SPHGAG,
        states=rules.swelling_convergence_dx.output.states,
    output:
        table="results/swelling/convergence/dx{dx}.csv",
        provenance="results/provenance/swelling_convergence_stresses_dx{dx}.json",
    log:
        "logs/swelling_convergence/stresses_dx{dx}.log",
    benchmark:
        "results/benchmarks/swelling_convergence_stresses_dx{dx}.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1500,
    params:
        **SC_SIMULATION,
        probe_length=SW["probe_length_um"],
    script:
        "../scripts/swelling_convergence_stresses.py"


rule swelling_convergence:
    """The resolution study of the pool stresses in one tidy table."""
    input:
        expand(rules.swelling_convergence_stresses.output.table, dx=CONVERGENCE_DX),
    output:
        report(
            "results/swelling/convergence.csv",
            caption="../report/swelling_convergence_table.rst",
            category="3 Swelling",
            labels={"result": "Resolution study of the pool stresses (table)"},
        ),
    log:
        "logs/swelling_convergence.log",
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/concat_tables.py"
