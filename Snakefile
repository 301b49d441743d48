# sphgag: reproduce Ahmadzadeh, Rausch & Humphrey (2018) as a reproducible pipeline.
#   snakemake --cores 2 all                          full study (config/config.yaml)
#   snakemake --cores 2 all --configfile config/ci.yaml   reduced study, same DAG
import os
import sys
from pathlib import Path

# the package lives in src/: importable by this Snakefile and by every script job,
# whether or not it was pip-installed (cluster nodes, conda environments)
SRC = str(Path(workflow.basedir, "src").resolve())
sys.path.insert(0, SRC)
os.environ.update(PYTHONPATH=os.pathsep.join(filter(None, [SRC, os.environ.get("PYTHONPATH")])))

from snakemake.utils import update_config  # noqa: E402

from sphgag import plugins  # noqa: E402
from sphgag.config import canonical, load_yaml, typed_overrides, validate  # noqa: E402

# The full study is the default only when no --configfile is given: a user's config stands alone (Snakemake would
# otherwise merge it over config/config.yaml, so that pools, pressures and whole sections leak in from the full study).
if not workflow.overwrite_configfiles:

    configfile: "config/config.yaml"


for _path in workflow.configfiles:  # Snakemake's own YAML reader lets a duplicated key win silently
    load_yaml(_path)
# --config key='{nested: 0.001}' arrives with every nested value as text: read those values as YAML does
update_config(config, typed_overrides(workflow.config_settings.config))
# the configuration's own variants (docs/contributing.md): registered before the schema names the registries' variants
plugins.export(config.get("plugins", []))
validate(config, Path(workflow.basedir, "config", "schema.yaml"))
# key order must not matter when Snakemake compares a rule's params with its last run
config = canonical(config)


# snakemake --report report.zip: every figure and the main tables carry report(caption, category, labels) in
# workflow/rules/*.smk, with their captions in workflow/report/. The report's menu sorts categories by name, so they
# are numbered: the claims table first (0 Claims), then the paper's order (1 Calibration ... 5 Delamination).
# Captions are read only by --report: they are inputs of nothing, and editing one reruns nothing.
report: "workflow/report/workflow.rst"


include: "workflow/rules/common.smk"
include: "workflow/rules/package.smk"
include: "workflow/rules/calibration.smk"
include: "workflow/rules/homeostasis.smk"
include: "workflow/rules/swelling.smk"
include: "workflow/rules/verification.smk"
include: "workflow/rules/delamination.smk"
include: "workflow/rules/figures.smk"
include: "workflow/rules/sensitivity.smk"
include: "workflow/rules/views.smk"
include: "workflow/rules/variants.smk"
include: "workflow/rules/procedure.smk"
include: "workflow/rules/paper_settings.smk"
include: "workflow/rules/docs.smk"


# Targets by purpose. `all` (the default) regenerates the paper: figures 1 and 3-7 and the claims table, for every
# charge law, at the configured resolution, with the pool verification and every table the report shows of them.
# The heavier studies are targets of their own; `everything` runs them all. README: jobs, time and core-hours of each.
rule all:
    default_target: True
    input:
        rules.calibrate_mean.output,
        rules.homeostasis.output,
        rules.homeostasis_target.output,
        expand(rules.bilayer_pressure_diameter.output, model=("passive", "active")),
        rules.bilayer_table.output,
        rules.transmural.output,
        rules.fig1.output,
        rules.fig3a_mean.output,
        rules.fig3b.output,
        rules.fig3.output,
        rules.tip_stress.output,
        rules.fig4.output,
        rules.verification_pool_figure.output,
        rules.delamination_growth.output,
        rules.delamination_summary.output,
        rules.fig5.output,
        rules.fig6.output,
        rules.fig7.output,
        rules.claims.output,


rule resolution:
    """The resolution studies: the pools' swelling (figure 4) and the delamination at every spacing, with the grid
    convergence index of the delamination's event concentrations."""
    input:
        rules.swelling_convergence_figure.output,
        rules.swelling_gci.output,
        rules.delamination_convergence.output,
        rules.delamination_gci.output,


rule verification:
    """The closed-form verifications at every spacing: the swelling pool (Inglis, Lame; at large strain, the exact
    circular pool; the pressurised annulus below and above its limit of existence), the walls' transmural stress
    against the exact thick wall, and the pressurised crack of the damage law with a fracture energy (Sneddon,
    Griffith)."""
    input:
        rules.verification_pool_figure.output,
        rules.verification_circular_pool_figure.output,
        rules.verification_annulus_figure.output,
        rules.verification_profiles_figure.output,
        rules.verification_crack_figure.output,


rule fracture_energy:
    """Figure 5's pool grown by the damage law with a fracture energy (measured toughness), beside Griffith."""
    input:
        rules.fracture_energy_growth.output,
        rules.fracture_energy_summary.output,


rule sensitivity:
    """The sensitivity study: Morris screening, Sobol indices and the delamination map, with their figures."""
    input:
        rules.sensitivity_tables.output,
        rules.sensitivity_figure.output,
        rules.delamination_map.output,
        rules.delamination_map_figure.output,


rule variants:
    """The variants beside the default: eq. (2.14) as printed and its energy form, on figure 4's first pool and
    figure 5's pool, with the figure that compares them; and figure 4 and its claims with every pool model
    (swelling.variant_pool_models beside the paper's)."""
    input:
        rules.variants_figure.output,
        rules.variants_fig4.output,
        rules.variants_claims.output,


rule paper_procedure:
    """The authors' explicit, fixed-step procedure beside our equilibria: figure 4's pools swollen by leapfrog
    pseudo-dynamics at the script's step counts and multiples of them, with their residuals."""
    input:
        rules.procedure_summary.output,
        rules.procedure_figure.output,


rule paper_settings:
    """Figure 4's magnitudes against the authors' settings: figure 4's protocol at equilibrium under the authors'
    configuration (config/script.yaml) and ours, and each with one setting switched to the other's value."""
    input:
        rules.paper_settings_table.output,
        rules.paper_settings_figure.output,


rule views:
    """A ParaView series of every swelling and delamination run, and an animation of every delamination run."""
    input:
        RUN_VIEWS,


rule docs:
    """The documentation site in site/ (open site/index.html): the physics, the API, contributing, and the results
    pages generated from this run's tables (with the studies' tables where they have run)."""
    input:
        rules.site.output,


rule everything:
    """Every output the configuration defines."""
    input:
        rules.all.input,
        rules.resolution.input,
        rules.verification.input,
        rules.fracture_energy.input,
        rules.sensitivity.input,
        rules.variants.input,
        rules.paper_procedure.input,
        rules.paper_settings.input,
        rules.views.input,
        rules.docs.input,


# One software environment for every job (--sdm conda): set here on each rule that runs a script or a command and
# names none, rather than by `conda:` in each rule. (Snakemake's top-level `conda:` directive injects an environment
# into Snakemake's own process, not into the jobs: a script job runs with the Python Snakemake runs with.)
ENV = str(Path(workflow.basedir, "workflow", "envs", "sphgag.yaml"))
for _rule in workflow.rules:
    if _rule.conda_env is None and (_rule.script or _rule.shellcmd):
        _rule.conda_env = ENV
