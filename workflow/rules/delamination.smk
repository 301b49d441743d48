import re

DE = config["delamination"]
DE_PRESSURE = f"{DE['pressure_mmHg']:g}"
# one run per (pool set, sigma_cr, onset criterion): the single pool at every sigma_cr of figure 5, the other sets at
# critical_stress_kPa
DE_RUNS = [
    dict(poolset=case, sigma=f"{sigma:g}", criterion=criterion)
    for case in DE["pool_sets"]
    for sigma in (DE["critical_stresses_kPa"] if case == "single" else [DE["critical_stress_kPa"]])
    for criterion in DE["criteria"]
]
DE_SETTINGS = {k: v for k, v in DE.items() if k not in ("pool_sets", "critical_stresses_kPa", "convergence")}
DE_DX = [f"{dx:g}" for dx in DE["convergence"]["dx_um"]]
DE_GROWTH = [f"results/delamination/runs/{r['poolset']}_{r['sigma']}kPa_{r['criterion']}_growth.csv" for r in DE_RUNS]
DE_SUMMARIES = [
    f"results/delamination/runs/{r['poolset']}_{r['sigma']}kPa_{r['criterion']}_summary.csv" for r in DE_RUNS
]


wildcard_constraints:
    poolset="|".join(re.escape(c) for c in DE["pool_sets"]),
    sigma=r"[0-9.]+",
    criterion="averaged|particle",
    dedx="|".join(re.escape(dx) for dx in DE_DX),


rule delaminate:
    """Pool set {poolset} in the passive wall: seeded, swollen, grown by damage at sigma_cr = {sigma} kPa ({criterion})."""
    input:
        code=SPHGAG,
        state=f"results/states/passive_{DE_PRESSURE}mmHg.npz",
    output:
        growth="results/delamination/runs/{poolset}_{sigma}kPa_{criterion}_growth.csv",
        summary="results/delamination/runs/{poolset}_{sigma}kPa_{criterion}_summary.csv",
        snapshots="results/delamination/runs/{poolset}_{sigma}kPa_{criterion}_snapshots.npz",
        provenance="results/provenance/delaminate_{poolset}_{sigma}kPa_{criterion}.json",
    log:
        "logs/delaminate/{poolset}_{sigma}kPa_{criterion}.log",
    benchmark:
        "results/benchmarks/delaminate_{poolset}_{sigma}kPa_{criterion}.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=1000,
    params:
        state_slice=dict(PRESSURISED_SLICE, model="passive"),
        pools=lambda wildcards: DE["pool_sets"][wildcards.poolset],
        delamination=DE_SETTINGS,
        gag=config["gag"],
    script:
        "../scripts/delaminate.py"


rule delamination_growth:
    """Every delamination run's growth rows in one tidy table."""
    input:
        DE_GROWTH,
    output:
        "results/delamination/growth.csv",
    log:
        "logs/delamination_growth.log",
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/concat_tables.py"


rule delamination_summary:
    """One row per delamination run."""
    input:
        DE_SUMMARIES,
    output:
        report(
            "results/delamination/summary.csv",
            caption="../report/delamination_summary.rst",
            category="5 Delamination",
            labels={"result": "Table: one row per delamination run"},
        ),
    log:
        "logs/delamination_summary.log",
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/concat_tables.py"


rule delamination_convergence_dx:
    """Resolution study of delamination, one particle spacing (dx = {dedx} um): the single pool, every criterion."""
    input:
        code=SPHGAG,
    output:
        table="results/delamination/convergence/dx{dedx}.csv",
        provenance="results/provenance/delamination_convergence_dx{dedx}.json",
    log:
        "logs/delamination_convergence/dx{dedx}.log",
    benchmark:
        "results/benchmarks/delamination_convergence_dx{dedx}.tsv"
    conda:
        "../envs/sphgag.yaml"
    threads: 1
    resources:
        runtime=5,
        mem_mb=2500,
    params:
        bilayer=config["bilayer"],
        numerics=config["numerics"],
        homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
        delamination=dict(DE_SETTINGS, pool_sets=dict(single=DE["pool_sets"]["single"])),
        gag=config["gag"],
    script:
        "../scripts/delamination_convergence.py"


rule delamination_convergence:
    """The delamination resolution study in one tidy table."""
    input:
        expand(rules.delamination_convergence_dx.output.table, dedx=DE_DX),
    output:
        report(
            "results/delamination/convergence.csv",
            caption="../report/delamination_convergence.rst",
            category="5 Delamination",
            labels={"result": "Resolution study of delamination (table)"},
        ),
    log:
        "logs/delamination_convergence.log",
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/concat_tables.py"
