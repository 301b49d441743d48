# The authors' explicit, fixed-step procedure beside our equilibria (target paper_procedure): figure 4's pools
# swollen by leapfrog pseudo-dynamics at the script's step counts and at multiples of them, against the equilibrium
# path of the same walls, at the same spacing and temperature.
from sphgag.studies.paper_procedure import Timing

PP = config["paper_procedure"]
PP_FACTORS = [str(f) for f in PP["step_factors"]]
# the equilibrium runs of this target: the figure 4 protocol at its spacing, its pools and its temperature
# (wall: what the pressurised wall depends on, the slice its saved state records)
PP_SIMULATION = dict(
    wall=dict(
        dx=PP["dx_um"],
        bilayer=config["bilayer"],
        numerics=config["numerics"],
        homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
        calibration=BilayerCalibration.activation(config["bilayer_calibration"]),
        pressure_mmHg=PP["pressure_mmHg"],
    ),
    gag=canonical(dict(law_gag(config["gag"], PAPER_LAW), temperature_K=PP["temperature_K"])),  # configured or not
    cases={c: SW["cases"][c] for c in PP["cases"]},
)
PP_TIMING = Timing.keys_in(PP)
# the summary's concentration: the top of figure 4's ramp, or where the explicit runs stop below it
PP_TOP = min(SW["max_concentration_mEq_l"], PP["swelling"]["stop_concentration_mEq_l"])
# the damage runs: each pool set of paper_procedure.pool_sets at each of its sigma_cr and every step factor
PP_DAMAGE_RUNS = [
    dict(poolset=name, sigma=text(sigma), factor=factor)
    for name, sigmas in PP["pool_sets"].items()
    for sigma in sigmas
    for factor in PP_FACTORS
]


wildcard_constraints:
    factor=one_of(PP_FACTORS),


rule procedure_start:
    """The {model} wall at the procedure's spacing and pressure (equilibrium): the state its runs start from."""
    input:
        code=code_of("procedure_start"),
    output:
        start="results/paper_procedure/{model}/start.npz",
        provenance=JOBS.procedure_start.provenance,
    log:
        JOBS.procedure_start.log,
    benchmark:
        JOBS.procedure_start.benchmark
    threads: 1
    params:
        wall=PP_SIMULATION["wall"],
    script:
        "../scripts/procedure_start.py"


rule procedure_equilibrium:
    """Figure 4's equilibrium path of each of the procedure's pools in the {model} wall, at its spacing and
    temperature, measured."""
    input:
        code=code_of("procedure_equilibrium"),
        start=rules.procedure_start.output.start,
    output:
        table="results/paper_procedure/{model}/equilibrium.csv",
        provenance=JOBS.procedure_equilibrium.provenance,
    log:
        JOBS.procedure_equilibrium.log,
    benchmark:
        JOBS.procedure_equilibrium.benchmark
    threads: 1
    params:
        **PP_SIMULATION,
        settings=dict(SWELL_SETTINGS, pool_model="particles"),
        probe_length=SW["probe_length_um"],
        tip_probe=SW["tip_probe"],
    script:
        "../scripts/procedure_equilibrium.py"


rule procedure_explicit:
    """Figure 4's pool {case} in the {model} wall by the explicit procedure, every stage's steps times {factor}:
    the recorded states and their pool stresses, residuals and kinetic energies."""
    input:
        code=code_of("procedure_explicit"),
        start=rules.procedure_start.output.start,
    output:
        states=JOBS.procedure_explicit.output("paper_procedure/states", ".npz"),
        table=JOBS.procedure_explicit.output("paper_procedure/runs", ".csv"),
        provenance=JOBS.procedure_explicit.provenance,
    log:
        JOBS.procedure_explicit.log,
    benchmark:
        JOBS.procedure_explicit.benchmark
    threads: 1
    resources:
        runtime=15,
        mem_mb=1000,
    params:
        **PP_SIMULATION,
        procedure=dict(timing=PP_TIMING, swelling=PP["swelling"]),
        # the swelling stage's lumen and hourglass modulus as the equilibria's (swelling section), its tips likewise
        lumen_control=SW["lumen_control"],
        hourglass_factor=SW["hourglass_factor"],
        probe_length=SW["probe_length_um"],
        tip_probe=SW["tip_probe"],
    script:
        "../scripts/procedure_explicit.py"


rule procedure_delaminate:
    """The pools of set {poolset} in the passive wall at sigma_cr = {sigma} kPa by the explicit damage stage, every
    count of steps times {factor}: one row per load update, and the saved states."""
    input:
        code=code_of("procedure_delaminate"),
        start=expand(rules.procedure_start.output.start, model="passive"),
    output:
        states=JOBS.procedure_delaminate.output("paper_procedure/states", ".npz"),
        table=JOBS.procedure_delaminate.output("paper_procedure/damage", ".csv"),
        provenance=JOBS.procedure_delaminate.provenance,
    log:
        JOBS.procedure_delaminate.log,
    benchmark:
        JOBS.procedure_delaminate.benchmark
    threads: 1
    resources:
        runtime=10,
        mem_mb=1000,
    params:
        wall=PP_SIMULATION["wall"],
        gag=PP_SIMULATION["gag"],
        pools=lambda wildcards: config["delamination"]["pool_sets"][wildcards.poolset],
        delamination=DE_SETTINGS,
        criterion=config["delamination"]["criteria"][0],
        procedure=dict(timing=PP_TIMING, damage=PP["damage"]),
    script:
        "../scripts/procedure_delaminate.py"


rule procedure_summary:
    """Every explicit run's states in one table, and figure 4's quantities at the top of the paper's range by path
    (equilibrium, explicit at each step factor) with their residuals."""
    input:
        code=code_of("procedure_summary"),
        equilibrium=expand(rules.procedure_equilibrium.output.table, model=PP["models"]),
        runs=expand(rules.procedure_explicit.output.table, model=PP["models"], case=PP["cases"], factor=PP_FACTORS),
        damage=[rules.procedure_delaminate.output.table.format(**run) for run in PP_DAMAGE_RUNS],
    output:
        runs="results/paper_procedure/explicit.csv",
        damage="results/paper_procedure/damage.csv",
        table=report(
            "results/paper_procedure/summary.csv",
            caption="../report/paper_procedure_table.rst",
            category="6 Procedure",
            labels={"result": "The explicit procedure against the equilibria (table)"},
        ),
    log:
        "logs/paper_procedure/summary.log",
    benchmark:
        "results/benchmarks/procedure_summary.tsv"
    params:
        concentration=PP_TOP,
    script:
        "../scripts/procedure_summary.py"


rule procedure_figure:
    """The explicit procedure against the equilibria: figure 4's tip and top stresses and the residual against
    concentration, per pool, wall and step factor."""
    input:
        code=code_of("procedure_figure"),
        equilibrium=rules.procedure_summary.input.equilibrium,
        runs=rules.procedure_summary.output.runs,
        damage=rules.procedure_summary.output.damage,
        summary=rules.procedure_summary.output.table,
    output:
        pdf="figures/paper_procedure.pdf",
        png=report(
            "figures/paper_procedure.png",
            caption="../report/paper_procedure.rst",
            category="6 Procedure",
            labels={"figure": "The paper's explicit procedure against the equilibria"},
        ),
    log:
        "logs/paper_procedure/figure.log",
    benchmark:
        "results/benchmarks/procedure_figure.tsv"
    params:
        tolerance=config["numerics"]["tolerance"],
        concentration=PP_TOP,
    script:
        "../scripts/procedure_figure.py"
