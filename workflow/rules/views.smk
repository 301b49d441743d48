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
        series=directory(JOBS.paraview_delamination.output("paraview/delamination", "")),
        provenance=JOBS.paraview_delamination.provenance,
    log:
        JOBS.paraview_delamination.log,
    benchmark:
        JOBS.paraview_delamination.benchmark
    script:
        "../scripts/paraview.py"


rule paraview_swelling:
    """Swelling run {law}/{pool}/{model}_{case}_{pressure}mmHg: its states as a ParaView series (a .vtu file per state, a .pvd
    collection)."""
    input:
        code=code_of("paraview"),
        states=rules.swell.output.states,
    output:
        series=directory(JOBS.paraview_swelling.output("paraview/swelling", "")),
        provenance=JOBS.paraview_swelling.provenance,
    log:
        JOBS.paraview_swelling.log,
    benchmark:
        JOBS.paraview_swelling.benchmark
    script:
        "../scripts/paraview.py"


rule animation:
    """Delamination run {law}/{run} drawn frame by frame from its ParaView series: an animated GIF."""
    input:
        code=code_of("animation"),
        series=rules.paraview_delamination.output.series,
    output:
        report(
            f"figures/animations/{JOBS.animation.key}.gif",
            caption="../report/animation.rst",
            category="5 Delamination",
            subcategory="Animations",
            labels={"charge law": "{law}", "run": "{run}"},
        ),
    log:
        JOBS.animation.log,
    benchmark:
        JOBS.animation.benchmark
    script:
        "../scripts/animation.py"


# every run's series and animation: the target views
RUN_VIEWS = (
    swell_runs(rules.paraview_swelling.output.series, pools=SWELL_POOLS)
    + expand(rules.paraview_delamination.output.series, zip, **law_and_run(DE_SNAPSHOT_NAMES))
    + expand(rules.animation.output, zip, **law_and_run(DE_SNAPSHOT_NAMES))
)
