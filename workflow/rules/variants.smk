# Numerical variants of the study (target variants): figure 4's first pool and figure 5's pool under each form of the
# hourglass control, eq. (2.14) as printed beside its energy form (the default), each from a wall of its own.

from sphgag.engine.forces import HOURGLASS_FORMS


rule variant:
    """Figure 4's first pool and figure 5's pool with the hourglass control's {form} form (the paper's charge law), from
    a passive wall of its own at the delamination pressure."""
    input:
        code=code_of("variant"),
    output:
        swelling=JOBS.variant.output("variants", "_swelling.csv"),
        growth=JOBS.variant.output("variants", "_growth.csv"),
        summary=JOBS.variant.output("variants", "_summary.csv"),
        provenance=JOBS.variant.provenance,
    log:
        JOBS.variant.log,
    benchmark:
        JOBS.variant.benchmark
    wildcard_constraints:
        form=one_of(HOURGLASS_FORMS),
    threads: 1
    resources:
        runtime=30,
        mem_mb=2000,
    params:
        bilayer=config["bilayer"],
        numerics=lambda wildcards: dict(config["numerics"], hourglass=wildcards.form),
        homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
        # figure 4's first pool and figure 5's pool, with what their runs read (not every case, set or figure role)
        swelling=dict(SWELL_SETTINGS, probe_length_um=SW["probe_length_um"], case=CASES[0], pool=SW["cases"][CASES[0]]),
        delamination=dict(
            DE_SETTINGS,
            pressure_mmHg=DE["pressure_mmHg"],
            critical_stress_kPa=DE["critical_stress_kPa"],
            criterion=DE["criteria"][0],
            case=FIG5_SET,
            pools=DE["pool_sets"][FIG5_SET],
        ),
        gag=canonical(law_gag(config["gag"], PAPER_LAW)),  # the paper's law, whether or not the study runs it
    script:
        "../scripts/variant.py"


rule variants_figure:
    """The hourglass control's forms side by side: figure 4's first pool and figure 5's pool under each."""
    input:
        code=code_of("variants_figure"),
        swelling=expand(rules.variant.output.swelling, form=HOURGLASS_FORMS),
        growth=expand(rules.variant.output.growth, form=HOURGLASS_FORMS),
        summary=expand(rules.variant.output.summary, form=HOURGLASS_FORMS),
    output:
        pdf="figures/variants_hourglass.pdf",
        png=report(
            "figures/variants_hourglass.png",
            caption="../report/variants_hourglass.rst",
            category="6 Variants",
            labels={"result": "The hourglass control: eq. (2.14) as printed beside its energy form"},
        ),
    log:
        "logs/variants_figure.log",
    benchmark:
        "results/benchmarks/variants_figure.tsv"
    threads: 1
    params:
        forms={name: form.short for name, form in HOURGLASS_FORMS.items()},
        default=config["numerics"]["hourglass"],
    script:
        "../scripts/variants_figure.py"


# The pool models beside the paper's (swelling.variant_pool_models): figure 4's swelling runs of every pool model, and
# figure 4 and its claims redrawn with them, by the rules of target `all` with these tables.
VARIANT_POOLS = SW["pool_models"] + SW["variant_pool_models"]


use rule tip_stress as variants_tip_stress with:
    input:
        swell_runs(rules.pool_stresses.output.table, pools=VARIANT_POOLS),
    output:
        report(
            "results/variants/tip_stress.csv",
            caption="../report/tip_stress.rst",
            category="6 Variants",
            labels={"result": "Table: figure 4's swelling runs of every pool model"},
        ),
    log:
        "logs/variants_tip_stress.log",
    benchmark:
        "results/benchmarks/variants_tip_stress.tsv"


use rule fig4 as variants_fig4 with:
    input:
        code=code_of("fig4"),
        tips=rules.variants_tip_stress.output[0],
        particles=rules.homeostasis.output.particles,
        band=study_input(lambda: rules.swelling_gci.output.band, "resolution"),
        resolution=study_input(lambda: rules.swelling_convergence.output[0], "resolution"),
    output:
        **law_figures("variants_pool_models", "6 Variants", "Figure 4 with every pool model"),
    log:
        "logs/variants_fig4.log",
    benchmark:
        "results/benchmarks/variants_fig4.tsv"


use rule claims as variants_claims with:
    input:
        code=code_of("claims"),
        mean=rules.calibrate_mean.output.states,
        bilayer=rules.bilayer_table.output.table,
        activation=rules.bilayer_table.output.activation,
        layers=rules.homeostasis.output.layers,
        transmural=rules.transmural.output[0],
        tips=rules.variants_tip_stress.output[0],
        growth=rules.delamination_growth.output[0],
        delamination=rules.delamination_summary.output[0],
        sensitivity=study_input(lambda: rules.sensitivity_tables.output.samples, "sensitivity"),
        band=study_input(lambda: rules.swelling_gci.output.band, "resolution"),
        resolution=study_input(lambda: rules.swelling_convergence.output[0], "resolution"),
        procedure=study_input(lambda: rules.procedure_summary.output.table, "paper_procedure"),
        procedure_damage=study_input(lambda: rules.procedure_summary.output.damage, "paper_procedure"),
    output:
        table=report(
            "results/variants/claims.csv",
            caption="../report/claims.rst",
            category="6 Variants",
            labels={"result": "The paper's claims against our numbers, every pool model"},
        ),
        markdown="results/variants/claims.md",
    log:
        "logs/variants_claims.log",
    benchmark:
        "results/benchmarks/variants_claims.tsv"
