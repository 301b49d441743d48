# What researchers look at beside the figures: every swelling run and every delamination run as a ParaView series
# (results/paraview/swelling/{law}/{pool}/{run}/{run}.pvd, results/paraview/delamination/{law}/{run}/{run}.pvd, one
# .vtu per saved state), and an animation of every delamination run drawn from its series
# (figures/animations/{law}/{run}.gif).


rule paraview_delamination:
    """Delamination run {law}/{run}: its snapshots as a ParaView series (a .vtu file per snapshot, a .pvd collection)."""
    input:
        code=code_of("paraview"),
        states=DE_SNAPSHOTS,
    output:
        series=directory(f"results/paraview/delamination/{DE_ANY_NAME}"),
        provenance=f"results/provenance/paraview_delamination_{flat(DE_ANY_NAME)}.json",
    log:
        f"logs/paraview/delamination/{DE_ANY_NAME}.log",
    benchmark:
        f"results/benchmarks/paraview_delamination_{flat(DE_ANY_NAME)}.tsv"
    conda:
        "../envs/sphgag.yaml"
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/paraview.py"


rule paraview_swelling:
    """Swelling run {law}/{pool}/{model}_{case}_{pressure}mmHg: its states as a ParaView series (a .vtu file per state, a .pvd
    collection)."""
    input:
        code=code_of("paraview"),
        states=rules.swell.output.states,
    output:
        series=directory(f"results/paraview/swelling/{SWELL_NAME}"),
        provenance=f"results/provenance/paraview_swelling_{flat(SWELL_NAME)}.json",
    log:
        f"logs/paraview/swelling/{SWELL_NAME}.log",
    benchmark:
        f"results/benchmarks/paraview_swelling_{flat(SWELL_NAME)}.tsv"
    conda:
        "../envs/sphgag.yaml"
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/paraview.py"


rule animation:
    """Delamination run {law}/{run} drawn frame by frame from its ParaView series: an animated GIF."""
    input:
        code=code_of("animation"),
        series=rules.paraview_delamination.output.series,
    output:
        report(
            f"figures/animations/{DE_ANY_NAME}.gif",
            caption="../report/animation.rst",
            category="5 Delamination",
            subcategory="Animations",
            labels={"charge law": "{law}", "run": "{run}"},
        ),
    log:
        f"logs/animation/{DE_ANY_NAME}.log",
    benchmark:
        f"results/benchmarks/animation_{flat(DE_ANY_NAME)}.tsv"
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/animation.py"


# every run's series and animation: the target views
RUN_VIEWS = (
    swell_runs(rules.paraview_swelling.output.series, pools=SWELL_POOLS)
    + expand(rules.paraview_delamination.output.series, zip, **law_and_run(DE_SNAPSHOT_NAMES))
    + expand(rules.animation.output, zip, **law_and_run(DE_SNAPSHOT_NAMES))
)
