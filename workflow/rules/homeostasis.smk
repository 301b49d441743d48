wildcard_constraints:
    model="passive|active",


rule homeostasis:
    """Figure 2b: deposition pre-stretches ramped at the held in vivo inner radius; the carried pressure is measured."""
    input:
        code=code_of("homeostasis"),
    output:
        state="results/states/homeostatic.npz",
        summary=report(
            "results/homeostasis/summary.csv",
            caption="../report/homeostasis_summary.rst",
            category="2 Homeostasis",
            labels={"result": "Table: the homeostatic state and the pressure it carries"},
        ),
        profile="results/homeostasis/profile.csv",
        layers="results/homeostasis/layers.csv",
        particles="results/homeostasis/particles.csv",
        provenance="results/provenance/homeostasis.json",
    log:
        "logs/homeostasis.log",
    benchmark:
        "results/benchmarks/homeostasis.tsv"
    threads: 1
    params:
        slice=HOMEOSTATIC_SLICE,
    script:
        "../scripts/homeostasis.py"


rule homeostasis_target:
    """The carried homeostatic pressure beside the reference value Table 2 was made for (a table, no simulation)."""
    input:
        summary=rules.homeostasis.output.summary,
    output:
        "results/homeostasis/target.csv",
    log:
        "logs/homeostasis_target.log",
    benchmark:
        "results/benchmarks/homeostasis_target.tsv"
    params:
        target_pressure=config["homeostasis"]["target_pressure_mmHg"],
    script:
        "../scripts/homeostasis_target.py"


rule bilayer_pressure_diameter:
    """Passive or active bi-layered model under pressure control, beside the semi-analytical tube."""
    input:
        code=code_of("bilayer_pressure_diameter"),
        homeostatic=rules.homeostasis.output.state,
    output:
        table="results/calibration/bilayer_{model}.csv",
        exact="results/calibration/bilayer_{model}_exact_curve.csv",
        transmural="results/calibration/transmural_{model}.csv",
        states=[STATE.format(model="{model}", pressure=p) for p in STATE_PRESSURES],
        provenance=JOBS.bilayer_pressure_diameter.provenance,
    log:
        JOBS.bilayer_pressure_diameter.log,
    benchmark:
        JOBS.bilayer_pressure_diameter.benchmark
    threads: 1
    params:
        slice=PRESSURISED_SLICE,
        homeostatic_slice=HOMEOSTATIC_SLICE,
        active=lambda wildcards: wildcards.model == "active",
    script:
        "../scripts/bilayer_pressure_diameter.py"


rule transmural:
    """Transmural stress profiles of all models in one tidy table (figure 3b,c)."""
    input:
        rules.calibrate_mean.output.transmural,
        expand(rules.bilayer_pressure_diameter.output.transmural, model=("passive", "active")),
    output:
        "results/calibration/transmural.csv",
    log:
        "logs/transmural.log",
    benchmark:
        "results/benchmarks/transmural.tsv"
    script:
        "../scripts/concat_tables.py"


rule bilayer_table:
    """Passive and active pressure-diameter in one table, and the outer-diameter reduction by activation."""
    input:
        code=code_of("bilayer_table"),
        passive=rules.bilayer_pressure_diameter.output.table.format(model="passive"),
        active=rules.bilayer_pressure_diameter.output.table.format(model="active"),
    output:
        table="results/calibration/bilayer_pressure_diameter.csv",
        activation="results/calibration/activation_summary.csv",
    log:
        "logs/bilayer_table.log",
    benchmark:
        "results/benchmarks/bilayer_table.tsv"
    params:
        pressure=config["bilayer_calibration"]["activation_pressure_mmHg"],
    script:
        "../scripts/bilayer_table.py"
