wildcard_constraints:
    case=one_of(CASES),
    pressure=one_of(SWELL_PRESSURES),


rule swell:
    """One GAG pool ({case}, as {pool}) in the {model} wall at {pressure} mmHg, {law} charge: conversion, then swelling
    (states)."""
    input:
        code=code_of("swell"),
        state=STATE,
    output:
        states=JOBS.swell.output("swelling/states", ".npz"),
        provenance=JOBS.swell.provenance,
    log:
        JOBS.swell.log,
    benchmark:
        JOBS.swell.benchmark
    threads: 1
    resources:
        runtime=8,
        mem_mb=1500,
    params:
        state_slice=lambda wildcards: dict(PRESSURISED_SLICE, model=wildcards.model),
        pool=lambda wildcards: SW["cases"][wildcards.case],
        settings=swell_settings,
        gag=lambda wildcards: GAG[wildcards.law],
        grading=config["grading"],
    script:
        "../scripts/swell.py"


rule pool_stresses:
    """The stresses around the pool ({case} as {pool}, {model} wall, {pressure} mmHg, {law} charge) in every state of
    its run."""
    input:
        code=code_of("pool_stresses"),
        states=rules.swell.output.states,
    output:
        table=JOBS.pool_stresses.output("swelling/runs", ".csv"),
        provenance=JOBS.pool_stresses.provenance,
    log:
        JOBS.pool_stresses.log,
    benchmark:
        JOBS.pool_stresses.benchmark
    threads: 1
    params:
        state_slice=lambda wildcards: dict(PRESSURISED_SLICE, model=wildcards.model),
        pool=lambda wildcards: SW["cases"][wildcards.case],
        settings=swell_settings,
        gag=lambda wildcards: GAG[wildcards.law],
        grading=config["grading"],
        probe_length=SW["probe_length_um"],
        tip_probe=SW["tip_probe"],
    script:
        "../scripts/pool_stresses.py"


rule tip_stress:
    """Figure 4's swelling runs (every charge law and pool model of swelling.pool_models) in one tidy table."""
    input:
        swell_runs(rules.pool_stresses.output.table),
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
    script:
        "../scripts/concat_tables.py"


SC = config["swelling_convergence"]
CONVERGENCE_DX = text(SC["dx_um"])
# what the study's simulations depend on besides their charge law (params gag; the measurement adds
# swelling.probe_length_um): first the run's spacing, as its key names it
SC_SIMULATION = dict(
    dx=lambda wildcards: wildcards.dx,
    bilayer=config["bilayer"],
    numerics=config["numerics"],
    homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
    settings=swell_settings,
    cases={c: SW["cases"][c] for c in SC["cases"]},
    grading=config["grading"],
    pressure=SC["pressure_mmHg"],
    calibration=BilayerCalibration.activation(config["bilayer_calibration"]),
    volume_ratios=SC["volume_ratios"],
)


wildcard_constraints:
    dx=one_of(CONVERGENCE_DX),


rule swelling_convergence_dx:
    """Resolution study, one particle spacing (dx = {dx} um), {law} charge, pools as {pool}: the {model} wall, every
    study pool swollen."""
    input:
        code=code_of("swelling_convergence"),
    output:
        states=JOBS.swelling_convergence_dx.output("swelling/convergence/states", ".npz"),
        provenance=JOBS.swelling_convergence_dx.provenance,
    log:
        JOBS.swelling_convergence_dx.log,
    benchmark:
        JOBS.swelling_convergence_dx.benchmark
    threads: 1
    resources:
        runtime=90,
        mem_mb=4500,
    params:
        **SC_SIMULATION,
        gag=lambda wildcards: GAG[wildcards.law],
        active=lambda wildcards: wildcards.model == "active",
    script:
        "../scripts/swelling_convergence.py"


rule swelling_convergence_stresses:
    """Resolution study, one particle spacing (dx = {dx} um), {law} charge, pools as {pool}, {model} wall: the pool
    stresses of the saved states."""
    input:
        code=code_of("swelling_convergence_stresses"),
        states=rules.swelling_convergence_dx.output.states,
    output:
        table=JOBS.swelling_convergence_stresses.output("swelling/convergence", ".csv"),
        provenance=JOBS.swelling_convergence_stresses.provenance,
    log:
        JOBS.swelling_convergence_stresses.log,
    benchmark:
        JOBS.swelling_convergence_stresses.benchmark
    threads: 1
    resources:
        mem_mb=2000,
    params:
        **SC_SIMULATION,
        gag=lambda wildcards: GAG[wildcards.law],
        active=lambda wildcards: wildcards.model == "active",
        probe_length=SW["probe_length_um"],
    script:
        "../scripts/swelling_convergence_stresses.py"


rule swelling_convergence:
    """The resolution study of the pool stresses (every charge law and pool model) in one tidy table."""
    input:
        swell_runs(  # every run of the study: its charge laws and pool models, walls and spacings
            rules.swelling_convergence_stresses.output.table,
            pools=SC["pool_models"],
            model=SC["models"],
            case=[],
            pressure=[],
            dx=CONVERGENCE_DX,
        ),
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
    script:
        "../scripts/concat_tables.py"


rule swelling_gci:
    """The discretisation error of figure 4's quantities (Celik et al. 2008): at the study's volume ratios and at the
    stated concentrations, the observed order, the extrapolated value and the GCI of the finest spacing; and at
    every step of the ramp, the bands of figure 4."""
    input:
        code=code_of("swelling_gci"),
        table=rules.swelling_convergence.output[0],
    output:
        table=report(
            "results/swelling/gci.csv",
            caption="../report/swelling_gci.rst",
            category="3 Swelling",
            labels={"result": "Discretisation error of figure 4's quantities (GCI)"},
        ),
        band="results/swelling/gci_band.csv",
    log:
        "logs/swelling_gci.log",
    benchmark:
        "results/benchmarks/swelling_gci.tsv"
    threads: 1
    params:
        concentrations=SC["gci_concentrations_mEq_l"],
        pressure=SC["pressure_mmHg"],
    script:
        "../scripts/swelling_gci.py"
