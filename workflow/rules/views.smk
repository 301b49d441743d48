# What researchers look at beside the figures: every swelling run and every delamination run as a ParaView series
# (results/paraview/{swelling,delamination}/{law}/{run}/{run}.pvd, one .vtu per saved state), and an animation of
# every delamination run drawn from its series (figures/animations/{law}/{run}.gif).
PARAVIEW = MODULES["views/paraview.py"]


def law_and_run(names):
    """The wildcards law and run of run names "{law}/{run}", for expand(..., zip, **law_and_run(names))."""
    return dict(zip(("law", "run"), zip(*(name.split("/") for name in names))))


wildcard_constraints:
    run=r"[^/]+",


rule paraview_delamination:
    """Delamination run {law}/{run}: its snapshots as a ParaView series (a .vtu file per snapshot, a .pvd collection)."""
    input:
        code=SPHGAG + [PARAVIEW],
        states="results/delamination/runs/{law}/{run}_snapshots.npz",
    output:
        series=directory("results/paraview/delamination/{law}/{run}"),
        provenance="results/provenance/paraview_delamination_{law}_{run}.json",
    log:
        "logs/paraview/delamination/{law}/{run}.log",
    conda:
        "../envs/sphgag.yaml"
    resources:
        runtime=5,
        mem_mb=1000,
    script:
        "../scripts/paraview.py"


rule paraview_swelling:
    """Swelling run {law}/{run}: its states as a ParaView series (a .vtu file per state, a .pvd collection)."""
    input:
        code=SPHGAG + [PARAVIEW],
        states="results/swelling/states/{law}/{run}.npz",
    output:
        series=directory("results/paraview/swelling/{law}/{run}"),
        provenance="results/provenance/paraview_swelling_{law}_{run}.json",
    log:
        "logs/paraview/swelling/{law}/{run}.log",
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
        code=[PARAVIEW, MODULES["views/animation.py"]],
        series=rules.paraview_delamination.output.series,
    output:
        report(
            "figures/animations/{law}/{run}.gif",
            caption="../report/animation.rst",
            category="5 Delamination",
            subcategory="Animations",
            labels={"charge law": "{law}", "run": "{run}"},
        ),
    log:
        "logs/animation/{law}/{run}.log",
    conda:
        "../envs/sphgag.yaml"
    script:
        "../scripts/animation.py"


VIEWS = (
    expand(rules.paraview_swelling.output.series, zip, **law_and_run(SWELL_NAMES))
    + expand(rules.paraview_delamination.output.series, zip, **law_and_run(DE_RUN_NAMES))
    + expand(rules.animation.output, zip, **law_and_run(DE_RUN_NAMES))
)
