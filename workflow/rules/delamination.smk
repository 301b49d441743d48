wildcard_constraints:
    poolset=one_of(DE["pool_sets"]),
    sigma=r"[0-9.]+",
    dedx=one_of(DE_DX),


rule delaminate:
    """Pool set {poolset} in the passive wall, {law} charge: seeded, swollen, grown by damage at sigma_cr = {sigma} kPa
    ({criterion})."""
    input:
        code=code_of("delaminate"),
        state=DE_STATE,
    output:
        **de_run(JOBS.delaminate.key),
        provenance=JOBS.delaminate.provenance,
    log:
        JOBS.delaminate.log,
    benchmark:
        JOBS.delaminate.benchmark
    threads: 1
    resources:
        mem_mb=1500,
    params:
        state_slice=dict(PRESSURISED_SLICE, model="passive"),
        pools=lambda wildcards: DE["pool_sets"][wildcards.poolset],
        delamination=de_law_settings,
        gag=lambda wildcards: GAG[wildcards.law],
    script:
        "../scripts/delaminate.py"


rule delaminate_fracture_energy:
    """Pool set {poolset} in the passive wall, {law} charge, grown by the damage law with a fracture energy G_c = {gc}
    J/m^2 (onset at sigma_cr = {sigma} kPa, {criterion}); G_c = paper (MATCHED): the energy the paper's law
    dissipates."""
    input:
        code=code_of("delaminate"),
        state=DE_STATE,
        matched=lambda wildcards: de_run(DE_MATCHED)["summary"] if wildcards.gc == MATCHED else [],
    output:
        **de_run(JOBS.delaminate_fracture_energy.key),
        provenance=JOBS.delaminate_fracture_energy.provenance,
    log:
        JOBS.delaminate_fracture_energy.log,
    benchmark:
        JOBS.delaminate_fracture_energy.benchmark
    wildcard_constraints:
        gc=one_of(DE_TOUGHNESS),
    threads: 1
    params:
        state_slice=dict(PRESSURISED_SLICE, model="passive"),
        pools=lambda wildcards: DE["pool_sets"][wildcards.poolset],
        delamination=de_fracture_energy_settings,
        gag=lambda wildcards: GAG[wildcards.law],
    script:
        "../scripts/delaminate.py"


rule delamination_growth:
    """Every delamination run's growth rows under the configured damage law (every charge law) in one tidy table."""
    input:
        run_tables(DE_LAW_NAMES, "growth"),
    output:
        "results/delamination/growth.csv",
    log:
        "logs/delamination_growth.log",
    benchmark:
        "results/benchmarks/delamination_growth.tsv"
    script:
        "../scripts/concat_tables.py"


rule delamination_summary:
    """One row per delamination run under the configured damage law (every charge law)."""
    input:
        run_tables(DE_LAW_NAMES, "summary"),
    output:
        report(
            "results/delamination/summary.csv",
            caption="../report/delamination_summary.rst",
            category="5 Delamination",
            labels={"result": "Table: one row per delamination run"},
        ),
    log:
        "logs/delamination_summary.log",
    benchmark:
        "results/benchmarks/delamination_summary.tsv"
    script:
        "../scripts/concat_tables.py"


rule fracture_energy_growth:
    """Every run of the damage law with a fracture energy: its growth rows (every charge law) in one tidy table."""
    input:
        run_tables(DE_FE_NAMES, "growth"),
    output:
        "results/delamination/fracture_energy/growth.csv",
    log:
        "logs/fracture_energy_growth.log",
    benchmark:
        "results/benchmarks/fracture_energy_growth.tsv"
    script:
        "../scripts/concat_tables.py"


rule fracture_energy_summary:
    """One row per run of the damage law with a fracture energy (every charge law), beside Griffith's closed form."""
    input:
        run_tables(DE_FE_NAMES, "summary"),
    output:
        report(
            "results/delamination/fracture_energy/summary.csv",
            caption="../report/fracture_energy_summary.rst",
            category="5 Delamination",
            labels={"result": "Table: the damage law with a fracture energy, beside Griffith"},
        ),
    log:
        "logs/fracture_energy_summary.log",
    benchmark:
        "results/benchmarks/fracture_energy_summary.tsv"
    script:
        "../scripts/concat_tables.py"


rule delamination_convergence_dx:
    """Resolution study of delamination, one particle spacing (dx = {dedx} um), {law} charge, {criterion} onset:
    the pool sets of delamination.convergence.pool_sets."""
    input:
        code=code_of("delamination_convergence"),
    output:
        table=JOBS.delamination_convergence_dx.output("delamination/convergence", ".csv"),
        provenance=JOBS.delamination_convergence_dx.provenance,
    log:
        JOBS.delamination_convergence_dx.log,
    benchmark:
        JOBS.delamination_convergence_dx.benchmark
    threads: 1
    resources:
        runtime=25,
        mem_mb=2500,
    params:
        bilayer=config["bilayer"],
        numerics=config["numerics"],
        homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
        delamination=lambda wildcards: DelaminationSettings.params(
            DE,
            *DE_AT_CONFIG,
            criteria=[wildcards.criterion],
            pool_sets={name: DE["pool_sets"][name] for name in DE["convergence"]["pool_sets"]},
        ),
        gag=lambda wildcards: GAG[wildcards.law],
    script:
        "../scripts/delamination_convergence.py"


rule delamination_convergence:
    """The delamination resolution study (every charge law) in one tidy table."""
    input:
        expand(rules.delamination_convergence_dx.output.table, law=LAWS, dedx=DE_DX, criterion=DE["criteria"]),
    output:
        report(
            "results/delamination/convergence.csv",
            caption="../report/delamination_convergence.rst",
            category="5 Delamination",
            labels={"result": "Resolution study of delamination (table)"},
        ),
    log:
        "logs/delamination_convergence.log",
    benchmark:
        "results/benchmarks/delamination_convergence.tsv"
    script:
        "../scripts/concat_tables.py"


rule delamination_gci:
    """The discretisation error of the onset, runaway and merge concentrations: observed order, extrapolated value and
    grid convergence index of the three finest spacings (Celik et al. 2008)."""
    input:
        code=code_of("delamination_gci"),
        convergence=rules.delamination_convergence.output[0],
    output:
        report(
            "results/delamination/gci.csv",
            caption="../report/delamination_gci.rst",
            category="5 Delamination",
            labels={"result": "Resolution study of delamination: GCI (table)"},
        ),
    log:
        "logs/delamination_gci.log",
    benchmark:
        "results/benchmarks/delamination_gci.tsv"
    script:
        "../scripts/delamination_gci.py"
