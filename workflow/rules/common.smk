# Names shared by the rule files, included first. They are the package's modules (the rules' code inputs), the charge
# laws, the configuration slices that saved states depend on, and the runs of each stage by name. Every other file
# defines only the names it alone uses.

import hashlib
import re

from sphgag import plugins
from sphgag.jobs import kinds as JOBS
from sphgag.jobs import text
from sphgag.engine.forces import HOURGLASS_FORMS
from sphgag.physics.damage import DAMAGE_LAWS, FractureEnergyLaw
from sphgag.physics.donnan import CHARGE_LAWS
from sphgag.physics.donnan import PAPER_LAW
from sphgag.physics.materials import law_gag
from sphgag.studies.artery import Bilayer
from sphgag.studies.delamination.settings import MATCHED
from sphgag.studies.delamination.settings import Settings as DelaminationSettings
from sphgag.studies.delamination.settings import CRITERIA
from sphgag.studies.pool_swelling import POOL_MODELS
from sphgag.studies.swelling import Swelling
from sphgag.studies.wall_loading import BilayerCalibration, HomeostasisSettings
from sphgag.views.names import law_figure

# the Donnan laws run side by side (wildcard {law}); a run's params hold its own law only (gag.charge_law), so that
# adding or removing a law adds or removes its jobs and reruns no other simulation
LAWS = config["gag"]["charge_laws"]
GAG = {law: canonical(law_gag(config["gag"], law)) for law in LAWS}


def law_figures(stem, category, label):
    """The outputs of a figure drawn once per charge law (LAWS): ``pdf_<law>`` and ``png_<law>``, under the paper's
    figure's name for the paper's law (figures/fig4.png) and with the law's name for another (fig4_conserved.png,
    sphgag.views.names); each PNG in the report under ``category`` with the caption workflow/report/<stem>.rst,
    labelled with its law."""
    out = {}
    for law in LAWS:
        name, paper = law_figure(stem, law), CHARGE_LAWS[law].paper
        out[f"pdf_{law}"] = f"figures/{name}.pdf"
        result = f"{label}, {law} charge law" + (" (the paper's)" if paper else "")
        out[f"png_{law}"] = report(
            f"figures/{name}.png", caption=f"../report/{stem}.rst", category=category, labels={"result": result}
        )
    return out


def law_pngs(rule):
    """The PNGs of a rule's figure, one per charge law (law_figures), in the order of LAWS."""
    return [rule.output[f"png_{law}"] for law in LAWS]


# Code inputs. Snakemake tracks a rule's script, not the package modules the script imports: a rule's code input is
# the set of modules its script's job imports, computed from the imports (workflow/code_inputs.py: the script's
# imports followed through the package, those inside functions included, less the modules that compute no number).
# An edit of a module reruns exactly the jobs that import it, and a module no script imports is no rule's input (the
# site's aside: its API pages document every module, MODULES).
# A rule's input is not the modules themselves but their digest, one file per script (code_of, the file
# results/code/<script>.sha256 that package_digest in package.smk writes). An edit of any of them reruns the same jobs;
# and the scheduler, which checks every input of every ready job at each pass, checks one file per job, not thirty
# (with the modules listed, a tenth of a core on `all`). A module touched but not changed (a checkout) reruns
# nothing: Snakemake compares a newer input's checksum with the one recorded when the job ran.
WORKFLOW = Path(SRC).parent / "workflow"
sys.path.insert(0, str(WORKFLOW))
from code_inputs import code_inputs  # noqa: E402

# every module of the package, subpackages included, by its path in the package; each path relative to the working
# directory, so that moving or re-cloning the checkout reruns nothing
PACKAGE = Path(SRC, "sphgag")
MODULES = {p.relative_to(PACKAGE).as_posix(): os.path.relpath(p) for p in sorted(PACKAGE.rglob("*.py"))}
# {script: the modules its job imports} of every workflow script (none where it imports no module computing a number)
CODE = {script: [MODULES[m] for m in modules] for script, modules in code_inputs(WORKFLOW / "scripts", PACKAGE).items()}


# each plug-in file of the configuration (key plugins): its variant's registry and name (sphgag.plugins)
PLUGINS = {path: plugins.variant_of(path) for path in config["plugins"]}
# a variant that a setting selects (not a wildcard of its own) is built where the settings are read: the jobs whose
# scripts import that module may compute with it
PLUGIN_READERS = {
    DAMAGE_LAWS.kind: MODULES["studies/delamination/settings.py"],
    HOURGLASS_FORMS.kind: MODULES["engine/model.py"],
}


def one_of(names):
    """A wildcard constraint that matches exactly the names ``names`` (none: no name; an empty constraint would match
    any text)."""
    return "|".join(re.escape(n) for n in names) or "(?!)"


def code_of(script):
    """Rule input: the digest of the modules that the job of workflow/scripts/``script``.py imports (CODE), none
    where it imports no module that computes a number; and the plug-in files whose variant the job may compute with:
    those its wildcards name, and those a setting selects whose reader module (PLUGIN_READERS) it imports."""
    digest = [f"results/code/{script}.sha256"] if CODE[script] else []
    if not PLUGINS:
        return digest
    read = [path for path, (reg, _) in PLUGINS.items() if PLUGIN_READERS.get(reg.kind) in CODE[script]]

    def inputs(wildcards):
        values = set(dict(wildcards.items()).values())
        named = [path for path, (_, name) in PLUGINS.items() if name in values]
        return digest + sorted(set(read + named))

    return inputs


# Configuration slices that saved states depend on: a later rule refuses a state made with others.
# (homeostasis.target_pressure_mmHg is only a reference value: it is not part of the slice; Options.job_settings)
HOMEOSTATIC_SLICE = {
    "bilayer": config["bilayer"],
    "numerics": config["numerics"],
    "homeostasis": HomeostasisSettings.job_settings(config["homeostasis"]),
}
PRESSURISED_SLICE = dict(HOMEOSTATIC_SLICE, bilayer_calibration=config["bilayer_calibration"])
STATE_PRESSURES = text(config["bilayer_calibration"]["state_pressures_mmHg"])
# the pressurised walls' states (rule bilayer_pressure_diameter), from which swelling and delamination start
STATE = "results/states/{model}_{pressure}mmHg.npz"


# Swelling (figure 4)
SW = config["swelling"]
CASES = list(SW["cases"])
SWELL_PRESSURES = text(SW["pressures_mmHg"])
# what the simulations depend on (the section's settings, sphgag.studies.swelling.Swelling): not the lists the runs fan
# out over, nor probe_length_um and tip_probe, which only set where rule pool_stresses measures
SWELL_SETTINGS = Swelling.job_settings(SW)
# the pool models run side by side (wildcard {pool}), each under the charge laws it carries
# (sphgag.studies.pool_swelling.POOL_MODELS); a run's settings hold its own pool model only. Figure 4's pool models
# (swelling.pool_models) run in `all`; the variants' (swelling.variant_pool_models) in target `variants` only.
SWELL_POOLS = SW["pool_models"] + SW["variant_pool_models"]
LAWS_OF_POOL = {pool: [law for law in LAWS if law in POOL_MODELS[pool].laws] for pool in SWELL_POOLS}
SWELL_LAWS_POOLS = dict(
    zip(("law", "pool"), zip(*((law, pool) for pool, laws in LAWS_OF_POOL.items() for law in laws)))
)


def swell_settings(wildcards):
    """The swelling settings of one run: the configuration's, with the run's pool model."""
    return dict(SWELL_SETTINGS, pool_model=wildcards.pool)


def swell_runs(pattern, pools=SW["pool_models"], **wildcards):
    """``pattern`` expanded for every (charge law, pool model) pair of the pool models ``pools`` (figure 4's unless
    given), and every other wildcard of the swelling runs (``model``, ``case``, ``pressure``) unless given."""
    others = dict(dict(model=SW["models"], case=CASES, pressure=SWELL_PRESSURES), **wildcards)
    pairs = zip(SWELL_LAWS_POOLS["law"], SWELL_LAWS_POOLS["pool"])
    return [path for law, pool in pairs if pool in pools for path in expand(pattern, law=law, pool=pool, **others)]


# Delamination (figures 5-7)
DE = config["delamination"]
DE_PRESSURE = text(DE["pressure_mmHg"])
# the state every delamination run starts from: the passive wall at delamination.pressure_mmHg
DE_STATE = STATE.format(model="passive", pressure=DE_PRESSURE)
# the pool sets' roles in the figures (delamination.figures): figure 5's set runs at every critical_stresses_kPa and
# is the set of the resolution study; figures 6 and 7 show theirs; every set runs and appears in the tables
DE_FIGURES = DE["figures"]
FIG5_SET, FIG6_SETS, FIG7_SET = DE_FIGURES["fig5"], DE_FIGURES["fig6"], DE_FIGURES["fig7"]
# one run per (charge law, pool set, sigma_cr, onset criterion): figure 5's set at every sigma_cr, the other sets at
# critical_stress_kPa
DE_RUNS = [
    dict(poolset=case, sigma=text(sigma), criterion=criterion)
    for case in DE["pool_sets"]
    for sigma in (DE["critical_stresses_kPa"] if case == FIG5_SET else [DE["critical_stress_kPa"]])
    for criterion in DE["criteria"]
]
# what every run reads of the section (its sigma_cr and criterion are its own wildcards), so that adding or removing a
# sigma_cr or a criterion reruns no other run; the candidate rule (delamination.candidates) is one of these run-level
# settings, not a wildcard: changing it reruns every delamination run. A study that runs at the section's own sigma_cr
# (and lumen pressure) reads them after its other settings (DE_AT_CONFIG).
DE_SETTINGS = DelaminationSettings.params(DE)


def de_law_settings(wildcards):
    """The settings of a run of figures 5-7 under the charge law {law}: its law's ramp top, where it has its own."""
    return DelaminationSettings.params(DelaminationSettings.of_law(DE, wildcards.law))


def de_fracture_energy_settings(wildcards):
    """The settings of a fracture-energy run under the charge law {law}: de_law_settings, grown by the damage law
    with a fracture energy (its G_c is the run's wildcard {gc})."""
    return dict(de_law_settings(wildcards), damage_law=FractureEnergyLaw.name)


DE_AT_CONFIG = ("critical_stress_kPa", "pressure_mmHg")
DE_DX = text(DE["convergence"]["dx_um"])


def de_run(name):
    """The files of the delamination run ``name`` (a key or a run's name): its growth and summary tables and its
    snapshots."""
    path = f"results/delamination/runs/{name}"
    return dict(growth=f"{path}_growth.csv", summary=f"{path}_summary.csv", snapshots=f"{path}_snapshots.npz")


# the damage law with a fracture energy: figure 5's set at critical_stress_kPa, default criterion, one run per G_c
# (and per charge law); MATCHED is the G_c that the paper's damage law dissipates in its run of that pool under the
# paper's charge law (PAPER_LAW)
DE_FE = DE["fracture_energy"]
# (matched where both paper's laws are studied, against their own run: another law's default run may not grow)
DE_MATCH = DE_FE["match_paper"] and PAPER_LAW in LAWS and DAMAGE_LAWS[DE["damage_law"]].paper
DE_TOUGHNESS = text(DE_FE["fracture_energies_J_m2"]) + ([MATCHED] if DE_MATCH else [])
DE_FE_RUN = dict(poolset=FIG5_SET, sigma=text(DE["critical_stress_kPa"]), criterion=DE["criteria"][0])
# every delamination run by its name (its key filled in: the kind delaminate's, or delaminate_fracture_energy's), which
# names its files (de_run: growth and summary tables, snapshots), ParaView series and animation.
# The runs of the configured damage law (delamination.damage_law: figures 5-7, the claims) and those of the law with a
# fracture energy (target fracture_energy) have tables of their own.
DE_LAW_NAMES = [JOBS.delaminate.key.format(law=law, **r) for law in LAWS for r in DE_RUNS]
DE_FE_NAMES = [
    JOBS.delaminate_fracture_energy.key.format(law=law, gc=gc, **DE_FE_RUN) for law in LAWS for gc in DE_TOUGHNESS
]
DE_RUN_NAMES = DE_LAW_NAMES + DE_FE_NAMES


def run_tables(names, table):
    """The ``table`` (growth or summary) of each delamination run of ``names``."""
    return [de_run(name)[table] for name in names]


# the run whose dissipation is the fracture-energy runs' MATCHED G_c (PAPER_LAW), and every run that keeps
# snapshots: the runs of the tables and that one, where it is not among them (a reduced configuration's sigma_cr)
DE_MATCHED = JOBS.delaminate.key.format(law=PAPER_LAW, **DE_FE_RUN)
DE_SNAPSHOT_NAMES = DE_RUN_NAMES + ([DE_MATCHED] if DE_MATCH and DE_MATCHED not in DE_RUN_NAMES else [])
# the snapshots of any delamination run (rule delaminate or delaminate_fracture_energy) by its name "{law}/{run}"
# (law_and_run; the key of the views' kinds, JOBS.ANY_DELAMINATION)
DE_SNAPSHOTS = de_run(JOBS.ANY_DELAMINATION)["snapshots"]


def law_and_run(names):
    """The wildcards law and run of run names "{law}/{run}", for expand(..., zip, **law_and_run(names))."""
    return dict(zip(("law", "run"), zip(*(name.split("/") for name in names))))


wildcard_constraints:
    law=one_of(LAWS),
    pool=one_of(SWELL_POOLS),
    criterion=one_of(CRITERIA),
    run=r"[^/]+",


# Evidence of the claims and figures that a target other than `all` makes (the sensitivity study's samples, figure 4's
# resolution bands). Where this run makes it (its target or `everything` asked for), it is an input, so that the
# claims and figures wait for it. Otherwise they read it as an earlier run left it, and its digest is a parameter: a new
# result redraws them, but `snakemake all` never pulls in the study that makes it. Without it, the claim's row (or the
# figure) says "not run". (Switching between the two ways reruns the rules that read it alone, to the same bytes.)
def requested(target):
    """Whether this invocation asked for the rule ``target`` (or `everything`)."""
    asked = workflow.dag_settings.targets if workflow.dag_settings is not None else ()
    return bool({target, "everything"} & set(asked))


def study_input(path, target):
    """Rule input: ``path`` where this run makes it (see above)."""
    return lambda wildcards: [path()] if requested(target) else []


def study_evidence(path, target):
    """Rule parameter: how the claims read ``path`` (``made here``, its ``sha256`` where an earlier run made it, or
    ``not run``)."""

    def param(wildcards):
        file = Path(path())
        if requested(target):
            return dict(path=str(file), state="made here")
        if file.exists():
            return dict(path=str(file), state="earlier run", sha256=hashlib.sha256(file.read_bytes()).hexdigest())
        return dict(path=str(file), state="not run")

    return param


def studies_input(studies):
    """Rule input: the files of the studies ``studies`` (name -> (a function giving its paths, its target)) that this
    run makes (their targets asked for)."""
    return lambda wildcards: [path for paths, target in studies.values() if requested(target) for path in paths()]


def studies_evidence(studies):
    """Rule parameter: every file's evidence (study_evidence) of the studies ``studies``, a list per study."""
    return lambda wildcards: {
        name: [study_evidence(lambda p=p: p, target)(wildcards) for p in paths()]
        for name, (paths, target) in studies.items()
    }
