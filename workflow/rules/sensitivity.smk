import math

from sphgag.studies import pool_response
from sphgag.studies.sensitivity import SENSITIVITY_METHODS

SE = config["sensitivity"]
# the nominal scenario of every sample (sphgag.studies.pool_response): figure 5's pool with the pipeline's own slices, so
# that the nominal sample reruns the pipeline's runs of that pool to the bit
SE_SCENARIO = dict(
    bilayer=config["bilayer"],
    numerics=config["numerics"],
    homeostasis=HOMEOSTATIC_SLICE["homeostasis"],
    swelling=SWELL_SETTINGS,
    delamination=DelaminationSettings.params(DE, *DE_AT_CONFIG),
    pool=DE["pool_sets"][FIG5_SET][0],
    pool_set=FIG5_SET,
    criterion=DE["criteria"][0],
    concentration_mEq_l=SE["concentration_mEq_l"],
    probe_length_um=SW["probe_length_um"],
    gag=GAG[LAWS[0]],  # each batch runs its own law (the laws share every number)
)
pool_response.check_inputs(SE_SCENARIO, SE["inputs"])  # config.validate names the keys; this keeps them in step
# the inputs' ranges without their sources (a source is documentation: editing it reruns nothing)
SE_RANGES = {name: dict(low=r["low"], high=r["high"]) for name, r in SE["inputs"].items()}
SE_K = len(SE_RANGES)
# the methods run (sensitivity.methods), in the registry's order
SE_METHODS = {n: m for n, m in SENSITIVITY_METHODS.items() if n in SE["methods"]}
# a method's samples, the settings of sensitivity.methods.<method> its design reads and those its indices read (a
# resampling setting reruns no sample); the nominal design is the configuration's own values (one sample)
SE_SETTINGS = {
    purpose: {n: {k: SE["methods"][n][k] for k in getattr(m, f"{purpose}_keys")} for n, m in SE_METHODS.items()}
    for purpose in ("design", "index")
}
SE_SIZES = dict(nominal=1, **{n: m.size(SE_K, **SE_SETTINGS["design"][n]) for n, m in SE_METHODS.items()})
SE_SETTINGS["design"]["nominal"] = {n: pool_response.nominal(SE_SCENARIO, n) for n in SE_RANGES}
SE_BATCHES = {m: range(math.ceil(n / SE["batch_size"])) for m, n in SE_SIZES.items()}
# the methods whose design reads another's indices (Sobol screens with the Morris indices, written after the Morris
# design): rule screened_design; the nominal design and the others': rule sensitivity_design
SE_SCREENED = [n for n, m in SE_METHODS.items() if m.screening]
SE_UNSCREENED = ("nominal", *(n for n, m in SE_METHODS.items() if not m.screening))
# a method's design, indices and samples
SE_DESIGN = "results/sensitivity/{method}/design.csv"
SE_INDICES = "results/sensitivity/{method}/indices.csv"
SE_SAMPLES = "results/sensitivity/{method}/samples.csv"
SE_MAP = SE["map"]


wildcard_constraints:
    method=one_of(("nominal", *SE_METHODS)),
    batch=r"\d+",
    width=r"[0-9.]+",


rule sensitivity_design:
    """The samples of the {method} design (nominal: the configuration's own values; a method: its design over every
    input, e.g. Morris trajectories)."""
    input:
        code=code_of("sensitivity_design"),
    output:
        SE_DESIGN,
    log:
        JOBS.sensitivity_design.log,
    benchmark:
        JOBS.sensitivity_design.benchmark
    wildcard_constraints:
        method=one_of(SE_UNSCREENED),
    params:
        ranges=SE_RANGES,
        method=lambda wildcards: wildcards.method,
        settings=lambda wildcards: SE_SETTINGS["design"][wildcards.method],
    script:
        "../scripts/sensitivity_design.py"


rule screened_design:
    """The samples of the {method} design over the inputs its screening method ranks highest, read from that method's
    indices (e.g. Saltelli's samples of the Sobol indices over the inputs with the largest Morris mu*)."""
    input:
        code=code_of("sensitivity_design"),
        screening=lambda wildcards: SE_INDICES.format(method=SE_METHODS[wildcards.method].screening),
    output:
        SE_DESIGN,
    log:
        JOBS.screened_design.log,
    benchmark:
        JOBS.screened_design.benchmark
    wildcard_constraints:
        method=one_of(SE_SCREENED),
    params:
        ranges=SE_RANGES,
        method=lambda wildcards: wildcards.method,
        settings=lambda wildcards: SE_SETTINGS["design"][wildcards.method],
    script:
        "../scripts/sensitivity_design.py"


rule sensitivity_batch:
    """Samples of batch {batch} of the {method} design, {law} charge: each reruns figure 5's pool from the homeostatic
    state at its inputs (swelling to the stated concentration, then growth); a failed run is a row with its error."""
    input:
        code=code_of("sensitivity_batch"),
        design=SE_DESIGN,
    output:
        table=JOBS.sensitivity_batch.output("sensitivity", ".csv"),
        provenance=JOBS.sensitivity_batch.provenance,
    log:
        JOBS.sensitivity_batch.log,
    benchmark:
        JOBS.sensitivity_batch.benchmark
    threads: 1
    resources:
        runtime=5 + 12 * SE["batch_size"],  # measured: up to 5.4 min per prescribed-law sample (benchmarks/resources.csv)
        mem_mb=1500,
    params:
        scenario=lambda wildcards: dict(SE_SCENARIO, gag=GAG[wildcards.law]),
        batch_size=SE["batch_size"],
    script:
        "../scripts/sensitivity_batch.py"


rule sensitivity_method:
    """The {method} indices of every output under every charge law, and every sample of the design with its
    outputs."""
    input:
        code=code_of("sensitivity_indices"),
        design=SE_DESIGN,
        batches=lambda wildcards: expand(
            rules.sensitivity_batch.output.table, method=wildcards.method, law=LAWS, batch=SE_BATCHES[wildcards.method]
        ),
    output:
        indices=SE_INDICES,
        samples=SE_SAMPLES,
    log:
        JOBS.sensitivity_method.log,
    benchmark:
        JOBS.sensitivity_method.benchmark
    wildcard_constraints:
        method=one_of(SE_METHODS),
    params:
        ranges=SE_RANGES,
        settings=lambda wildcards: SE_SETTINGS["index"][wildcards.method],
    script:
        "../scripts/sensitivity_indices.py"


rule sensitivity_tables:
    """The study in three tidy tables: the indices, every sample with its inputs and outputs (the nominal one first),
    and the samples without an output (a failed run, or no equilibrium at the stated concentration), by their inputs."""
    input:
        code=code_of("sensitivity_tables"),
        indices=expand(rules.sensitivity_method.output.indices, method=SE_METHODS),
        samples=expand(rules.sensitivity_method.output.samples, method=SE_METHODS),
        nominal=expand(rules.sensitivity_batch.output.table, method="nominal", law=LAWS, batch=0),
    output:
        indices=report(
            "results/sensitivity/indices.csv",
            caption="../report/sensitivity_indices.rst",
            category="6 Sensitivity",
            labels={"result": "Table: Morris and Sobol indices"},
        ),
        samples="results/sensitivity/samples.csv",
        failures="results/sensitivity/failures.csv",
    log:
        JOBS.sensitivity_tables.log,
    benchmark:
        JOBS.sensitivity_tables.benchmark
    script:
        "../scripts/sensitivity_tables.py"


rule sensitivity_figure:
    """Morris mu* against sigma, and Sobol S1 and ST with their intervals, for every output and charge law."""
    input:
        code=code_of("sensitivity_figure"),
        indices=rules.sensitivity_tables.output.indices,
    output:
        pdf="figures/sensitivity.pdf",
        png=report(
            "figures/sensitivity.png",
            caption="../report/sensitivity.rst",
            category="6 Sensitivity",
            labels={"result": "Figure: which inputs decide the results"},
        ),
    log:
        "logs/sensitivity_figure.log",
    benchmark:
        "results/benchmarks/sensitivity_figure.tsv"
    script:
        "../scripts/sensitivity_figure.py"


rule delamination_map_point:
    """Figure 5's pool at {width} deg and sigma_cr = {sigma} kPa, {law} charge, grown over the ramp: what it does at
    each concentration level."""
    input:
        code=code_of("delamination_map_point"),
        state=DE_STATE,
    output:
        table=JOBS.delamination_map_point.output("sensitivity/map", ".csv"),
        provenance=JOBS.delamination_map_point.provenance,
    log:
        JOBS.delamination_map_point.log,
    benchmark:
        JOBS.delamination_map_point.benchmark
    threads: 1
    resources:
        runtime=15,
    params:
        state_slice=dict(PRESSURISED_SLICE, model="passive"),
        pool=lambda wildcards: dict(DE["pool_sets"][FIG5_SET][0], angular_extent_deg=float(wildcards.width)),
        delamination=DE_SETTINGS,
        criterion=DE["criteria"][0],
        gag=lambda wildcards: GAG[wildcards.law],
    script:
        "../scripts/delamination_map_point.py"


rule delamination_map:
    """The delamination map (every charge law, angular extent, sigma_cr and concentration level) in one tidy table."""
    input:
        expand(
            rules.delamination_map_point.output.table,
            law=LAWS,
            width=text(SE_MAP["angular_extents_deg"]),
            sigma=text(SE_MAP["critical_stresses_kPa"]),
        ),
    output:
        report(
            "results/sensitivity/delamination_map.csv",
            caption="../report/delamination_map_table.rst",
            category="6 Sensitivity",
            labels={"result": "Table: the delamination map"},
        ),
    log:
        "logs/delamination_map.log",
    benchmark:
        "results/benchmarks/delamination_map.tsv"
    script:
        "../scripts/concat_tables.py"


rule delamination_map_figure:
    """The map: angular extent x concentration, one panel per sigma_cr and charge law, with the limit concentrations
    of figure 4's swelling runs."""
    input:
        code=code_of("delamination_map_figure"),
        map=rules.delamination_map.output[0],
        swelling=rules.tip_stress.output[0],
    output:
        pdf="figures/delamination_map.pdf",
        png=report(
            "figures/delamination_map.png",
            caption="../report/delamination_map.rst",
            category="6 Sensitivity",
            labels={"result": "Figure: the delamination map"},
        ),
    log:
        "logs/delamination_map_figure.log",
    benchmark:
        "results/benchmarks/delamination_map_figure.tsv"
    params:
        pressure=DE["pressure_mmHg"],
        cases={name: c["angular_extent_deg"] for name, c in SW["cases"].items()},
    script:
        "../scripts/delamination_map_figure.py"
