rule fig3a_mean:
    """Figure 3a for the mean-behaviour model: pressure-outer diameter and mean stress-stretch."""
    input:
        code=code_of("fig3a_mean"),
        states=rules.calibrate_mean.output.states,
        exact=rules.calibrate_mean.output.exact,
    output:
        pdf="figures/fig3a_mean.pdf",
        png=report(
            "figures/fig3a_mean.png",
            caption="../report/fig3a_mean.rst",
            category="1 Calibration",
            labels={"result": "Figure 3a: mean model, pressure-diameter and stress-stretch"},
        ),
    log:
        "logs/fig3a_mean.log",
    benchmark:
        "results/benchmarks/fig3a_mean.tsv"
    threads: 1
    params:
        homeostatic_pressure=config["homeostasis"]["target_pressure_mmHg"],
    script:
        "../scripts/fig3a_mean.py"


rule fig3b:
    """Figure 3b: transmural radial and circumferential stress of the mean model at the calibration's transmural
    pressures (103, 145, 200 mmHg)."""
    input:
        code=code_of("fig3b"),
        profiles=rules.transmural.output[0],
    output:
        pdf="figures/fig3b.pdf",
        png=report(
            "figures/fig3b.png",
            caption="../report/fig3b.rst",
            category="1 Calibration",
            labels={"result": "Figure 3b: mean model, stresses across the wall"},
        ),
    log:
        "logs/fig3b.log",
    benchmark:
        "results/benchmarks/fig3b.tsv"
    threads: 1
    script:
        "../scripts/fig3b.py"


rule fig3:
    """Figure 3, complete: mean, passive and active models (pressure-diameter, stress-stretch, transmural)."""
    input:
        code=code_of("fig3"),
        mean_states=rules.calibrate_mean.output.states,
        mean_exact=rules.calibrate_mean.output.exact,
        bilayer=rules.bilayer_table.output.table,
        passive_exact=rules.bilayer_pressure_diameter.output.exact.format(model="passive"),
        active_exact=rules.bilayer_pressure_diameter.output.exact.format(model="active"),
        profiles=rules.transmural.output[0],
    output:
        pdf="figures/fig3.pdf",
        png=report(
            "figures/fig3.png",
            caption="../report/fig3.rst",
            category="1 Calibration",
            labels={"result": "Figure 3, complete: mean and bi-layered models"},
        ),
    log:
        "logs/fig3.log",
    benchmark:
        "results/benchmarks/fig3.tsv"
    threads: 1
    params:
        homeostatic_pressure=config["homeostasis"]["target_pressure_mmHg"],
    script:
        "../scripts/fig3.py"


rule fig1:
    """Figure 1: particle layout of the bi-layered model, the kernel, the layer composition."""
    input:
        code=code_of("fig1"),
        particles=rules.homeostasis.output.particles,
    output:
        pdf="figures/fig1.pdf",
        png=report(
            "figures/fig1.png",
            caption="../report/fig1.rst",
            category="2 Homeostasis",
            labels={"result": "Figure 1: the particle model of the bi-layered wall"},
        ),
    log:
        "logs/fig1.log",
    benchmark:
        "results/benchmarks/fig1.tsv"
    threads: 1
    params:
        mass_fractions=config["bilayer"]["mass_fractions"],
        layers=Bilayer.of(config["bilayer"]).layer_names(),
        support_factor=config["numerics"]["kernel_support_factor"],
        dx=config["bilayer"]["dx_um"],
    script:
        "../scripts/fig1.py"


rule fig4:
    """Figure 4, once per charge law: the pools, and the tip radial and top hoop stress against GAG concentration;
    with the resolution study's bands and its tip stress against pool volume where target `resolution` has run."""
    input:
        code=code_of("fig4"),
        tips=rules.tip_stress.output[0],
        particles=rules.homeostasis.output.particles,
        band=study_input(lambda: rules.swelling_gci.output.band, "resolution"),
        resolution=study_input(lambda: rules.swelling_convergence.output[0], "resolution"),
    output:
        **law_figures("fig4", "3 Swelling", "Figure 4: stresses around a swelling GAG pool"),
    log:
        "logs/fig4.log",
    benchmark:
        "results/benchmarks/fig4.tsv"
    threads: 1
    params:
        cases=config["swelling"]["cases"],
        probe_length=config["swelling"]["probe_length_um"],
        laws=LAWS,
        max_concentration=config["swelling"]["max_concentration_mEq_l"],
        # the pressures of figure 3's transmural profiles: a pressure has one colour in figures 3 and 4
        pressures=config["calibration"]["transmural_pressures_mmHg"],
        pool_layers=config["bilayer"]["pool_layers"],
        band=study_evidence(lambda: rules.swelling_gci.output.band, "resolution"),
        resolution=study_evidence(lambda: rules.swelling_convergence.output[0], "resolution"),
    script:
        "../scripts/fig4.py"


rule claims:
    """The paper's claims (figures 3-7) against our numbers, from the CSV tables alone."""
    input:
        code=code_of("claims"),
        mean=rules.calibrate_mean.output.states,
        bilayer=rules.bilayer_table.output.table,
        activation=rules.bilayer_table.output.activation,
        layers=rules.homeostasis.output.layers,
        transmural=rules.transmural.output[0],
        tips=rules.tip_stress.output[0],
        growth=rules.delamination_growth.output[0],
        delamination=rules.delamination_summary.output[0],
        sensitivity=study_input(lambda: rules.sensitivity_tables.output.samples, "sensitivity"),
        band=study_input(lambda: rules.swelling_gci.output.band, "resolution"),
        resolution=study_input(lambda: rules.swelling_convergence.output[0], "resolution"),
        procedure=study_input(lambda: rules.procedure_summary.output.table, "paper_procedure"),
        procedure_damage=study_input(lambda: rules.procedure_summary.output.damage, "paper_procedure"),
        paper_settings=study_input(lambda: rules.paper_settings_table.output.table, "paper_settings"),
    output:
        table=report(
            "results/claims.csv",
            caption="../report/claims.rst",
            category="0 Claims",
            labels={"result": "The paper's claims against our numbers"},
        ),
        markdown="figures/claims.md",
    log:
        "logs/claims.log",
    benchmark:
        "results/benchmarks/claims.tsv"
    params:
        cases=config["swelling"]["cases"],
        max_concentration=config["swelling"]["max_concentration_mEq_l"],
        criteria=config["delamination"]["criteria"],
        figures=config["delamination"]["figures"],
        laws=LAWS,
        sensitivity=study_evidence(lambda: rules.sensitivity_tables.output.samples, "sensitivity"),
        band=study_evidence(lambda: rules.swelling_gci.output.band, "resolution"),
        resolution=study_evidence(lambda: rules.swelling_convergence.output[0], "resolution"),
        procedure=study_evidence(lambda: rules.procedure_summary.output.table, "paper_procedure"),
        procedure_damage=study_evidence(lambda: rules.procedure_summary.output.damage, "paper_procedure"),
        paper_settings=study_evidence(lambda: rules.paper_settings_table.output.table, "paper_settings"),
        study_pressure=config["swelling_convergence"]["pressure_mmHg"],
    script:
        "../scripts/claims.py"


rule swelling_convergence_figure:
    """Resolution study of the pool stresses: tip, top and pool volume change against concentration per dx and law."""
    input:
        code=code_of("swelling_convergence_figure"),
        table=rules.swelling_convergence.output[0],
    output:
        pdf="figures/swelling_convergence.pdf",
        png=report(
            "figures/swelling_convergence.png",
            caption="../report/swelling_convergence_figure.rst",
            category="3 Swelling",
            labels={"result": "Resolution study of the pool stresses (figure)"},
        ),
    log:
        "logs/swelling_convergence_figure.log",
    benchmark:
        "results/benchmarks/swelling_convergence_figure.tsv"
    threads: 1
    params:
        laws=LAWS,
    script:
        "../scripts/swelling_convergence_figure.py"


# figures 5-7: the delamination runs (rule delaminate) of the pool sets named by delamination.figures, one figure per
# charge law, one row of snapshots or line style per onset criterion.
# The wall's layers as [name, outer radius] from the lumen out: the snapshots' particles are greyed by layer
DE_LAYERS = [[name, outer] for name, _, outer in Bilayer.of(config["bilayer"]).bands()]
# figure 5a shows its set at critical_stress_kPa if that is one of its sigma_cr, else at the nearest one
FIG5_SIGMA = min(DE["critical_stresses_kPa"], key=lambda s: abs(s - DE["critical_stress_kPa"]))


# figures 5-7 (rules fig5, fig6, fig7) are one family: what differs between them is the pool sets and sigma_cr of the
# runs whose snapshots they draw and their report label; one script draws each by the rule's name.
# Figure 5: figure 5's pool set grown (snapshots), its tip radial stress against pseudo-time for every sigma_cr.
# Figure 6: pools at one radius (figure 6's sets, e.g. low and high separation): snapshots, interior and exterior growth.
# Figure 7: two pools offset in radius: four snapshots per criterion, tip stress and growth.
DE_FIGURE_RULES = dict(
    fig5=dict(poolsets=[FIG5_SET], sigma=FIG5_SIGMA, label="Figure 5: one pool grown by damage"),
    fig6=dict(poolsets=FIG6_SETS, sigma=DE["critical_stress_kPa"], label="Figure 6: two pools at the same radius"),
    fig7=dict(poolsets=[FIG7_SET], sigma=DE["critical_stress_kPa"], label="Figure 7: two pools offset in radius"),
)
for figure, spec in DE_FIGURE_RULES.items():

    rule:
        """Figure 5, 6 or 7 (the rule's name): the delamination runs of its pool sets (delamination.figures),
        snapshots and growth, one figure per charge law."""
        name:
            figure
        input:
            code=code_of("delamination_figure"),
            growth=rules.delamination_growth.output[0],
            summary=rules.delamination_summary.output[0],
            # the snapshots of the figure's runs, by law, then pool set, then criterion (the order the script reads)
            snapshots=[
                rules.delaminate.output.snapshots.format(
                    law=law, poolset=poolset, sigma=text(spec["sigma"]), criterion=criterion
                )
                for law in LAWS
                for poolset in spec["poolsets"]
                for criterion in DE["criteria"]
            ],
        output:
            **law_figures(figure, "5 Delamination", spec["label"]),
        log:
            f"logs/{figure}.log",
        benchmark:
            f"results/benchmarks/{figure}.tsv"
        threads: 1
        params:
            poolsets=spec["poolsets"],
            sigma=spec["sigma"],
            criteria=DE["criteria"],
            laws=LAWS,
            layers=DE_LAYERS,
        script:
            # one path for the whole family: Snakemake reads a rule's script path when its job runs, after the loop
            "../scripts/delamination_figure.py"
