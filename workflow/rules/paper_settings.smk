# Figure 4's magnitudes against the authors' settings (target paper_settings): figure 4's protocol under the
# authors' configuration (paper_settings.script_config) and ours, and each with one setting switched to the other's
# value, at equilibrium; the ablation table, the figure of each setting's step, and claim P5's evidence.
from sphgag.studies import paper_settings as PAPER_SETTINGS

PS = config["paper_settings"]
# the authors' configuration, validated like this one before any job (a ConfigError names what is wrong)
PS_SCRIPT = canonical(validate(load_yaml(PS["script_config"]), Path(workflow.basedir, "config", "schema.yaml")))
PS_RUNS = PAPER_SETTINGS.runs(PS)


wildcard_constraints:
    base=one_of(PAPER_SETTINGS.BASES),
    setting=one_of([PAPER_SETTINGS.NONE, *PS["settings"]]),


rule paper_settings_run:
    """Figure 4's protocol (103 mmHg, the paper's charge law) in the {model} wall under the {base} configuration with
    the setting {setting} switched to the other's value (none: as it is), its pools measured."""
    input:
        code=code_of("paper_settings_run"),
    output:
        table=JOBS.paper_settings_run.output("paper_settings/runs", ".csv"),
        provenance=JOBS.paper_settings_run.provenance,
    log:
        JOBS.paper_settings_run.log,
    benchmark:
        JOBS.paper_settings_run.benchmark
    threads: 1
    resources:
        runtime=60,
        mem_mb=3000,
    params:
        run=lambda wildcards: canonical(PAPER_SETTINGS.run_params(config, PS_SCRIPT, wildcards.base, wildcards.setting)),
    script:
        "../scripts/paper_settings_run.py"


rule paper_settings_table:
    """Every run's figure 4 quantities at the section's concentrations, with their residuals (ablation.csv), and
    each setting's step from the authors' value to ours (steps.csv)."""
    input:
        code=code_of("paper_settings_table"),
        runs=[
            rules.paper_settings_run.output.table.format(model=model, **run)
            for run in PS_RUNS
            for model in PS["models"]
        ],
    output:
        table=report(
            "results/paper_settings/ablation.csv",
            caption="../report/paper_settings_table.rst",
            category="6 Procedure",
            labels={"result": "Figure 4 under the authors' settings, one at a time (table)"},
        ),
        steps="results/paper_settings/steps.csv",
    log:
        "logs/paper_settings/table.log",
    benchmark:
        "results/benchmarks/paper_settings_table.tsv"
    params:
        concentrations=PS["concentrations_mEq_l"],
        tolerance=config["numerics"]["tolerance"],
    script:
        "../scripts/paper_settings_table.py"


rule paper_settings_figure:
    """Each setting's step in the tip radial stress from the authors' value to ours, per pool and wall, both ways."""
    input:
        code=code_of("paper_settings_figure"),
        steps=rules.paper_settings_table.output.steps,
    output:
        pdf="figures/paper_settings.pdf",
        png=report(
            "figures/paper_settings.png",
            caption="../report/paper_settings.rst",
            category="6 Procedure",
            labels={"figure": "Figure 4 under the authors' settings, one at a time"},
        ),
    log:
        "logs/paper_settings/figure.log",
    benchmark:
        "results/benchmarks/paper_settings_figure.tsv"
    script:
        "../scripts/paper_settings_figure.py"
